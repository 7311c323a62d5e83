#include "puncture/equilibrium.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "indentation/depth_solve.hpp"
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

namespace {

// The partial-slip family of a `coulomb` problem after its release (partial_slip_path.hpp),
// built on `shooting` after locating the switch; empty for other rules or without a release.
template <class Shooting>
std::optional<PartialSlipSegment> coulomb_partial_slip(const Problem& p, const Shooting& shooting) {
  if (p.stick.rule != StickRule::Coulomb) return std::nullopt;
  const auto switch_point = locate_switch(p, shooting);
  const StageBoundary& b = switch_point.boundary;
  if (b.status != Status::Converged || !b.switches) return std::nullopt;
  return partial_slip_segment(p, shooting, b);
}

// The path's state at a depth between a `coulomb` release and the hand-over to the sliding
// model, the family's (as the loading curve's), with its fields when `options` records them;
// empty elsewhere.
std::optional<Equilibrium> partial_slip_state(const Problem& p, const PartialSlipSegment& segment,
                                              double depth_mm, const SolverOptions& options) {
  if (!segment.covers(depth_mm) || depth_mm < segment.first_depth_mm) return std::nullopt;
  auto found = segment.detail_at_depth(depth_mm, options.record_fields);
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
  return partial_slip_equilibrium(p, segment, std::move(*found));
}

template <class Shooting>
std::optional<Equilibrium> partial_slip_at_depth(const Problem& p, const Shooting& shooting,
                                                 double depth_mm, const SolverOptions& options) {
  const auto segment = coulomb_partial_slip(p, shooting);
  if (!segment) return std::nullopt;
  return partial_slip_state(p, *segment, depth_mm, options);
}

// solve_at_depth's state outside the family (the caller's): on a fresh shooting, the switch
// located first in the slip stage as solve_at_depth does (its solves leave the contact model's
// warm starts as there), then the depth's own solve.
Equilibrium state_at_depth_beside_family(const Problem& p, double depth_mm, Stage stage,
                                         const SolverOptions& options) {
  const double d = depth_mm / solver_scales(p).length_mm;
  return reporting_failures<Equilibrium>([&] {
    return with_shooting(p, options, [&](const auto& shooting) {
      if (stage == Stage::Slip) (void)locate_switch(p, shooting);
      return to_physical(p, shooting.contact(), shooting.solve_at_depth(stage, d), stage, options);
    });
  });
}

}  // namespace

void with_depth_solve(const Problem& p, const SolverOptions& options,
                      const std::function<void(const DepthSolve&)>& use) {
  // Under a gas pressure each depth is solved on its own (solve_at_depth: the same states).
  if (p.stick.rule != StickRule::Coulomb || p.preload.gas_volume_mm3 ||
      p.preload.pressure_mpa > 0.0) {
    use([&](double depth_mm, Stage stage) { return solve_at_depth(p, depth_mm, stage, options); });
    return;
  }
  with_shooting(p, options, [&](const auto& shooting) {
    std::optional<PartialSlipSegment> family;
    bool built = true;
    try {
      family = coulomb_partial_slip(p, shooting);
    } catch (const std::exception&) {  // then each depth's own solve_at_depth says why
      built = false;
    }
    use([&](double depth_mm, Stage stage) -> Equilibrium {
      if (!built) return solve_at_depth(p, depth_mm, stage, options);
      if (stage == Stage::Slip && family && family->covers(depth_mm) &&
          depth_mm >= family->first_depth_mm)
        return reporting_failures<Equilibrium>(
            [&] { return *partial_slip_state(p, *family, depth_mm, options); });
      return state_at_depth_beside_family(p, depth_mm, stage, options);
    });
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
      if (stage == Stage::Slip)
        if (auto partial = detail::partial_slip_at_depth(problem, shooting, depth_mm, options))
          return std::move(*partial);
      return detail::to_physical(
          problem, shooting.contact(), shooting.solve_at_depth(stage, d), stage, options);
    });
  });
}

}  // namespace puncture
