#pragma once
// The failure criteria on a normalised solution, as the puncture search and the states use them.
// The critical I1 reads the largest I1 the shooting found between its steps; every other
// criterion reads the sampled fields (state_fields.hpp; the energy release integrates the energy
// over them), so that a state's assessment (puncture::assess on its Equilibrium) and the
// search's agree to the last bit.
#include "failure/criterion.hpp"
#include "failure/energy_release_balance.hpp"
#include "indentation/contact/contact_model.hpp"
#include "indentation/state_fields.hpp"
#include "puncture/failure.hpp"

namespace puncture::detail {

// The criterion's measure where it is largest on `sol` (needs the samples, `record`, for any
// criterion but the critical I1), with the place: normalised radii for the critical I1 as the
// contact model places it, mm otherwise (the fields').
template <class Contact>
FailureAssessment assess_scaled(const Problem& p, const Contact& contact,
                                const FailureCriterion& criterion, const ScaledSolution& sol) {
  if (std::holds_alternative<CriticalFirstInvariant>(criterion)) {
    const LargestFirstInvariant largest = contact.largest_first_invariant(sol);
    const double big_a = solver_scales(p).length_mm;
    return {max_first_invariant_of(sol),
            critical_value(criterion),
            largest.part,
            largest.reference_radius * big_a,
            largest.radius * big_a};
  }
  MembraneFields fields;
  append_state_fields(p, contact, sol, fields);
  if (const auto* energy = std::get_if<CriticalEnergyRelease>(&criterion))
    return energy_release_assessment(
        p,
        energy_release_of(p, fields, sol.part_three_stretch, energy->tearing_energy_n_per_mm),
        *energy);
  return assess_fields(criterion, fields, p.material);
}

// Measure minus critical value (>= 0: failed).
template <class Contact>
double criterion_excess(const Problem& p, const Contact& contact, const FailureCriterion& criterion,
                        const ScaledSolution& sol) {
  if (std::holds_alternative<CriticalFirstInvariant>(criterion)) return excess(criterion, sol);
  return assess_scaled(p, contact, criterion, sol).value - critical_value(criterion);
}

// Whether any of the problem's criteria is exceeded (exceeded()'s margin).  A criterion other
// than the critical I1 is read only on a state with Part I sampled (the curve's points are not:
// the curve marks every point past the puncture depth instead).
template <class Contact>
bool any_exceeded(const Problem& p, const Contact& contact, const ScaledSolution& sol) {
  if (!sol.ok()) return false;
  for (const auto& c : failure_criteria(p)) {
    if (!std::holds_alternative<CriticalFirstInvariant>(c) && sol.part_one.empty()) continue;
    if (criterion_excess(p, contact, c, sol) > 1e-8 * critical_value(c)) return true;
  }
  return false;
}

}  // namespace puncture::detail
