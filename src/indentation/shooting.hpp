#pragma once
// Equilibrium of the indented membrane at a prescribed normalised force: the shooting of
// docs/model.md ("Solving at a given force"), for any indenter.  The contact model (Contact, see
// contact/contact_model.hpp) says where Part I starts for a shooting parameter and solves the
// parts in contact; the shooting integrates Part I to the clamp and finds the parameter that
// meets the clamp condition lambda2(A) = 1.
#include <fmt/format.h>

#include <limits>
#include <optional>

#include "indentation/contact/contact_model.hpp"
#include "indentation/depth_newton.hpp"
#include "indentation/free_part.hpp"
#include "numerics/shooting.hpp"

namespace puncture::detail {

template <class Contact>
class IndentationShooting {
 public:
  using Law = typename Contact::law_type;

  // `record_unloaded`: whether the state at zero force samples the flat membrane (the loaded
  // states always sample Part I; Equilibrium fields are made from the samples on request).
  IndentationShooting(const Law& law, const ShootingSettings& settings,
                      const typename Contact::Settings& contact, bool record_unloaded = true)
      : part_one_(law, settings), contact_(part_one_, contact), record_unloaded_(record_unloaded) {}
  // The contact model refers to part_one_.
  IndentationShooting(const IndentationShooting&) = delete;
  IndentationShooting& operator=(const IndentationShooting&) = delete;

  const Contact& contact() const { return contact_; }
  const ShootingSettings& settings() const { return part_one_.settings(); }
  double parameter_floor(Configuration configuration) const {
    return contact_.parameter_floor(configuration);
  }

  // The equilibrium at force f in `stage` (the contact model picks the configuration).
  ScaledSolution solve(Stage stage, double f) const {
    if (f == 0.0) return contact_.unloaded(record_unloaded_);
    ScaledSolution sol;
    sol.f = f;
    int evals = 0;
    auto counted = [&](Configuration c, double p) {
      ++evals;
      return residual(c, f, p);
    };
    const ShootingPlan plan = contact_.plan(stage, f, counted);
    sol.configuration = plan.configuration;
    if (!plan.ok()) {
      sol.status = plan.status;
      sol.message = plan.message;
      return sol;
    }
    const auto root = shoot_increasing([&](double p) { return counted(plan.configuration, p); },
                                       plan.lo,
                                       plan.g_lo,
                                       plan.cap,
                                       settings().max_iterations,
                                       plan.initial_step);
    if (!root) {
      sol.message = plan.no_root_message;
      sol.evaluations = evals;
      return sol;
    }
    sol = assemble(plan.configuration, f, *root, true);
    sol.evaluations += evals;
    accept_collapsed_bracket(sol);
    return sol;
  }

  // The state of `configuration` at force f and parameter p, integrated once.  Its residual is
  // zero only at an equilibrium; status is Converged when it is within the shooting tolerance.
  // With `record`, Part I (and the parts in contact) are sampled.
  ScaledSolution assemble(Configuration c, double f, double p, bool record) const {
    ScaledSolution sol;
    sol.f = f;
    sol.parameter = p;
    sol.configuration = c;
    sol.evaluations = 1;
    const auto st = contact_.free_start(c, f, p);
    if (!st) {
      sol.status = Status::BeyondLocking;
      sol.message = "the shooting parameter is outside the material's domain";
      return sol;
    }
    const auto run = part_one_.run(f, *st, record ? &sol.part_one : nullptr);
    if (!run.ok) {
      sol.message = run.turned_back ? "Part I turns back towards the axis before the clamp"
                                    : "Part I cannot be integrated to the clamp (material locks)";
      return sol;
    }
    sol.residual = run.residual;
    sol.r_top = st->r0;
    sol.corner_slope = st->slope;
    sol.tension_ratio = st->ratio;
    sol.edge_s1 = membrane_stress(part_one_.law(), st->state[1], st->state[2]).s1;
    sol.max_i1 = run.max_i1;
    sol.max_i1_r = run.max_i1_r;
    sol.max_i1_radius = run.max_i1_radius;
    sol.depth = run.height;
    if (!contact_.attach(c, *st, p, record, sol)) return sol;
    sol.integrated = true;
    sol.shooting_tol = settings().shooting_tol;
    sol.status = std::abs(sol.residual) <= settings().shooting_tol ? Status::Converged
                                                                   : Status::NoConvergence;
    if (!sol.ok())
      sol.message = fmt::format("the shooting stalled at clamp residual {:.3g}", sol.residual);
    return sol;
  }

  // Clamp residual of a configuration's Part I at (f, p); empty outside the material's domain.
  std::optional<double> residual(Configuration c, double f, double p) const {
    return part_one_.residual(f, contact_.free_start(c, f, p));
  }

  // From a state shallower than d (the force bracket's end), the state at depth d followed in
  // depth control: Newton on (force, shooting parameter) with the clamp and depth residuals
  // (DepthNewton) at depths stepped towards d, each started from the linear extrapolation of the
  // last two states; a failed step is halved.  Well posed through a fold of the force, where the
  // force search is not.  Empty when the states end (or change configuration) before d.
  // `from` becomes the deepest state reached.
  std::optional<ScaledSolution> continue_in_depth(ScaledSolution& from, double d) const {
    DepthNewton<IndentationShooting> newton(*this, settings().shooting_tol);
    ScaledSolution last = from;
    std::optional<ScaledSolution> before;
    // Steps relative to the depth reached (a local continuation), growing while Newton
    // converges; a step below 1e-4 of the depth that still fails ends the states here.
    double step = std::min(d - from.depth, kFirstDepthStep * from.depth);
    int failures = 0;  // failed steps cost the most (integrations beyond the states' end)
    for (int k = 0; k < kMaxDepthSteps && last.depth < d * (1.0 - kDepthMatch); ++k) {
      const double target = std::min(d, last.depth + step);
      double f = last.f, p = last.parameter;
      if (before && last.depth > before->depth) {
        const double t = (target - last.depth) / (last.depth - before->depth);
        const double f_next = last.f + t * (last.f - before->f);
        const double p_next = last.parameter + t * (last.parameter - before->parameter);
        if (f_next > 0.0 && p_next > parameter_floor(last.configuration)) {
          f = f_next;
          p = p_next;
        }
      }
      auto next = newton.solve(last.configuration, target, f, p);
      if (!next) {
        newton.reset();
        step *= 0.5;
        if (step < kSmallestDepthStep * last.depth || ++failures > kMaxDepthFailures)
          return std::nullopt;
        continue;
      }
      before = std::move(last);
      last = std::move(*next);
      from = last;
      step *= 1.5;
    }
    if (!(std::abs(last.depth - d) <= kDepthMatch * d)) return std::nullopt;
    ScaledSolution out = assemble(last.configuration, last.f, last.parameter, true);
    if (!out.ok()) return std::nullopt;
    return out;
  }
  static constexpr int kMaxDepthSteps = 100;
  static constexpr int kMaxDepthFailures = 10;
  static constexpr double kFirstDepthStep = 0.05;
  static constexpr double kSmallestDepthStep = 1e-4;

  // A depth within this relative distance of the requested one is a root of the depth search.
  static constexpr double kDepthMatch = 1e-5;

  // The equilibrium at normalised depth d in `stage`: the force bracketed from zero (a search
  // over solve(); the loading curve uses the faster DepthNewton and falls back on this).
  ScaledSolution solve_at_depth(Stage stage, double d, double f_guess = 0.0) const {
    if (d == 0.0) return solve(stage, 0.0);
    ScaledSolution last_failure;
    std::optional<ScaledSolution> deepest;  // the deepest state short of d the search met
    auto keep_if_deepest = [&](const ScaledSolution& sol) {
      if (sol.ok() && sol.depth < d && (!deepest || sol.depth > deepest->depth)) deepest = sol;
    };
    auto residual = [&](double f) -> std::optional<double> {
      auto sol = solve(stage, f);
      if (!sol.ok()) {
        last_failure = std::move(sol);
        return std::nullopt;
      }
      keep_if_deepest(sol);
      return sol.depth - d;
    };
    const double step = f_guess > 0.0 ? 0.5 * f_guess : 0.1;
    const auto f = shoot_increasing(residual,
                                    0.0,
                                    -d,
                                    std::numeric_limits<double>::infinity(),
                                    settings().max_iterations,
                                    step);
    // The bracket closes either on a root or, when the depth lies beyond every equilibrium of
    // the stage, on the largest force the stage carries (where the residual jumps from the
    // deepest state's to the failure's stand-in).  At a root the depth matches to the
    // shooting's noise (up to ~2e-6 relative at micrometre depths, where the depth goes as the
    // cube root of the force); at the end of the solutions it falls short by the unreachable rest.
    if (f) {
      ScaledSolution sol = solve(stage, *f);
      if (sol.ok() && std::abs(sol.depth - d) <= kDepthMatch * d) return sol;
      keep_if_deepest(sol);
    }
    // Near a limit load the depth grows much faster than the force, so the force search may
    // stop short of the depth although states exist beyond: follow them in depth control.
    // Only where the states may go on: not past locking (the depth is bounded there while the
    // force is not) nor into a configuration the model does not cover.
    const bool may_go_on = last_failure.status == Status::Converged ||
                           last_failure.status == Status::NoConvergence ||
                           last_failure.status == Status::LimitLoad;
    if (deepest && may_go_on)
      if (auto reached = continue_in_depth(*deepest, d)) return *reached;
    if (!deepest) {
      if (last_failure.status == Status::Converged) last_failure.status = Status::NoConvergence;
      last_failure.message = last_failure.message.empty()
                                 ? "no force gives the requested depth"
                                 : "the requested depth cannot be reached: " + last_failure.message;
      return last_failure;
    }
    ScaledSolution out = std::move(*deepest);
    // Why the states end: the failure beyond them, unless that was the solver's own.
    const bool explained = last_failure.status != Status::Converged &&
                           failure_kind(last_failure.status) != FailureKind::Numerical;
    out.status = explained ? last_failure.status : Status::NoConvergence;
    out.message = explained ? last_failure.message
                            : "neither the force search nor depth control reaches it: " +
                                  last_failure.message;
    out.deepest_state = true;
    return out;
  }

 private:
  FreePart<Law> part_one_;
  Contact contact_;
  bool record_unloaded_;
};

}  // namespace puncture::detail
