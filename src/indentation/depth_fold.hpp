#pragma once
// Where depth control ends on a loading path, whether the depth turns back there (a fold): the
// branch is followed in force from the path's deepest state, the shooting parameter continued by
// secant steps on the clamp residual at each force (not a force search: it stays on the branch),
// and where the depth passes a maximum the fold is located by Brent's method on the depth as a
// function of the force (docs/model.md §8.1, "A fold exists on a later inflated state").  Under
// depth control the membrane snaps through there: the force drops at that depth.
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdint>
#include <optional>

#include "indentation/scaled_solution.hpp"

namespace puncture::detail {

// The located fold: the state of largest depth on the branch, and how far (normalised depth) the
// true turning depth may lie from it: the depth's change over the final force bracket.
struct DepthFold {
  ScaledSolution state;
  double depth_uncertainty = 0.0;
};

// Forces stepped by this factor from the deepest state (at most kFoldSteps: the force grows by
// up to 1.05^60 ~ 19 times), each state's parameter by secant steps to the clamp tolerance.
inline constexpr double kFoldForceFactor = 1.05;
inline constexpr int kFoldSteps = 60;
inline constexpr int kFoldSecantSteps = 30;
// The states' depths are converged to the shooting tolerance (~1e-9 relative, §8).
inline constexpr double kFoldDepthNoise = 1e-9;

// The state on the branch through (f_a, p_a) and (f_b, p_b) at force f, in configuration c: the
// parameter by secant steps from the line through them.  Empty if a step fails or does not meet
// the shooting tolerance.
template <class Shooting>
std::optional<ScaledSolution> branch_state_at_force(const Shooting& shooting, Configuration c,
                                                    double f, double f_a, double p_a, double f_b,
                                                    double p_b) {
  const double tol = shooting.settings().shooting_tol;
  double x0 = p_b + (p_b - p_a) / (f_b - f_a) * (f - f_b);
  double x1 = x0 * (1.0 + 1e-7);
  auto g0 = shooting.residual(c, f, x0), g1 = shooting.residual(c, f, x1);
  for (int k = 0; k < kFoldSecantSteps && g0 && g1; ++k) {
    if (std::abs(*g1) <= 1e-2 * tol) break;
    if (*g1 == *g0) return std::nullopt;
    const double x2 = x1 - *g1 * (x1 - x0) / (*g1 - *g0);
    x0 = x1;
    g0 = g1;
    x1 = x2;
    g1 = shooting.residual(c, f, x1);
  }
  if (!g1 || !(std::abs(*g1) <= tol)) return std::nullopt;
  ScaledSolution s = shooting.assemble(c, f, x1, false);
  if (!s.integrated || !(std::abs(s.residual) <= tol)) return std::nullopt;
  return s;
}

// From the path's deepest state `deepest` and the state `before` it on the path (the same
// configuration), the fold where the depth turns back, if it does within kFoldSteps force steps.
template <class Shooting>
std::optional<DepthFold> depth_fold_after(const Shooting& shooting, const ScaledSolution& before,
                                          const ScaledSolution& deepest) {
  if (before.configuration != deepest.configuration || !(deepest.f > before.f)) return std::nullopt;
  const Configuration c = deepest.configuration;
  ScaledSolution a = before, b = deepest;
  for (int k = 0; k < kFoldSteps; ++k) {
    const double f = b.f * kFoldForceFactor;
    auto next = branch_state_at_force(shooting, c, f, a.f, a.parameter, b.f, b.parameter);
    if (!next) return std::nullopt;
    if (next->depth < b.depth) {
      // The depth's maximum lies between a's force and next's: Brent on -depth(f), each state from
      // the line through a and next.
      const ScaledSolution lo = a, hi = *next;
      std::optional<ScaledSolution> best;
      auto minus_depth = [&](double force) {
        auto s = branch_state_at_force(shooting, c, force, lo.f, lo.parameter, hi.f, hi.parameter);
        if (!s) return 0.0;  // outside the branch: no maximum there
        if (!best || s->depth > best->depth) best = *s;
        return -s->depth;
      };
      std::uintmax_t iterations = 100;
      const auto found =
          boost::math::tools::brent_find_minima(minus_depth, lo.f, hi.f, 40, iterations);
      (void)found;
      if (!best || !(best->depth >= b.depth)) return std::nullopt;
      // Near a maximum the depth is flat in the force: its change across Brent's final bracket
      // (2^-40 of the force) is far below the states' own accuracy (kFoldDepthNoise of the
      // depth); the uncertainty is that plus the depth's change over 1e-6 of the force either
      // side.
      const double h = 1e-6 * best->f;
      double uncertainty = kFoldDepthNoise * best->depth;
      for (const double side : {-1.0, 1.0}) {
        auto s = branch_state_at_force(
            shooting, c, best->f + side * h, lo.f, lo.parameter, hi.f, hi.parameter);
        if (s)
          uncertainty = std::max(uncertainty,
                                 kFoldDepthNoise * best->depth + std::abs(best->depth - s->depth));
      }
      return DepthFold{std::move(*best), uncertainty};
    }
    a = std::move(b);
    b = std::move(*next);
  }
  return std::nullopt;
}

}  // namespace puncture::detail
