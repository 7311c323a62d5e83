#pragma once
// The physical fields of a normalised solution from its samples (the parts in contact from the
// contact model, then Part I): what Equilibrium::fields holds, and what the criteria other than
// the critical I1 are read on.
#include "indentation/membrane_fields.hpp"
#include "indentation/scaled_solution.hpp"
#include "indentation/solver_scales.hpp"
#include "puncture/membrane_fields.hpp"
#include "puncture/problem.hpp"

namespace puncture::detail {

template <class Contact>
void append_state_fields(const Problem& p, const Contact& contact, const ScaledSolution& sol,
                         MembraneFields& fields) {
  const SolverScales units = solver_scales(p);
  const FieldScales scales{units.length_mm, p.material.shear_modulus_mpa, p.geometry.thickness_mm};
  // Before contact under a gas pressure the whole membrane is the inflated dome, free.
  const bool dome = sol.configuration == Configuration::Unloaded && p.preload.pressure_mpa > 0.0;
  if (!dome) contact.append_contact_fields(sol, scales, fields);
  append_free_fields(contact.law(),
                     sol,
                     dome ? 0.0 : contact.free_part_inner_height(sol),
                     scales,
                     fields,
                     dome_pressure(p));
}

}  // namespace puncture::detail
