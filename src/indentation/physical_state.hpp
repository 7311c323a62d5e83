#pragma once
// A normalised solution as the user's Equilibrium (mm, N, MPa), with the fields when asked: the
// contact model places the largest I1 and gives the fields of the parts in contact.
#include <fmt/format.h>

#include <cmath>

#include "indentation/contact/contact_model.hpp"
#include "indentation/criterion_on_state.hpp"
#include "indentation/scaled_solution.hpp"
#include "indentation/solver_scales.hpp"
#include "indentation/state_fields.hpp"
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
  if (sol.configuration != Configuration::Unloaded) {
    e.contact_edge_radius_mm = sol.edge_radius * big_a;
    e.contact_edge_height_mm = contact.free_part_inner_height(sol) * big_a;
  }
  e.corner_tension_ratio = sol.tension_ratio;
  e.max_first_invariant = max_first_invariant_of(sol);
  const LargestFirstInvariant largest = contact.largest_first_invariant(sol);
  e.max_first_invariant_reference_radius_mm = largest.reference_radius * big_a;
  e.max_first_invariant_radius_mm = largest.radius * big_a;
  e.max_first_invariant_part = largest.part;
  e.clamp_residual = std::abs(sol.residual);
  e.shooting_evaluations = sol.evaluations;
  e.beyond_puncture = any_exceeded(p, contact, sol);
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
  if (options.record_fields && sol.ok()) append_state_fields(p, contact, sol, e.fields);
  return e;
}

}  // namespace puncture::detail
