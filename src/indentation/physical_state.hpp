#pragma once
// A normalised solution as the user's Equilibrium (mm, N, MPa), with the fields when asked: the
// contact model places the largest I1 and gives the fields of the parts in contact.
#include <fmt/format.h>

#include <cmath>

#include "failure/criterion.hpp"
#include "indentation/contact/contact_model.hpp"
#include "indentation/membrane_fields.hpp"
#include "indentation/scaled_solution.hpp"
#include "indentation/solver_scales.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/problem.hpp"

namespace puncture::detail {

template <class Contact>
Equilibrium to_physical(const Problem& p, const Contact& contact, const ScaledSolution& sol,
                        Stage stage, const SolverOptions& options) {
  Equilibrium e;
  const SolverScales units = solver_scales(p);
  const double big_a = units.length_mm;
  e.status = sol.status;
  e.message = sol.message;
  e.configuration = sol.configuration;
  e.stage = stage;
  e.normalized_force = units.normalized_force(sol.f);
  e.force_n = sol.f * units.force_n;
  e.depth_mm = sol.depth * big_a;
  e.part_three_stretch = sol.part_three_stretch;
  e.corner_reference_radius_mm = sol.r_corner * big_a;
  e.part_two_top_reference_radius_mm = sol.r_top * big_a;
  e.part_two_length_mm = sol.part_two_length * big_a;
  e.corner_slope_rad = sol.corner_slope;
  e.corner_tension_ratio = sol.tension_ratio;
  e.max_first_invariant = max_first_invariant_of(sol);
  const LargestFirstInvariant largest = contact.largest_first_invariant(sol);
  e.max_first_invariant_reference_radius_mm = largest.reference_radius * big_a;
  e.max_first_invariant_radius_mm = largest.radius * big_a;
  e.max_first_invariant_part = largest.part;
  e.clamp_residual = std::abs(sol.residual);
  e.shooting_evaluations = sol.evaluations;
  e.beyond_puncture = exceeded(failure_criterion(p), sol);
  if (sol.status == Status::Wrinkles)
    e.message = fmt::format(
        "the hoop stress turns compressive at reference radius R = {:.6g} mm (current radius r "
        "= {:.6g} mm): the membrane wrinkles there, outside the tension-only membrane theory (a "
        "tension-field model is not implemented), so no state is given",
        sol.wrinkle_r * big_a,
        sol.wrinkle_radius * big_a);
  if (sol.deepest_state)
    e.message = fmt::format(
        "this depth cannot be reached: the deepest equilibrium of the {} stage is at depth "
        "{:.6g} mm and force {:.6g} N (largest I1 {:.6g}); beyond it {}",
        to_string(stage),
        e.depth_mm,
        e.force_n,
        e.max_first_invariant,
        sol.message);
  if (options.record_fields && sol.ok()) {
    const FieldScales scales{big_a, p.material.shear_modulus_mpa, p.geometry.thickness_mm};
    // Before contact under a gas pressure the whole membrane is the inflated dome, free.
    const bool dome = sol.configuration == Configuration::Unloaded && p.preload.pressure_mpa > 0.0;
    if (!dome) contact.append_contact_fields(sol, scales, e.fields);
    append_free_fields(contact.law(),
                       sol,
                       dome ? 0.0 : contact.free_part_inner_height(sol),
                       scales,
                       e.fields,
                       dome_pressure(p));
  }
  return e;
}

}  // namespace puncture::detail
