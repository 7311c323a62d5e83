#include "puncture/failure.hpp"

#include <fmt/format.h>

namespace puncture {

FailureCriterion failure_criterion(const Problem& problem) {
  return CriticalFirstInvariant{problem.critical_i1};
}

std::string describe(const FailureCriterion& criterion) {
  return std::visit(
      [](const CriticalFirstInvariant& c) {
        return fmt::format("critical I1 = {:g}", c.critical_i1);
      },
      criterion);
}

FailureAssessment assess(const FailureCriterion& criterion, const Equilibrium& state) {
  return std::visit(
      [&](const CriticalFirstInvariant& c) {
        return FailureAssessment{state.max_first_invariant,
                                 c.critical_i1,
                                 state.max_first_invariant_part,
                                 state.max_first_invariant_reference_radius_mm,
                                 state.max_first_invariant_radius_mm};
      },
      criterion);
}

}  // namespace puncture
