#pragma once
// Equilibrium at a prescribed depth in a known configuration: Newton's method on the pair
// (force, shooting parameter) with residuals (clamp condition, depth), one integration per
// iteration.  The Jacobian is taken by finite differences and reused from point to point along
// a loading curve (a chord method) until the convergence slows down, so that a point started from
// a good extrapolation of the previous ones costs three or four integrations.  Used for speed
// only: any failure falls back to the bracketing solver (solve_scaled_at_depth).
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
    auto converged = [&](const Eigen::Vector2d& r) {
      return std::abs(r[0]) <= tol_ && std::abs(r[1]) <= tol_ * std::max(depth, 1e-3);
    };
    ScaledSolution sol = solver_.assemble(c, x[0], x[1], false);
    if (!sol.integrated) return std::nullopt;
    Eigen::Vector2d r = value(sol);
    bool fresh = false;  // the Jacobian was computed at this point
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
      if (iteration > 0 && converged(r)) return sol;
      if (!have_jacobian_) {
        if (!finite_difference_jacobian(c, x, r, depth)) return std::nullopt;
        fresh = true;
      }
      const Eigen::Vector2d step = -lu_.solve(r);
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
      const Eigen::Vector2d r_next = value(next);
      // A chord step that does not shrink the residual tenfold means a stale Jacobian.
      if (!fresh && r_next.cwiseAbs().maxCoeff() > kChordContraction * r.cwiseAbs().maxCoeff())
        have_jacobian_ = false;
      x += scale * step;
      r = r_next;
      sol = std::move(next);
    }
    if (converged(r)) return sol;
    have_jacobian_ = false;
    return std::nullopt;
  }

 private:
  static constexpr int kMaxIterations = 10;
  static constexpr double kChordContraction = 0.1;

  bool finite_difference_jacobian(Configuration c, const Eigen::Vector2d& x,
                                  const Eigen::Vector2d& r, double depth) {
    // Relative steps of 1e-7: truncation ~1e-7 and round-off ~1e-10/1e-7 relative, both far
    // below what Newton needs to converge.
    Eigen::Matrix2d jacobian;
    for (int j = 0; j < 2; ++j) {
      Eigen::Vector2d xp = x;
      const double h = 1e-7 * x[j];
      xp[j] += h;
      const auto s = solver_.assemble(c, xp[0], xp[1], false);
      if (!s.integrated) return false;
      jacobian.col(j) = (Eigen::Vector2d(s.residual, s.depth - depth) - r) / h;
    }
    have_jacobian_ = jacobian.allFinite() && std::abs(jacobian.determinant()) > 0.0;
    if (have_jacobian_) lu_.compute(jacobian);
    return have_jacobian_;
  }

  const ForceSolver<Law>& solver_;
  double tol_;
  Eigen::PartialPivLU<Eigen::Matrix2d> lu_;
  bool have_jacobian_ = false;
};

}  // namespace puncture::detail
