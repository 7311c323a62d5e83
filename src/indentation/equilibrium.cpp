#include "puncture/equilibrium.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "indentation/dispatch.hpp"
#include "indentation/physical_state.hpp"
#include "indentation/reported_failure.hpp"
#include "indentation/scaled_problem.hpp"
#include "indentation/sealed_gas.hpp"

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

std::optional<ScaledSolution> direct_puncture(const Problem& problem,
                                              const SolverOptions& options) {
  return with_shooting(problem, options, [&](const auto& shooting) {
    return shooting.contact().direct_puncture(shooting, problem.critical_i1);
  });
}

}  // namespace detail

Equilibrium solve_at_force(const Problem& problem, double force_n, Stage stage,
                           const SolverOptions& options) {
  validate(problem);
  if (!std::isfinite(force_n) || force_n < 0.0)
    throw InvalidInput("force_n",
                       fmt::format("force must be a finite number >= 0 N, got {}", force_n));
  if (problem.preload.gas_volume_mm3)
    return detail::reporting_failures<Equilibrium>([&] {
      return detail::sealed_at_force(
          problem, detail::sealed_chamber(problem, options), force_n, stage, options);
    });
  const double f = force_n / detail::solver_scales(problem).force_n;
  return detail::reporting_failures<Equilibrium>([&] {
    return detail::with_shooting(problem, options, [&](const auto& shooting) {
      return detail::to_physical(
          problem, shooting.contact(), shooting.solve(stage, f), stage, options);
    });
  });
}

Equilibrium solve_at_depth(const Problem& problem, double depth_mm, Stage stage,
                           const SolverOptions& options) {
  validate(problem);
  if (!std::isfinite(depth_mm) || depth_mm < 0.0)
    throw InvalidInput("depth_mm",
                       fmt::format("depth must be a finite number >= 0 mm, got {}", depth_mm));
  if (problem.preload.gas_volume_mm3)
    return detail::reporting_failures<Equilibrium>([&] {
      return detail::sealed_at_depth(problem,
                                     detail::sealed_chamber(problem, options),
                                     depth_mm,
                                     stage,
                                     options,
                                     problem.preload.pressure_mpa);
    });
  const double d = depth_mm / detail::solver_scales(problem).length_mm;
  return detail::reporting_failures<Equilibrium>([&] {
    return detail::with_shooting(problem, options, [&](const auto& shooting) {
      return detail::to_physical(
          problem, shooting.contact(), shooting.solve_at_depth(stage, d), stage, options);
    });
  });
}

}  // namespace puncture
