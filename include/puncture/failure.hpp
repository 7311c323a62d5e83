#pragma once
// When the membrane punctures: the failure criteria (failure_criteria.hpp) evaluated on a solved
// state.  A criterion is a struct and an alternative of FailureCriterion, with its measure here
// and in src/failure/.
#include <string>
#include <vector>

#include "puncture/equilibrium.hpp"
#include "puncture/failure_criteria.hpp"
#include "puncture/material.hpp"
#include "puncture/problem.hpp"

namespace puncture {

// The problem's criteria: Problem::criteria, or the critical I1 of Problem::critical_i1 alone
// when that list is empty (the paper's).
std::vector<FailureCriterion> failure_criteria(const Problem& problem);
// The first of them (the only one unless Problem::criteria lists several).
FailureCriterion failure_criterion(const Problem& problem);

// E.g. "critical I1 = 95.2", "maximum principal stretch = 6", "critical strain-energy density
// = 12.5 MPa", "critical true stress = 30 MPa", "tearing energy = 2 N/mm".
std::string describe(const FailureCriterion& criterion);
// The name the CLI (--criterion NAME:VALUE) and Python use: "i1", "max-stretch",
// "energy-density", "true-stress", "energy-release".
std::string criterion_name(const FailureCriterion& criterion);
// The criterion called `name` with critical value `value` (its unit: criterion_unit).  Throws
// InvalidInput ("criterion") for an unknown name; the value's range is validation_errors()'s.
FailureCriterion criterion_from_name(const std::string& name, double value);
// The names, in that order.
std::vector<std::string> criterion_names();
// What the measure is ("I1", "largest principal stretch", ...) and its unit ("", "MPa" or
// "N/mm").
std::string measure_name(const FailureCriterion& criterion);
std::string criterion_unit(const FailureCriterion& criterion);
double critical_value(const FailureCriterion& criterion);

// Whether the criterion is a local measure of the stretches (all but the energy release, a
// balance over the whole membrane, which has no measure_at).
bool has_local_measure(const FailureCriterion& criterion);

// The criterion's measure at principal stretches lambda1, lambda2 (lambda3 = 1 / (lambda1
// lambda2)) of `material`: I1, max(lambda1, lambda2, lambda3), W [MPa] or max(lambda_i s_i)
// [MPa] (i = 1, 2; the thickness direction is free of stress).  Throws InvalidInput
// ("criterion") for the energy release, which has no local measure.
double measure_at(const FailureCriterion& criterion, const Material& material, double l1,
                  double l2);

// The part in words, e.g. "Part II (on the indenter's side)".
std::string to_string(MembranePart part);

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

// The critical I1 reads the state's largest I1 (found between the integration steps); every
// other local criterion reads the fields (state.fields, sampled at SolverOptions::field_points
// per part: the largest sampled value; NaN without fields).  Throws InvalidInput ("criterion")
// for the energy release, which needs the problem (the overload below).
FailureAssessment assess(const FailureCriterion& criterion, const Equilibrium& state,
                         const Material& material);
// Any criterion on a state of `problem`.  The energy release (energy_release.hpp): value the
// energy released per unit reference area of the cut [N/mm], critical the tearing energy, at the
// cut ring (Part III's edge, the corner); throws InvalidInput where the criterion does not apply
// (validation_errors) or the state has no fields.
FailureAssessment assess(const FailureCriterion& criterion, const Equilibrium& state,
                         const Problem& problem);
// The largest value of the criterion's measure over the rows of `fields`, and its row (the
// outermost among equal values); value NaN for empty fields.
FailureAssessment assess_fields(const FailureCriterion& criterion, const MembraneFields& fields,
                                const Material& material);

}  // namespace puncture
