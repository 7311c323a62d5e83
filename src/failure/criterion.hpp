#pragma once
// A failure criterion on a normalised solution, as the puncture search uses it: the excess of its
// measure over the critical value (>= 0: failed), increasing along the loading path.
#include <optional>
#include <string>
#include <variant>

#include "indentation/scaled_solution.hpp"
#include "puncture/failure.hpp"

namespace puncture::detail {

// Measure minus critical value on a solved state; for the critical I1 the largest I1 over every
// part (Part III's 2 L^2 + L^-4 included) minus the critical I1.
inline double excess(const FailureCriterion& criterion, const ScaledSolution& sol) {
  return std::visit(
      [&](const CriticalFirstInvariant& c) { return max_first_invariant_of(sol) - c.critical_i1; },
      criterion);
}

// The excess of the flat, unloaded membrane (the searches start there).
inline double unloaded_excess(const FailureCriterion& criterion) {
  return std::visit([](const CriticalFirstInvariant& c) { return 3.0 - c.critical_i1; }, criterion);
}

// The measure's value on a solved state, and its critical value.
inline double measure(const FailureCriterion& criterion, const ScaledSolution& sol) {
  return std::visit([&](const CriticalFirstInvariant&) { return max_first_invariant_of(sol); },
                    criterion);
}
inline double critical_value(const FailureCriterion& criterion) {
  return std::visit([](const CriticalFirstInvariant& c) { return c.critical_i1; }, criterion);
}

// The criterion is exceeded: loaded to this state the membrane would have punctured.  The margin
// (1e-8 of the critical value) keeps the puncture state itself, located to ~1e-10, intact.
inline bool exceeded(const FailureCriterion& criterion, const ScaledSolution& sol) {
  return sol.ok() && excess(criterion, sol) > 1e-8 * critical_value(criterion);
}

// What the measure is, in words ("I1").
inline std::string measure_name(const FailureCriterion& criterion) {
  return std::visit([](const CriticalFirstInvariant&) { return std::string("I1"); }, criterion);
}

// The critical I1 when the criterion is one (contact models may solve that puncture directly).
inline std::optional<double> critical_first_invariant(const FailureCriterion& criterion) {
  if (const auto* c = std::get_if<CriticalFirstInvariant>(&criterion)) return c->critical_i1;
  return std::nullopt;
}

}  // namespace puncture::detail
