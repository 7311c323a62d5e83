#pragma once
// Equilibrium at a prescribed depth in a known configuration: Newton's method on the pair
// (log f, log(p - p0)) of the force and the shooting parameter above its floor p0
// (the contact model's parameter_floor; near zero load both f and p - 1 vanish as powers of the
// depth, so relative steps suit them), with residuals (clamp condition, depth) each relative to
// its scale, one integration per iteration.  Relative residuals keep the Jacobian nearly the
// same from point to point along a curve (absolute ones grew with the depth: along the default
// curve a point took 2.4 steps, now 1.9).  The Jacobian is taken by finite differences, then
// kept up to date by Broyden's
// update from iteration to iteration and from point to point along a loading curve, and taken
// afresh only when a step shrinks the residual by less than a fifth: a point started from a good
// extrapolation of the previous ones costs two or three integrations.  Used for speed only: any
// failure falls back to the bracketing solver (IndentationShooting::solve_at_depth).
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <boost/math/tools/toms748_solve.hpp>
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
  void reset() {
    have_jacobian_ = false;
    kept_ = 0;
  }

  // Along a curve of equally spaced depths, each solve starts from the Jacobian extrapolated
  // linearly in the depth from those the last two solves ended with.  On the sphere-tipped probe
  // the pair is ill-conditioned (det J ~ 3 % of its terms' products): the Jacobian drifts by
  // ~1 % a point, Broyden's carried one left steps contracting by only ~0.3, and a point took
  // ~5 evaluations on the hemisphere; extrapolated, ~4 (bench/README.md).  Only the start of
  // Newton changes, not what it accepts.
  void extrapolated_jacobian() { extrapolate_ = true; }

  // A solve whose start's residuals exceed kValleyResidual first brings the clamp residual to
  // kValleyClamp by the parameter alone, at the start's force (valley_start_search), and takes
  // Newton's Jacobian there.  On the sphere-tipped probe near zero load the pair is so
  // ill-conditioned (det J ~ 0.2 % of its terms' products at the curve's second point) that
  // a start 1 % off in p - 1 lies outside Newton's basin (its first step went 60 % too far in
  // f), while the states with the clamp condition met form a valley along which it converges:
  // the curve's second and third points took 114 and 99 marches of the cap through the
  // fallback's force searches, now 24 and 13 (bench/README.md).
  void valley_start() { valley_ = true; }

  // The iterations skip the search for the largest I1 between the steps (IndentationShooting::
  // assemble's `maxima`, about half of an evaluation); the state found is assembled again with
  // it when `reassemble` (the same integration: the same state), else the caller does so.
  // With `reassemble`, a step expected to converge (search_next) searches at once, which spares
  // that second assembly when it does: along the default curve 283 searches (half an
  // evaluation each) replace 196 of 199 assemblies (one and a half), 14 % of the curve's time.
  // (Under contact control the states always carry their maxima.)
  void without_maxima(bool reassemble) {
    maxima_ = false;
    reassemble_ = reassemble;
  }

  // For the loading curve's points (follow_curve, through newton_at_depth): a solve whose steps
  // stall at the evaluations' own noise returns its best state if that is within
  // `noise_tolerance` (relative residuals, as the tolerance).  Near zero load on a smooth probe
  // the residuals carry rounding noise of ~1e-8 (the pole strain ~3e-4 held in stretches near 1,
  // bench/README.md): Newton cannot meet 1e-9 there, and the force search it fell back on ended
  // on that noise too, at the cost of hundreds of solves.
  void guarded(double noise_tolerance) {
    guarded_ = true;
    noise_tol_ = noise_tolerance;
  }

  // From (f, p), or (q, p) under contact control.
  std::optional<ScaledSolution> solve(Configuration c, double depth, double f_or_q, double p) {
    floor_ = solver_.parameter_floor(c);
    evaluations_ = 0;
    Eigen::Vector2d x(std::log(control_ == DepthControl::Force ? f_or_q : f_or_q - p),
                      std::log(p - floor_));
    if (!x.allFinite()) return std::nullopt;
    // The clamp residual is a hoop stretch minus 1: near zero load, where every stretch minus 1
    // is ~ p - p0, it is judged relative to that scale so the force stays accurate relatively;
    // the depth residual relative to the depth.
    scales_ = Eigen::Vector2d(std::min(1.0, std::exp(x[1])), std::max(depth, 1e-3));
    depth_ = depth;
    auto converged = [&](const Eigen::Vector2d& r) { return r.cwiseAbs().maxCoeff() <= tol_; };
    ScaledSolution sol = evaluate(c, x, false);
    bool sol_has_maxima = maxima_;
    if (!sol.integrated) return std::nullopt;
    Eigen::Vector2d r = value(sol);
    if (extrapolate_ && have_jacobian_) extrapolate_jacobian(c, depth);
    if (valley_ && r.cwiseAbs().maxCoeff() > kValleyResidual && !valley_start_search(c, x, sol, r))
      return std::nullopt;
    // Guarded: the state with the smallest residual so far, and the steps that met only noise.
    std::optional<ScaledSolution> best;
    double best_residual = 0.0;
    bool best_has_maxima = false;
    int noise_steps = 0;
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
      if (converged(r)) return accepted(std::move(sol), sol_has_maxima, iteration);
      if (guarded_ && (!best || r.cwiseAbs().maxCoeff() < best_residual)) {
        best = sol;
        best_residual = r.cwiseAbs().maxCoeff();
        best_has_maxima = sol_has_maxima;
      }
      if (!have_jacobian_) {
        if (!finite_difference_jacobian(c, x, r)) return std::nullopt;
      }
      const Eigen::Vector2d step = -lu_.solve(r);
      if (!step.allFinite()) return std::nullopt;
      // Backtrack when the full step leaves the material's domain or the configuration.
      double scale = 1.0;
      ScaledSolution next;
      const bool search = search_next(iteration, r);
      for (int halving = 0; halving < 6; ++halving, scale *= 0.5) {
        next = evaluate(c, x + scale * step, search && halving == 0);
        if (next.integrated) break;
      }
      if (!next.integrated) return std::nullopt;
      const Eigen::Vector2d r_next = value(next);
      sol_has_maxima = maxima_ || (search && scale == 1.0);
      contraction_ = r_next.cwiseAbs().maxCoeff() / r.cwiseAbs().maxCoeff();
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
      // Guarded: a step from residuals already within the noise tolerance that does not halve
      // them met the evaluations' noise (Newton's steps contract by ~1e-2 to 1e-1 there).
      if (guarded_ && r.cwiseAbs().maxCoeff() <= noise_tol_ && contraction_ > 0.5) ++noise_steps;
      x += dx;
      r = r_next;
      sol = std::move(next);
    }
    if (converged(r)) return accepted(std::move(sol), sol_has_maxima, kMaxIterations);
    if (guarded_ && r.cwiseAbs().maxCoeff() < best_residual) {
      best = std::move(sol);
      best_residual = r.cwiseAbs().maxCoeff();
      best_has_maxima = sol_has_maxima;
    }
    have_jacobian_ = false;
    if (noise_steps >= kNoiseSteps && best && best_residual <= noise_tol_)
      return accepted(std::move(*best), best_has_maxima, kMaxIterations);
    return std::nullopt;
  }

 private:
  static constexpr int kMaxIterations = 10;
  static constexpr double kValleyResidual = 1e-3;
  static constexpr double kValleyClamp = 1e-4;
  static constexpr int kValleySteps = 12;

  // valley_start(): from x (state sol, residuals r), secant steps in log(p - p0) alone on the
  // clamp residual until it changes sign, then TOMS 748 on that bracket, until |clamp| <=
  // kValleyClamp; x, sol and r become that state's, and the Jacobian is taken afresh there.
  // False when a state fails to integrate or no bracket is found in kValleySteps.
  bool valley_start_search(Configuration c, Eigen::Vector2d& x, ScaledSolution& sol,
                           Eigen::Vector2d& r) {
    struct Trial {
      double x1;
      Eigen::Vector2d r;
      ScaledSolution state;
    };
    bool failed = false;
    const auto at = [&](double x1) {
      Trial t{x1, Eigen::Vector2d::Zero(), {}};
      Eigen::Vector2d xn = x;
      xn[1] = x1;
      t.state = evaluate(c, xn, false);
      if (t.state.integrated)
        t.r = value(t.state);
      else
        failed = true;
      return t;
    };
    Trial lo{x[1], r, sol};
    Trial probe = at(x[1] + kLogStep);
    if (failed) return false;
    double slope = (probe.r[0] - lo.r[0]) / kLogStep;
    std::optional<Trial> hi;
    Trial best = lo;
    auto keep_best = [&](const Trial& t) {
      if (std::abs(t.r[0]) < std::abs(best.r[0])) best = t;
    };
    for (int k = 0; k < kValleySteps && !hi && std::abs(best.r[0]) > kValleyClamp; ++k) {
      if (!(slope != 0.0) || !std::isfinite(slope)) return false;
      Trial next = at(lo.x1 - lo.r[0] / slope);
      if (failed) return false;
      keep_best(next);
      if ((next.r[0] > 0.0) != (lo.r[0] > 0.0)) {
        hi = std::move(next);
      } else {
        slope = (next.r[0] - lo.r[0]) / (next.x1 - lo.x1);
        lo = std::move(next);
      }
    }
    if (hi && std::abs(best.r[0]) > kValleyClamp) {
      std::uintmax_t iterations = kValleySteps;
      const bool lo_first = lo.x1 < hi->x1;
      const Trial& left = lo_first ? lo : *hi;
      const Trial& right = lo_first ? *hi : lo;
      boost::math::tools::toms748_solve(
          [&](double x1) {
            Trial t = at(x1);
            if (failed) return 0.0;  // ends the search: failed is tested below
            keep_best(t);
            return t.r[0];
          },
          left.x1,
          right.x1,
          left.r[0],
          right.r[0],
          [&](double, double) { return failed || std::abs(best.r[0]) <= kValleyClamp; },
          iterations);
      if (failed) return false;
    }
    if (!(std::abs(best.r[0]) <= kValleyClamp)) return false;
    x[1] = best.x1;
    r = best.r;
    sol = std::move(best.state);
    have_jacobian_ = false;
    return true;
  }
  static constexpr double kLogStep = 1e-5;
  static constexpr double kRefreshContraction = 0.8;
  static constexpr int kNoiseSteps = 3;  // guarded: steps that met only noise, for its best state
  // extrapolated_jacobian(): the next depth at most this many spacings on.
  static constexpr double kMaxExtrapolation = 2.0;

  bool finite_difference_jacobian(Configuration c, const Eigen::Vector2d& x,
                                  const Eigen::Vector2d& r) {
    // Forward differences with steps of 1e-5 in the logs: truncation ~1e-5 relative, and the
    // integration's noise (~1e-12 absolute) stays small against the change it makes in the
    // residuals even near zero load, where they are ~1e-5 of their own size.
    Eigen::Matrix2d& jacobian = jacobian_;
    for (int j = 0; j < 2; ++j) {
      Eigen::Vector2d xp = x;
      const double h = kLogStep;
      xp[j] += h;
      const auto s = evaluate(c, xp, false);
      if (!s.integrated) return false;
      jacobian.col(j) = (value(s) - r) / h;
    }
    have_jacobian_ = jacobian.allFinite() && std::abs(jacobian.determinant()) > 0.0;
    if (have_jacobian_) lu_.compute(jacobian);
    return have_jacobian_;
  }

  // Whether the step after `iteration` (from the residual `r`) should search for the largest
  // I1: only when the found state would otherwise be assembled again for it, and the step is
  // expected to converge: the previous solve converged after as many steps, or the residual
  // times the last step's contraction is within the tolerance.
  bool search_next(int iteration, const Eigen::Vector2d& r) const {
    if (maxima_ || !reassemble_ || record_ || control_ != DepthControl::Force) return false;
    if (iteration + 1 >= last_steps_) return true;
    return contraction_ * r.cwiseAbs().maxCoeff() <= tol_;
  }

  // The solution passed Newton's test on both residuals (its own tolerance) after `steps`.
  ScaledSolution accepted(ScaledSolution sol, bool has_maxima, int steps) {
    last_steps_ = steps;
    if (extrapolate_) keep_jacobian(sol.configuration);
    if (!has_maxima && reassemble_ && control_ == DepthControl::Force) {
      ++evaluations_;
      sol = solver_.assemble(sol.configuration, sol.f, sol.parameter, record_);
    }
    accept_state(sol);
    sol.evaluations = evaluations_;
    return sol;
  }

  // The Jacobian this solve ends with, and the last one before it, for the next solve's start.
  void keep_jacobian(Configuration c) {
    if (!have_jacobian_ || (kept_ > 0 && kept_configuration_ != c)) kept_ = 0;
    if (!have_jacobian_) return;
    kept_jacobian_[1] = kept_jacobian_[0];
    kept_depth_[1] = kept_depth_[0];
    kept_jacobian_[0] = jacobian_;
    kept_depth_[0] = depth_;
    kept_configuration_ = c;
    kept_ = std::min(kept_ + 1, 2);
  }
  void extrapolate_jacobian(Configuration c, double depth) {
    if (kept_ < 2 || kept_configuration_ != c || !(kept_depth_[0] != kept_depth_[1])) return;
    const double t = (depth - kept_depth_[0]) / (kept_depth_[0] - kept_depth_[1]);
    if (!(t > 0.0 && t <= kMaxExtrapolation)) return;  // the next depth, not a jump or a return
    const Eigen::Matrix2d j = kept_jacobian_[0] + t * (kept_jacobian_[0] - kept_jacobian_[1]);
    if (!j.allFinite() || !(std::abs(j.determinant()) > 0.0)) return;
    jacobian_ = j;
    lu_.compute(jacobian_);
  }

  // The residuals of a state, each relative to its scale (solve()).
  Eigen::Vector2d value(const ScaledSolution& s) const {
    return Eigen::Vector2d(s.residual, s.depth - depth_).cwiseQuotient(scales_);
  }

  // With `search`, the largest I1 is searched even when the iterations skip it.
  ScaledSolution evaluate(Configuration c, const Eigen::Vector2d& x, bool search) {
    ++evaluations_;
    const double p = floor_ + std::exp(x[1]);
    return control_ == DepthControl::Force
               ? solver_.assemble(c, std::exp(x[0]), p, record_ && maxima_, maxima_ || search)
               : solver_.assemble_at_contact(c, p + std::exp(x[0]), p, record_);
  }

  const Shooting& solver_;
  double tol_;
  bool record_;
  DepthControl control_;
  double floor_ = 1.0;
  double depth_ = 0.0;                                // the prescribed depth
  Eigen::Vector2d scales_ = Eigen::Vector2d::Ones();  // of the residuals
  Eigen::Matrix2d jacobian_ = Eigen::Matrix2d::Zero();
  Eigen::PartialPivLU<Eigen::Matrix2d> lu_;
  bool have_jacobian_ = false;
  bool maxima_ = true;
  bool reassemble_ = true;
  bool guarded_ = false;    // guarded(): a state at the evaluations' noise may be accepted
  double noise_tol_ = 0.0;  // guarded(): the largest residual of a noise-limited state
  // Residual after / before the last step: Broyden's steps contract by ~1e-2 to 1e-1.
  double contraction_ = 0.1;
  // Steps the last solve took: along a curve the points converge after about as many.
  int last_steps_ = kMaxIterations;
  int evaluations_ = 0;       // of the current solve
  bool extrapolate_ = false;  // extrapolated_jacobian()
  bool valley_ = false;       // valley_start()
  // The Jacobians the last two solves ended with (the last first), their depths, configuration.
  std::array<Eigen::Matrix2d, 2> kept_jacobian_;
  std::array<double, 2> kept_depth_{0.0, 0.0};
  Configuration kept_configuration_ = Configuration::Unloaded;
  int kept_ = 0;
};

}  // namespace puncture::detail
