#include "puncture/equilibrium.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "indentation/dispatch.hpp"
#include "indentation/partial_slip_path.hpp"
#include "indentation/partial_slip_puncture.hpp"
#include "indentation/physical_state.hpp"
#include "indentation/puncture_search.hpp"
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
    case Configuration::PartialSlip:
      return "partial slip";
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
    case Configuration::PartialSlip:
      return "partial_slip";
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

// The path's state at a depth between a `coulomb` release and the hand-over to the sliding
// model (partial_slip_path.hpp), as the loading curve's, with its fields when `options` records
// them; empty elsewhere.
template <class Shooting>
std::optional<Equilibrium> partial_slip_at_depth(const Problem& p, const Shooting& shooting,
                                                 double depth_mm, const SolverOptions& options) {
  if (p.stick.rule != StickRule::Coulomb) return std::nullopt;
  const auto switch_point = locate_switch(p, shooting);
  const StageBoundary& b = switch_point.boundary;
  if (b.status != Status::Converged || !b.switches) return std::nullopt;
  const auto segment = partial_slip_segment(p, shooting, b);
  if (!segment || !segment->covers(depth_mm) || depth_mm < segment->first_depth_mm)
    return std::nullopt;
  auto found = segment->detail_at_depth(depth_mm, options.record_fields);
  if (!found) {
    Equilibrium e;
    e.stage = Stage::Slip;
    e.configuration = Configuration::PartialSlip;
    e.status = Status::NoConvergence;
    e.message = fmt::format("no partial-slip state after the coulomb release reaches depth {} mm",
                            depth_mm);
    return e;
  }
  found->point.depth_mm = depth_mm;  // the family's depth, to its search's 1e-13
  return partial_slip_equilibrium(p, *segment, std::move(*found));
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
      if (stage == Stage::Slip)
        if (auto partial = detail::partial_slip_at_depth(problem, shooting, depth_mm, options))
          return std::move(*partial);
      return detail::to_physical(
          problem, shooting.contact(), shooting.solve_at_depth(stage, d), stage, options);
    });
  });
}

}  // namespace puncture
