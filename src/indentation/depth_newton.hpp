#pragma once
// Equilibrium at a prescribed depth in a known configuration: Newton's method on the pair
// (log f, log(p - p0)) of the force and the shooting parameter above its floor p0
// (the contact model's parameter_floor; near zero load both f and p - 1 vanish as powers of the
// depth, so relative steps suit them), with residuals (clamp condition, depth), one integration per
// iteration.  The Jacobian is taken by finite differences, then kept up to date by Broyden's
// update from iteration to iteration and from point to point along a loading curve, and taken
// afresh only when a step shrinks the residual by less than a fifth: a point started from a good
// extrapolation of the previous ones costs two or three integrations.  Used for speed only: any
// failure falls back to the bracketing solver (IndentationShooting::solve_at_depth).
#include <Eigen/Dense>
#include <cmath>
#include <optional>

#include "indentation/scaled_solution.hpp"

namespace puncture::detail {

// The unknowns besides the shooting parameter p: the force f, or the contact model's own
// quantity q > p (IndentationShooting::assemble_at_contact; the flat punch's Part III stretch
// with Part II), Newton then on (log(q - p), log(p - p0)).  Near a limit load the depth runs
// away from the force (~1e-9 of it moves the depth by 1e-1) but not from q.
enum class DepthControl { Force, Contact };

// A state's unknown beside p under `control`: its force or its Part III stretch.
inline double depth_unknown(DepthControl control, const ScaledSolution& s) {
  return control == DepthControl::Force ? s.f : s.part_three_stretch;
}

// Shooting: an IndentationShooting (its assemble(), assemble_at_contact() and parameter_floor()).
template <class Shooting>
class DepthNewton {
 public:
  // With `record`, every state is integrated with its fields sampled (between the same steps:
  // the same state).
  DepthNewton(const Shooting& solver, double residual_tol, bool record = false,
              DepthControl control = DepthControl::Force)
      : solver_(solver), tol_(residual_tol), record_(record), control_(control) {}

  // Forget the Jacobian (a new configuration starts).
  void reset() { have_jacobian_ = false; }

  // The iterations skip the search for the largest I1 between the steps (IndentationShooting::
  // assemble's `maxima`, about half of an evaluation); the state found is assembled again with
  // it when `reassemble` (the same integration: the same state), else the caller does so.
  // (Under contact control the states always carry their maxima.)
  void without_maxima(bool reassemble) {
    maxima_ = false;
    reassemble_ = reassemble;
  }

  // From (f, p), or (q, p) under contact control.
  std::optional<ScaledSolution> solve(Configuration c, double depth, double f_or_q, double p) {
    floor_ = solver_.parameter_floor(c);
    evaluations_ = 0;
    Eigen::Vector2d x(std::log(control_ == DepthControl::Force ? f_or_q : f_or_q - p),
                      std::log(p - floor_));
    if (!x.allFinite()) return std::nullopt;
    auto value = [&](const ScaledSolution& s) {
      return Eigen::Vector2d(s.residual, s.depth - depth);
    };
    // The clamp residual is a hoop stretch minus 1: near zero load, where every stretch minus 1
    // is ~ p - p0, it is judged relative to that scale so the force stays accurate relatively.
    auto converged = [&](const Eigen::Vector2d& r) {
      const double stretch_scale = std::min(1.0, std::exp(x[1]));
      return std::abs(r[0]) <= tol_ * stretch_scale &&
             std::abs(r[1]) <= tol_ * std::max(depth, 1e-3);
    };
    ScaledSolution sol = evaluate(c, x);
    if (!sol.integrated) return std::nullopt;
    Eigen::Vector2d r = value(sol);
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
      if (converged(r)) return accepted(std::move(sol));
      if (!have_jacobian_) {
        if (!finite_difference_jacobian(c, x, r, depth)) return std::nullopt;
      }
      const Eigen::Vector2d step = -lu_.solve(r);
      if (!step.allFinite()) return std::nullopt;
      // Backtrack when the full step leaves the material's domain or the configuration.
      double scale = 1.0;
      ScaledSolution next;
      for (int halving = 0; halving < 6; ++halving, scale *= 0.5) {
        next = evaluate(c, x + scale * step);
        if (next.integrated) break;
      }
      if (!next.integrated) return std::nullopt;
      const Eigen::Vector2d r_next = value(next);
      // Broyden's update keeps the Jacobian in step along the iterations and the curve at no
      // cost; a step that shrinks the residual by less than a fifth means it is too stale (or the
      // curvature strong): a fresh one is taken where we now are.
      const Eigen::Vector2d dx = scale * step;
      jacobian_ += (r_next - r - jacobian_ * dx) * dx.transpose() / dx.squaredNorm();
      if (r_next.cwiseAbs().maxCoeff() > kRefreshContraction * r.cwiseAbs().maxCoeff() ||
          !jacobian_.allFinite() || !(std::abs(jacobian_.determinant()) > 0.0))
        have_jacobian_ = false;
      else
        lu_.compute(jacobian_);
      x += scale * step;
      r = r_next;
      sol = std::move(next);
    }
    if (converged(r)) return accepted(std::move(sol));
    have_jacobian_ = false;
    return std::nullopt;
  }

 private:
  static constexpr int kMaxIterations = 10;
  static constexpr double kLogStep = 1e-5;
  static constexpr double kRefreshContraction = 0.8;

  bool finite_difference_jacobian(Configuration c, const Eigen::Vector2d& x,
                                  const Eigen::Vector2d& r, double depth) {
    // Forward differences with steps of 1e-5 in the logs: truncation ~1e-5 relative, and the
    // integration's noise (~1e-12 absolute) stays small against the change it makes in the
    // residuals even near zero load, where they are ~1e-5 of their own size.
    Eigen::Matrix2d& jacobian = jacobian_;
    for (int j = 0; j < 2; ++j) {
      Eigen::Vector2d xp = x;
      const double h = kLogStep;
      xp[j] += h;
      const auto s = evaluate(c, xp);
      if (!s.integrated) return false;
      jacobian.col(j) = (Eigen::Vector2d(s.residual, s.depth - depth) - r) / h;
    }
    have_jacobian_ = jacobian.allFinite() && std::abs(jacobian.determinant()) > 0.0;
    if (have_jacobian_) lu_.compute(jacobian);
    return have_jacobian_;
  }

  // The solution passed Newton's test on both residuals (its own tolerance).
  ScaledSolution accepted(ScaledSolution sol) {
    if (!maxima_ && reassemble_ && control_ == DepthControl::Force) {
      ++evaluations_;
      sol = solver_.assemble(sol.configuration, sol.f, sol.parameter, record_);
    }
    sol.status = Status::Converged;
    sol.message.clear();
    sol.evaluations = evaluations_;
    return sol;
  }

  ScaledSolution evaluate(Configuration c, const Eigen::Vector2d& x) {
    ++evaluations_;
    const double p = floor_ + std::exp(x[1]);
    return control_ == DepthControl::Force
               ? solver_.assemble(c, std::exp(x[0]), p, record_ && maxima_, maxima_)
               : solver_.assemble_at_contact(c, p + std::exp(x[0]), p, record_);
  }

  const Shooting& solver_;
  double tol_;
  bool record_;
  DepthControl control_;
  double floor_ = 1.0;
  Eigen::Matrix2d jacobian_ = Eigen::Matrix2d::Zero();
  Eigen::PartialPivLU<Eigen::Matrix2d> lu_;
  bool have_jacobian_ = false;
  bool maxima_ = true;
  bool reassemble_ = true;
  int evaluations_ = 0;  // of the current solve
};

}  // namespace puncture::detail
