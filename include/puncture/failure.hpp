#pragma once
// When the membrane punctures: a failure criterion, evaluated on a solved state.  A criterion is
// a struct here and an alternative of FailureCriterion, with its measure in src/failure/.
#include <string>
#include <variant>

#include "puncture/equilibrium.hpp"
#include "puncture/problem.hpp"

namespace puncture {

// The paper's criterion (§2.3): the membrane punctures where the first invariant I1 of the
// right Cauchy-Green tensor first reaches a critical value, measured in the inflation test.
struct CriticalFirstInvariant {
  double critical_i1 = 95.2;
};

using FailureCriterion = std::variant<CriticalFirstInvariant>;

// The problem's criterion (today the critical I1 of Problem::critical_i1).
FailureCriterion failure_criterion(const Problem& problem);
// E.g. "critical I1 = 95.2".
std::string describe(const FailureCriterion& criterion);

// A criterion evaluated along every part of a state: its measure where it is largest, the value
// at which the membrane fails, and where that is.
struct FailureAssessment {
  double value = 0.0;     // the criterion's measure at its largest (I1 for the critical I1)
  double critical = 0.0;  // ... and its value at failure
  MembranePart part = MembranePart::Free;            // the part where the measure is largest
  double reference_radius_mm = 0.0;                  // there: reference radius R
  double radius_mm = 0.0;                            // ... and current radius r
  double ratio() const { return value / critical; }  // >= 1: the membrane has failed
  bool failed() const { return value >= critical; }
};

FailureAssessment assess(const FailureCriterion& criterion, const Equilibrium& state);

}  // namespace puncture
