#pragma once
// Equilibrium at a prescribed depth, nested: secant steps in u = log f on the depth, the state
// at each force meeting the clamp condition by its own search in v = log(p - p0)
// (root_above_branch).  For the first point of a loading curve on a smooth probe
// (follow_curve), where DepthNewton's pair (f, p) is too ill-conditioned to start from the
// seed's extrapolation: near zero load the sphere-tipped probe's clamp residual rises from a
// branch point like a square root, its root ~1e-4 (p - 1) above it (below it Part I turns back
// towards the axis), and the states meeting the clamp condition form a valley whose floor
// Newton's steps cannot follow (its Jacobian changed fourfold from step to step).  On that
// valley's floor the depth is a smooth function of the force, d ~ f^(1/3): the secant on it
// converges in a few steps, and each force's parameter starts from its neighbours'
// (bench/README.md).
#include <algorithm>
#include <cmath>
#include <optional>

#include "indentation/free_part.hpp"
#include "indentation/scaled_solution.hpp"
#include "numerics/root_above_branch.hpp"

namespace puncture::detail {

// Shooting: an IndentationShooting (its assemble() and parameter_floor()).
template <class Shooting>
class NestedDepthSolve {
 public:
  // `tol`: on the depth relative to itself and on the clamp residual relative to p - p0 (as
  // DepthNewton's); a state whose depth residual stalls at the evaluations' noise is accepted
  // within `noise_tol` (DepthNewton::guarded).
  NestedDepthSolve(const Shooting& solver, double tol, double noise_tol)
      : solver_(solver), tol_(tol), noise_tol_(std::max(noise_tol, tol)) {}

  // The state of configuration c at normalised depth `depth`, from the force f and parameter p
  // (a rough guess: the search in p starts from it, climbing while Part I turns back).  Its
  // largest I1 is searched; its fields are not sampled.  Empty when a search fails.
  std::optional<ScaledSolution> solve(Configuration c, double depth, double f, double p) {
    const double floor = solver_.parameter_floor(c);
    if (!(f > 0.0) || !(p > floor) || !(depth > 0.0)) return std::nullopt;
    evaluations_ = 0;
    slope_.reset();
    const double depth_scale = std::max(depth, 1e-3);
    double u = std::log(f), v = std::log(p - floor);
    // The force's last two states on the valley (u, v, log(depth / target)).
    struct OnValley {
      double u, v, r;
      ScaledSolution state;
    };
    std::optional<OnValley> before, now;
    std::optional<OnValley> best;
    int noise_steps = 0;
    for (int k = 0; k < kMaxForces; ++k) {
      if (now) {
        // The secant on log(depth / target) in u; first with d ~ f^(1/3).  The parameter from
        // the last two states' slope dv/du, first with p - p0 ~ f^(1/2) (the sphere's).
        const double du_dr = before ? (now->u - before->u) / (now->r - before->r) : 3.0;
        const double dv_du = before ? (now->v - before->v) / (now->u - before->u) : 0.5;
        const double step = -now->r * du_dr;
        if (!std::isfinite(step) || !std::isfinite(dv_du)) break;
        u = now->u + step;
        v = now->v + dv_du * step;
      }
      auto valley = on_valley(c, u, v, floor);
      if (!valley || !(valley->depth > 0.0)) return std::nullopt;
      OnValley next{u,
                    std::log(valley->parameter - floor),
                    std::log(valley->depth / depth),
                    std::move(*valley)};
      const double miss = std::abs(next.state.depth - depth) / depth_scale;
      if (miss <= tol_) return accepted(std::move(next.state));
      const bool stalled = now && miss <= noise_tol_ &&
                           miss > 0.5 * std::abs(now->state.depth - depth) / depth_scale;
      if (stalled) ++noise_steps;
      if (!best || miss < std::abs(best->state.depth - depth) / depth_scale) best = next;
      if (noise_steps >= kNoiseSteps) break;
      before = std::move(now);
      now = std::move(next);
    }
    if (best && std::abs(best->state.depth - depth) / depth_scale <= noise_tol_ &&
        noise_steps >= kNoiseSteps)
      return accepted(std::move(best->state));
    return std::nullopt;
  }

 private:
  static constexpr int kMaxForces = 12;
  static constexpr int kNoiseSteps = 2;
  static constexpr int kInnerEvaluations = 40;
  static constexpr double kLogProbe = 1e-5;  // the first slope's step in v (DepthNewton's)

  // The state at force e^u meeting the clamp condition, its parameter searched from e^v above p0.
  std::optional<ScaledSolution> on_valley(Configuration c, double u, double v, double floor) {
    const double f = std::exp(u);
    std::optional<ScaledSolution> kept;
    auto residual = [&](double x) -> std::optional<double> {
      ++evaluations_;
      ScaledSolution s = solver_.assemble(c, f, floor + std::exp(x), false, false);
      // Not integrated counts as below the branch point: Part I turned back, or the cap reached
      // the sphere's equator before it carried f.  (Near zero load, where this search runs, no
      // parameter locks the material.)
      if (!s.integrated) return std::nullopt;
      if (s.residual == kTurnedBack) return std::nullopt;  // the contact's stand-in for it
      const double g = s.residual;
      kept = std::move(s);
      return g;
    };
    const double scale = std::min(1.0, std::exp(v));
    BranchRootSearch search;
    search.up_step = 0.5;
    search.probe = kLogProbe;
    // (Residuals below the integration's absolute tolerance are its noise: IndentationShooting::
    // above_branch.)
    search.tol = std::max(tol_ * scale, solver_.settings().integration.abs_tol);
    search.max_evaluations = kInnerEvaluations;
    search.slope = slope_;
    const auto root = root_above_branch(residual, v, search);
    if (!root || !(std::abs(root->g) <= noise_tol_ * scale)) return std::nullopt;
    // The next force's search starts with this slope (its first step lands next to the root).
    if (root->slope > 0.0) slope_ = root->slope;
    if (!kept || kept->parameter != floor + std::exp(root->x)) {
      ++evaluations_;
      kept = solver_.assemble(c, f, floor + std::exp(root->x), false, false);
    }
    return kept;
  }

  ScaledSolution accepted(ScaledSolution sol) {
    ++evaluations_;  // the same integration, its largest I1 searched
    sol = solver_.assemble(sol.configuration, sol.f, sol.parameter, false, true);
    accept_state(sol);
    sol.evaluations = evaluations_;
    return sol;
  }

  const Shooting& solver_;
  double tol_;
  double noise_tol_;
  int evaluations_ = 0;
  std::optional<double> slope_;  // dg/dv at the last force's root
};

}  // namespace puncture::detail
