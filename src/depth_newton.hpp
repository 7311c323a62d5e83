#pragma once
// Equilibrium at a prescribed depth in a known configuration: Newton's method on the pair
// (force, shooting parameter) with residuals (clamp condition, depth), one integration per
// iteration.  The Jacobian is taken by finite differences when a segment starts and then kept
// up to date with Broyden's update, so successive points of a loading curve, each started from
// an extrapolation of the previous ones, cost two or three integrations.  Used for speed only:
// every failure falls back to the bracketing solver (solve_scaled_at_depth).
#include <Eigen/Dense>
#include <cmath>
#include <optional>

#include "force_solver.hpp"

namespace puncture::detail {

template <class Law>
class DepthNewton {
 public:
  DepthNewton(const ForceSolver<Law>& solver, double residual_tol)
      : solver_(solver), tol_(residual_tol) {}

  // Forget the Jacobian (a new configuration starts).
  void reset() { have_jacobian_ = false; }

  std::optional<ScaledSolution> solve(Configuration c, double depth, double f, double p) {
    Eigen::Vector2d x(f, p);
    auto value = [&](const ScaledSolution& s) {
      return Eigen::Vector2d(s.residual, s.depth - depth);
    };
    ScaledSolution sol = solver_.assemble(c, x[0], x[1], false);
    if (!sol.integrated) return std::nullopt;
    Eigen::Vector2d r = value(sol);
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
      if (std::abs(r[0]) <= tol_ && std::abs(r[1]) <= tol_ * std::max(depth, 1e-3) &&
          iteration > 0)
        return sol;
      if (!have_jacobian_ || iteration == kRefreshAfter) {
        if (!finite_difference_jacobian(c, x, r, depth)) return std::nullopt;
      }
      const Eigen::Vector2d step = -jacobian_.partialPivLu().solve(r);
      if (!step.allFinite()) return std::nullopt;
      // Backtrack when the full step leaves the material's domain or the configuration.
      double scale = 1.0;
      ScaledSolution next;
      for (int halving = 0; halving < 6; ++halving, scale *= 0.5) {
        const Eigen::Vector2d trial = x + scale * step;
        if (trial[0] <= 0.0 || trial[1] <= 0.0) continue;
        next = solver_.assemble(c, trial[0], trial[1], false);
        if (next.integrated) break;
      }
      if (!next.integrated) return std::nullopt;
      const Eigen::Vector2d dx = scale * step;
      const Eigen::Vector2d r_next = value(next);
      // Broyden's ("good") update keeps the Jacobian consistent with the step just taken.
      jacobian_ += ((r_next - r) - jacobian_ * dx) * dx.transpose() / dx.squaredNorm();
      x += dx;
      r = r_next;
      sol = std::move(next);
      if (std::abs(dx[0]) <= 1e-15 * x[0] && std::abs(dx[1]) <= 1e-15 * x[1]) break;
    }
    if (std::abs(r[0]) <= tol_ && std::abs(r[1]) <= tol_ * std::max(depth, 1e-3)) return sol;
    have_jacobian_ = false;
    return std::nullopt;
  }

 private:
  static constexpr int kMaxIterations = 12;
  static constexpr int kRefreshAfter = 4;  // iterations before a stale Jacobian is recomputed

  bool finite_difference_jacobian(Configuration c, const Eigen::Vector2d& x,
                                  const Eigen::Vector2d& r, double depth) {
    // Relative steps of 1e-7: truncation ~1e-7 and round-off ~1e-10/1e-7, both far below what
    // Newton needs to converge.
    for (int j = 0; j < 2; ++j) {
      Eigen::Vector2d xp = x;
      const double h = 1e-7 * x[j];
      xp[j] += h;
      const auto s = solver_.assemble(c, xp[0], xp[1], false);
      if (!s.integrated) return false;
      jacobian_.col(j) = (Eigen::Vector2d(s.residual, s.depth - depth) - r) / h;
    }
    have_jacobian_ = jacobian_.allFinite() && std::abs(jacobian_.determinant()) > 0.0;
    return have_jacobian_;
  }

  const ForceSolver<Law>& solver_;
  double tol_;
  Eigen::Matrix2d jacobian_ = Eigen::Matrix2d::Zero();
  bool have_jacobian_ = false;
};

}  // namespace puncture::detail
