#pragma once
// The loading path followed through a fold of the depth (docs/model.md §8.1, "Following a
// fold"): pseudo-arclength continuation (numerics/pseudo_arclength.hpp) of the states of one
// configuration, unknowns the shooting parameter p, the force f and the depth d (normalised),
// equations the clamp residual at (f, p) and the state's depth minus d, the arc length measured
// in (d, f) scaled by the path's last state.  Where depth control stops at a fold
// (depth_fold_after), it passes the turning point, locates it where the depth's tangent
// component vanishes, and follows the branch beyond, where the depth falls.
#include <Eigen/Dense>
#include <cmath>
#include <optional>
#include <vector>

#include "indentation/depth_fold.hpp"
#include "indentation/scaled_solution.hpp"
#include "numerics/pseudo_arclength.hpp"

namespace puncture::detail {

// y = (p, f, d).
inline constexpr int kArcParameter = 0;
inline constexpr int kArcForce = 1;
inline constexpr int kArcDepth = 2;

template <class Shooting>
class DepthArcSystem {
 public:
  // `scale`: the state whose force and depth scale the arc length.
  DepthArcSystem(const Shooting& shooting, Configuration c, const ScaledSolution& scale)
      : shooting_(shooting),
        c_(c),
        f_scale_(scale.f),
        d_scale_(scale.depth),
        p_scale_(std::abs(scale.parameter)) {}

  int unknowns() const { return 3; }
  std::optional<Eigen::VectorXd> residual(const Eigen::VectorXd& y) const {
    if (!(y[kArcForce] > 0.0) || !(y[kArcParameter] > shooting_.parameter_floor(c_)))
      return std::nullopt;
    const ScaledSolution s = state(y, false);
    if (!s.integrated || !std::isfinite(s.residual) || !std::isfinite(s.depth)) return std::nullopt;
    Eigen::VectorXd g(2);
    g << s.residual, s.depth - y[kArcDepth];
    return g;
  }
  // The clamp residual is relative already (the shooting's tolerance applies to it); the depth's
  // is relative to the path's depth.
  Eigen::VectorXd residual_scale() const { return Eigen::Vector2d(1.0, d_scale_); }
  Eigen::VectorXd scale() const { return Eigen::Vector3d(p_scale_, f_scale_, d_scale_); }
  Eigen::VectorXd metric() const {
    return Eigen::Vector3d(0.0, 1.0 / (f_scale_ * f_scale_), 1.0 / (d_scale_ * d_scale_));
  }

  // The state at y (its parameter and force), integrated once.
  ScaledSolution state(const Eigen::VectorXd& y, bool maxima = true) const {
    return shooting_.assemble(c_, y[kArcForce], y[kArcParameter], false, maxima);
  }

 private:
  const Shooting& shooting_;
  Configuration c_;
  double f_scale_, d_scale_, p_scale_;
};

inline Eigen::VectorXd arc_unknowns(const ScaledSolution& s) {
  return Eigen::Vector3d(s.parameter, s.f, s.depth);
}

// Arc length in units of the path's last state's (depth, force): steps of 2 % of them at first,
// at most 20 %; the corrector to 1e-1 of the shooting tolerance (1e-2 of it, as
// branch_state_at_force aims for, is the clamp residual's noise: a corrector at some arc lengths
// then stalled above it).
inline ArclengthSettings fold_arclength_settings(double shooting_tol) {
  ArclengthSettings s;
  s.initial_step = 0.02;
  s.max_step = 0.2;
  s.min_step = 1e-6;
  s.tolerance = 1e-1 * shooting_tol;
  return s;
}

// The branch followed through the fold: its states from the path's deepest state on (the fold
// among them, at `fold_index`), ending where the depth has fallen to kBeyondFoldDepth of the
// fold's or after kArcSteps steps.
struct FoldBranch {
  std::vector<ScaledSolution> states;
  std::size_t fold_index = 0;
  DepthFold fold;
  int steps = 0;  // accepted continuation steps
};

inline constexpr int kArcSteps = 200;
inline constexpr double kBeyondFoldDepth = 0.5;

// From the path's deepest state `deepest` and the state `before` it (the same configuration,
// shallower): the branch through the fold, if the depth turns back within kArcSteps steps.
template <class Shooting>
std::optional<FoldBranch> follow_through_fold(const Shooting& shooting,
                                              const ScaledSolution& before,
                                              const ScaledSolution& deepest) {
  if (before.configuration != deepest.configuration || !(deepest.depth > before.depth))
    return std::nullopt;
  const Configuration c = deepest.configuration;
  const DepthArcSystem<Shooting> system(shooting, c, deepest);
  PseudoArclength<DepthArcSystem<Shooting>> arc(
      system, fold_arclength_settings(shooting.settings().shooting_tol));
  ArcPoint a;
  a.y = arc_unknowns(deepest);
  const auto g = system.residual(a.y);
  if (!g) return std::nullopt;
  const auto j = arc.jacobian(a.y, *g);
  if (!j) return std::nullopt;
  a.tangent = arc.tangent(*j, a.y - arc_unknowns(before));  // along the path: deeper
  FoldBranch out;
  out.states.push_back(deepest);
  std::optional<double> fold_depth;
  for (; out.steps < kArcSteps; ++out.steps) {
    auto b = arc.advance(a);
    if (!b) break;
    if (!fold_depth && a.tangent[kArcDepth] > 0.0 && b->tangent[kArcDepth] < 0.0) {
      const auto turn = arc.turning_point(a, *b, kArcDepth);
      if (!turn) return std::nullopt;
      // The states' depths are converged to kFoldDepthNoise; the tangent's zero is located to
      // 2^-40 of the step, over which the depth changes by far less; the depth's change over
      // 1e-6 of the step either side bounds how flat the turn is there.
      double uncertainty = kFoldDepthNoise * turn->y[kArcDepth];
      const double h = 1e-6 * (b->arclength - a.arclength);
      for (const double side : {-1.0, 1.0})
        if (auto q = arc.correct(*turn, side * h))
          uncertainty = std::max(uncertainty,
                                 kFoldDepthNoise * turn->y[kArcDepth] +
                                     std::abs(q->y[kArcDepth] - turn->y[kArcDepth]));
      ScaledSolution s = system.state(turn->y);
      if (!s.ok()) return std::nullopt;
      fold_depth = s.depth;
      out.fold = DepthFold{s, uncertainty};
      out.fold_index = out.states.size();
      out.states.push_back(std::move(s));
    }
    ScaledSolution s = system.state(b->y);
    if (!s.ok()) break;
    out.states.push_back(std::move(s));
    a = std::move(*b);
    if (fold_depth && a.y[kArcDepth] < kBeyondFoldDepth * *fold_depth) break;
  }
  if (!fold_depth) return std::nullopt;
  return out;
}

}  // namespace puncture::detail
