#pragma once
// The critical I1 on a normalised solution, as the puncture search uses it: the excess of the
// largest I1 over the critical value (>= 0: failed), increasing along the loading path.  The
// other criteria read the state's fields (indentation/criterion_on_state.hpp).
#include <optional>
#include <variant>

#include "indentation/scaled_solution.hpp"
#include "puncture/failure.hpp"

namespace puncture::detail {

// Measure minus critical value on a solved state, for the critical I1: the largest I1 over
// every part (Part III's 2 L^2 + L^-4 included) minus the critical I1.  Any other criterion:
// criterion_excess (criterion_on_state.hpp).
inline double excess(const FailureCriterion& criterion, const ScaledSolution& sol) {
  return max_first_invariant_of(sol) - critical_value(criterion);
}

// The excess of the flat, unloaded membrane (the searches start there): the measure at
// lambda1 = lambda2 = 1 (I1 = 3, stretch 1, W = 0, stress 0, no energy released) minus the
// critical value (a pre-stretched membrane that releases energy unloaded is refused if it fails).
inline double unloaded_excess(const FailureCriterion& criterion) {
  static constexpr double kUnloaded[] = {3.0, 1.0, 0.0, 0.0, 0.0};
  return kUnloaded[criterion.index()] - critical_value(criterion);
}

// The critical I1 when the criterion is one (contact models may solve that puncture directly).
inline std::optional<double> critical_first_invariant(const FailureCriterion& criterion) {
  if (const auto* c = std::get_if<CriticalFirstInvariant>(&criterion)) return c->critical_i1;
  return std::nullopt;
}

}  // namespace puncture::detail
