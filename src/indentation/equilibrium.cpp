#include "puncture/equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "indentation/dispatch.hpp"
#include "indentation/reported_failure.hpp"
#include "indentation/scaled_problem.hpp"

namespace puncture {

std::string to_string(Configuration c) {
  switch (c) {
    case Configuration::Unloaded:
      return "unloaded";
    case Configuration::Stick:
      return "stick";
    case Configuration::SlipWithoutPartTwo:
      return "slip without Part II";
    case Configuration::SlipWithPartTwo:
      return "slip with Part II";
  }
  return "?";
}

std::string to_token(Configuration c) {
  switch (c) {
    case Configuration::Unloaded:
      return "unloaded";
    case Configuration::Stick:
      return "stick";
    case Configuration::SlipWithoutPartTwo:
      return "slip_without_part_two";
    case Configuration::SlipWithPartTwo:
      return "slip_with_part_two";
  }
  return "unknown";
}

std::string to_string(Stage stage) { return stage == Stage::Stick ? "stick" : "slip"; }

namespace detail {

ScaledSolution solve_scaled(const Problem& problem, double f, Stage stage,
                            const SolverOptions& options) {
  return with_shooting(
      problem, options, [&](const auto& shooting) { return shooting.solve(stage, f); });
}

ScaledSolution solve_scaled_at_depth(const Problem& problem, double d, Stage stage,
                                     const SolverOptions& options, double f_guess) {
  return with_shooting(problem, options, [&](const auto& shooting) {
    return shooting.solve_at_depth(stage, d, f_guess);
  });
}

std::optional<ScaledSolution> direct_puncture(const Problem& problem,
                                              const SolverOptions& options) {
  return with_shooting(problem, options, [&](const auto& shooting) {
    return shooting.contact().direct_puncture(shooting, problem.critical_i1);
  });
}

namespace {

void push_point(MembraneFields& m, int part, double r_ref, double radius, double deflection,
                double slope, double l1, double l2, const MembraneStress& st, double g_mpa,
                double pressure, double friction) {
  m.part.push_back(part);
  m.reference_radius_mm.push_back(r_ref);
  m.radius_mm.push_back(radius);
  m.deflection_mm.push_back(deflection);
  m.slope_rad.push_back(slope);
  m.radial_stretch.push_back(l1);
  m.hoop_stretch.push_back(l2);
  m.thickness_stretch.push_back(1.0 / (l1 * l2));
  m.radial_stress_mpa.push_back(st.s1 * g_mpa);
  m.hoop_stress_mpa.push_back(st.s2 * g_mpa);
  m.first_invariant.push_back(st.i1);
  m.contact_pressure_mpa.push_back(pressure);
  m.friction_traction_mpa.push_back(friction);
}

MembraneFields fields_of(const Problem& p, const ScaledSolution& sol) {
  MembraneFields m;
  const double big_a = p.geometry.clamp_radius_mm;
  const double a = radius_mm(p.indenter) / big_a;
  const double g = p.material.shear_modulus_mpa;
  const double depth = sol.depth * big_a;
  // Part III: homogeneous under the flat tip (unstretched when held).
  const double l3 = sol.part_three_stretch;
  constexpr int kPartThreePoints = 5;
  for (int i = 0; i < kPartThreePoints; ++i) {
    const double r_ref = sol.r_corner * i / (kPartThreePoints - 1);
    push_point(m,
               3,
               r_ref * big_a,
               l3 * r_ref * big_a,
               depth,
               0.0,
               l3,
               l3,
               membrane_stress(p.material.law, l3, l3),
               g,
               0.0,
               0.0);
  }
  // Part II, from the corner up the side (samples were taken downward).
  for (auto it = sol.part_two.rbegin(); it != sol.part_two.rend(); ++it) {
    const double r_ref = (*it)[0], l1 = (*it)[1], l2 = a / r_ref;
    const auto st = membrane_stress(p.material.law, l1, l2);
    const double pressure =
        st.s2 * g * p.geometry.thickness_mm / (l1 * radius_mm(p.indenter));  // Eq. (16)
    const double z = depth - (sol.part_two_length - (*it)[2]) * big_a;
    push_point(m,
               2,
               r_ref * big_a,
               radius_mm(p.indenter),
               z,
               detail::kHalfPi,
               l1,
               l2,
               st,
               g,
               pressure,
               p.friction * pressure);
  }
  // Part I, from the indenter to the clamp.
  for (const auto& s : sol.part_one) {
    const double r_ref = s[0], t = s[1], l1 = s[2], l2 = s[3], h = s[4];
    const double z = depth - (sol.part_two_length + h) * big_a;
    push_point(m,
               1,
               r_ref * big_a,
               l2 * r_ref * big_a,
               z,
               std::atan2(sol.f, t),
               l1,
               l2,
               membrane_stress(p.material.law, l1, l2),
               g,
               0.0,
               0.0);
  }
  return m;
}

}  // namespace

Equilibrium to_physical(const Problem& p, const ScaledSolution& sol, Stage stage,
                        const SolverOptions& options) {
  Equilibrium e;
  const double big_a = p.geometry.clamp_radius_mm;
  e.status = sol.status;
  e.message = sol.message;
  e.configuration = sol.configuration;
  e.stage = stage;
  e.normalized_force = sol.f;
  e.force_n = sol.f * force_scale_n(p);
  e.depth_mm = sol.depth * big_a;
  e.part_three_stretch = sol.part_three_stretch;
  e.corner_reference_radius_mm = sol.r_corner * big_a;
  e.part_two_top_reference_radius_mm = sol.r_top * big_a;
  e.part_two_length_mm = sol.part_two_length * big_a;
  e.corner_slope_rad = sol.corner_slope;
  e.corner_tension_ratio = sol.tension_ratio;
  e.max_first_invariant = max_first_invariant_of(sol);
  // Where I1 is largest; a tie with Part III (mu = 0) is reported at the corner's Part I/II side.
  const bool in_part_three = sol.max_i1 < e.max_first_invariant;
  e.max_first_invariant_reference_radius_mm = (in_part_three ? sol.r_corner : sol.max_i1_r) * big_a;
  e.max_first_invariant_radius_mm =
      (in_part_three ? sol.r_corner * sol.part_three_stretch : sol.max_i1_radius) * big_a;
  // The flat punch's parts: Part II spans the side from the corner to its top.
  e.max_first_invariant_part =
      in_part_three ? MembranePart::Tip
      : sol.configuration == Configuration::SlipWithPartTwo && sol.max_i1_r < sol.r_top
          ? MembranePart::Side
          : MembranePart::Free;
  e.clamp_residual = std::abs(sol.residual);
  e.shooting_evaluations = sol.evaluations;
  if (options.record_fields && sol.ok()) e.fields = fields_of(p, sol);
  return e;
}

}  // namespace detail

namespace {

Equilibrium invalid(std::string message) {
  Equilibrium e;
  e.status = Status::InvalidInput;
  e.message = std::move(message);
  return e;
}

}  // namespace

Equilibrium solve_at_force(const Problem& problem, double force_n, Stage stage,
                           const SolverOptions& options) {
  if (const auto errors = validation_errors(problem); !errors.empty())
    return invalid(errors.front().message);
  if (!std::isfinite(force_n) || force_n < 0.0)
    return invalid("force must be a finite number >= 0 N, got " + std::to_string(force_n));
  const double f = force_n / force_scale_n(problem);
  return detail::reporting_failures<Equilibrium>([&] {
    return detail::to_physical(
        problem, detail::solve_scaled(problem, f, stage, options), stage, options);
  });
}

Equilibrium solve_at_depth(const Problem& problem, double depth_mm, Stage stage,
                           const SolverOptions& options) {
  if (const auto errors = validation_errors(problem); !errors.empty())
    return invalid(errors.front().message);
  if (!std::isfinite(depth_mm) || depth_mm < 0.0)
    return invalid("depth must be a finite number >= 0 mm, got " + std::to_string(depth_mm));
  const double d = depth_mm / problem.geometry.clamp_radius_mm;
  return detail::reporting_failures<Equilibrium>([&] {
    return detail::to_physical(
        problem, detail::solve_scaled_at_depth(problem, d, stage, options), stage, options);
  });
}

}  // namespace puncture
