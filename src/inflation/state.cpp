// One inflated state in physical units, with its fields along the meridian.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "inflation/scaled_inflation.hpp"
#include "mechanics/field_point.hpp"

namespace puncture {

namespace detail {

void check_pole_stretch(const InflationProblem& problem, double pole_stretch) {
  const double flat = problem.prestretch;
  if (!std::isfinite(pole_stretch) || pole_stretch < flat)
    throw InvalidInput(
        "pole_stretch",
        flat == 1.0 ? fmt::format("pole stretch must be a finite number >= 1 (an inflated "
                                  "membrane stretches), got {}",
                                  pole_stretch)
                    : fmt::format("pole stretch must be a finite number >= the pre-stretch {:g} "
                                  "(an inflated membrane stretches beyond its flat state), got {}",
                                  flat,
                                  pole_stretch));
}

namespace {

// The membrane is free throughout, its deflection along the pressure is its height.
void push_field(MembraneFields& f, const MaterialLaw& law, double g, double a, double r_ref,
                double radius, double height, double slope, double l1, double l2) {
  append_point(f,
               MembranePart::Free,
               a * r_ref,
               a * radius,
               a * height,
               slope,
               l1,
               l2,
               membrane_stress(law, l1, l2),
               g,
               0.0,
               0.0);
}

}  // namespace

InflationState to_physical(const InflationProblem& p, const ScaledInflation& sol) {
  // The solver's lengths are in the stress-free clamp radius A / L0.
  const double a = reference_clamp_radius_mm(p), h = p.thickness_mm;
  const double g = p.material.shear_modulus_mpa;
  InflationState s;
  s.status = sol.status;
  s.message = sol.message;
  s.pole_stretch = sol.pole_stretch;
  s.shooting_evaluations = sol.evaluations;
  if (!sol.ok()) return s;
  const double l0 = sol.pole_stretch;
  // The reported normalisation stays p A / (G H), A the clamp radius (the solver's is A / L0).
  s.normalized_pressure = sol.pressure * p.prestretch;
  s.pressure_mpa = sol.pressure * solver_pressure_scale_mpa(p);
  s.pole_height_mm = a * sol.pole_height;
  s.volume_mm3 = a * a * a * sol.volume;
  s.stored_energy_mj = 2.0 * std::numbers::pi * g * h * a * a * sol.energy;
  const double s0 = membrane_stress(p.material.law, l0, l0).s1;
  s.pole_stress_mpa = g * s0;
  s.pole_tension_n_per_mm = g * h * s0 / l0;
  // phi = c R near the pole and ds = l0 dR: curvature c / l0 per unit current length.
  s.pole_curvature_radius_mm =
      sol.slope_rate > 0.0 ? a * l0 / sol.slope_rate : std::numeric_limits<double>::infinity();
  s.clamp_radial_stretch = sol.clamp_l1;
  s.clamp_slope_rad = sol.clamp_slope;
  s.max_first_invariant = sol.max_i1;
  s.max_first_invariant_reference_radius_mm = a * sol.max_i1_r_ref;
  s.max_first_invariant_radius_mm = a * sol.max_i1_radius;
  s.clamp_residual = sol.residual;
  if (sol.samples.empty()) return s;
  auto& f = s.fields;
  push_field(f, p.material.law, g, a, 0.0, 0.0, sol.pole_height, 0.0, l0, l0);
  for (const auto& x : sol.samples) {
    const double radius = x.l2 * x.r_ref;
    const double slope = std::atan2(0.5 * sol.pressure * radius * radius, x.t);
    push_field(f,
               p.material.law,
               g,
               a,
               x.r_ref,
               radius,
               sol.pole_height - x.drop,
               sol.pressure > 0.0 ? slope : 0.0,
               x.l1,
               x.l2);
  }
  return s;
}

}  // namespace detail

InflationState inflate_at_pole_stretch(const InflationProblem& problem, double pole_stretch,
                                       const SolverOptions& options) {
  validate(problem);
  detail::check_pole_stretch(problem, pole_stretch);
  return detail::to_physical(problem, detail::solve_inflation(problem, pole_stretch, options));
}

}  // namespace puncture
