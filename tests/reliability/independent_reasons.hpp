#pragma once
// Independent checks of the physical reasons the reliability sweep meets, through the public
// API only (solve_at_force), not the puncture search that gave them:
//   not reached   the stage's states end (found here by bisection on whether a state exists)
//                 with the largest I1 below the critical value, and none exists just beyond;
//   held membrane that would wrap the side: at the end of the held states the membrane leaves
//                 the edge vertically (corner slope -> 90 degrees, the pinned branch's end).
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <optional>
#include <string>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::test {

// The largest force [N] at which `stage` has a converged state, to 1e-9 relative: doubling from
// 1 nN until a solve fails, then bisection.  Empty when the states do not end below 1e6 N or
// already fail at 1 nN.
inline std::optional<double> stage_end_force_n(const Problem& p, Stage stage) {
  SolverOptions options;
  options.record_fields = false;
  auto exists = [&](double f) { return solve_at_force(p, f, stage, options).ok(); };
  double lo = 1e-9, hi = 2e-9;
  if (!exists(lo)) return std::nullopt;
  while (exists(hi)) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e6) return std::nullopt;
  }
  while (hi - lo > 1e-9 * hi) {
    const double mid = 0.5 * (lo + hi);
    (exists(mid) ? lo : hi) = mid;
  }
  return lo;
}

// Empty when the failure's physical reason is confirmed independently, else what disagrees.
// Reasons without an independent criterion here (limit loads, locking) pass.
inline std::string unconfirmed_reason(const Problem& p, const PuncturePrediction& at) {
  const bool not_reached = at.status == Status::NotReached;
  const bool wraps =
      at.status == Status::StickWrapsSide || at.message.find("wrap its side") != std::string::npos;
  if (!not_reached && !wraps) return {};
  const Stage stage = at.message.find("in the stick stage") != std::string::npos ||
                              at.status == Status::StickWrapsSide ||
                              p.stick.rule == StickRule::Always
                          ? Stage::Stick
                          : Stage::Slip;
  const auto end = stage_end_force_n(p, stage);
  if (!end) return "the stage's states do not end";
  SolverOptions options;
  options.record_fields = false;
  const Equilibrium last = solve_at_force(p, *end, stage, options);
  if (!last.ok()) return "no state at the end found";
  if (not_reached && !(last.max_first_invariant < p.critical_i1))
    return "the largest I1 at the end of the states reaches the critical value";
  // No state just beyond the end, and the end is physical.
  const Equilibrium beyond = solve_at_force(p, *end * (1.0 + 1e-6), stage, options);
  if (beyond.ok()) return "a state exists beyond the end";
  // Beyond the end: no state (physical), or a state the model does not cover (e.g. the ball's
  // contact past its equator); a numerical failure there is no end.
  if (beyond.failure_kind() == FailureKind::Numerical) return "the states end numerically";
  // The pinned branch ends where the membrane leaves the edge vertically: within 1e-9 of the end
  // the slope's deficit (going as the square root of the force's) is far below 0.01 rad.
  if (wraps && stage == Stage::Stick &&
      !(last.corner_slope_rad > boost::math::constants::half_pi<double>() - 1e-2))
    return "the held membrane does not leave the edge vertically at the end";
  return {};
}

}  // namespace puncture::test
