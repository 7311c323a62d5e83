#include "puncture/equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

std::string to_string(Status s) {
  switch (s) {
    case Status::Converged:
      return "converged";
    case Status::NoConvergence:
      return "no convergence";
    case Status::BeyondLocking:
      return "beyond locking";
    case Status::StickWrapsSide:
      return "stick wraps side";
    case Status::InvalidInput:
      return "invalid input";
  }
  return "?";
}

namespace detail {

ScaledSettings scaled_settings(const Problem& p, const SolverOptions& o) {
  return {p.geometry.indenter_radius_mm / p.geometry.clamp_radius_mm,
          p.friction,
          p.part_two_equation,
          {o.integration_rel_tol, o.integration_abs_tol, o.max_steps},
          o.shooting_tol,
          o.max_shooting_iterations,
          o.field_points};
}

ScaledSolution solve_scaled(const Problem& problem, double f, Stage stage,
                            const SolverOptions& options) {
  if (f == 0.0) {
    ScaledSolution flat;
    flat.status = Status::Converged;
    const double a = problem.geometry.indenter_radius_mm / problem.geometry.clamp_radius_mm;
    flat.r_corner = flat.r_top = a;
    flat.configuration = Configuration::Unloaded;
    // The rest of the flat membrane is Part I, unstretched, from the indenter's edge to the
    // clamp: sampled like a loaded Part I (at least field_points steps, both ends included).
    if (options.record_fields) {
      const int n = std::max(1, options.field_points);
      for (int k = 0; k <= n; ++k) {
        const double r = k == n ? 1.0 : a + (1.0 - a) * k / n;
        flat.part_one.push_back({r, 0.0, 1.0, 1.0, 0.0});
      }
    }
    return flat;
  }
  const auto settings = scaled_settings(problem, options);
  return std::visit(
      [&](const auto& law) {
        const ForceSolver solver(law, settings);
        return stage == Stage::Stick ? solver.stick(f) : solver.slip(f);
      },
      problem.material.law);
}

ScaledSolution solve_scaled_at_depth(const Problem& problem, double d, Stage stage,
                                     const SolverOptions& options, double f_guess) {
  if (d == 0.0) return solve_scaled(problem, 0.0, stage, options);
  SolverOptions inner = options;
  inner.record_fields = false;
  ScaledSolution last_failure;
  auto residual = [&](double f) -> std::optional<double> {
    auto sol = solve_scaled(problem, f, stage, inner);
    if (!sol.ok()) {
      last_failure = std::move(sol);
      return std::nullopt;
    }
    return sol.depth - d;
  };
  const double step = f_guess > 0.0 ? 0.5 * f_guess : 0.1;
  const auto f = shoot_increasing(residual,
                                  0.0,
                                  -d,
                                  std::numeric_limits<double>::infinity(),
                                  options.max_shooting_iterations,
                                  step);
  if (!f) {
    if (last_failure.status == Status::Converged) last_failure.status = Status::NoConvergence;
    if (last_failure.message.empty())
      last_failure.message = "no force gives the requested depth";
    else
      last_failure.message = "the requested depth cannot be reached: " + last_failure.message;
    return last_failure;
  }
  return solve_scaled(problem, *f, stage, options);
}

double max_first_invariant(const ScaledSolution& sol) { return max_first_invariant_of(sol); }

std::optional<ScaledSolution> puncture_at_corner(const Problem& problem,
                                                 const SolverOptions& options) {
  const auto settings = scaled_settings(problem, options);
  return std::visit(
      [&](const auto& law) {
        return ForceSolver(law, settings).puncture_at_corner(problem.critical_i1);
      },
      problem.material.law);
}

std::optional<ScaledSolution> part_two_onset(const Problem& problem, const SolverOptions& options) {
  const auto settings = scaled_settings(problem, options);
  return std::visit([&](const auto& law) { return ForceSolver(law, settings).part_two_onset(); },
                    problem.material.law);
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
  const double a = p.geometry.indenter_radius_mm / big_a;
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
        st.s2 * g * p.geometry.thickness_mm / (l1 * p.geometry.indenter_radius_mm);  // Eq. (16)
    const double z = depth - (sol.part_two_length - (*it)[2]) * big_a;
    push_point(m,
               2,
               r_ref * big_a,
               p.geometry.indenter_radius_mm,
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
  e.max_first_invariant = max_first_invariant(sol);
  // Where I1 is largest; a tie with Part III (mu = 0) is reported at the corner's Part I/II side.
  const bool in_part_three = sol.max_i1 < e.max_first_invariant;
  e.max_first_invariant_reference_radius_mm = (in_part_three ? sol.r_corner : sol.max_i1_r) * big_a;
  e.max_first_invariant_radius_mm =
      (in_part_three ? sol.r_corner * sol.part_three_stretch : sol.max_i1_radius) * big_a;
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
    return invalid(errors.front());
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
    return invalid(errors.front());
  if (!std::isfinite(depth_mm) || depth_mm < 0.0)
    return invalid("depth must be a finite number >= 0 mm, got " + std::to_string(depth_mm));
  const double d = depth_mm / problem.geometry.clamp_radius_mm;
  return detail::reporting_failures<Equilibrium>([&] {
    return detail::to_physical(
        problem, detail::solve_scaled_at_depth(problem, d, stage, options), stage, options);
  });
}

}  // namespace puncture
