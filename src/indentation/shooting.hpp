#pragma once
// Equilibrium of the indented membrane at a prescribed normalised force: the shooting of
// docs/model.md ("Solving at a given force"), for any indenter.  The contact model (Contact, see
// contact/contact_model.hpp) says where Part I starts for a shooting parameter and solves the
// parts in contact; the shooting integrates Part I to the clamp and finds the parameter that
// meets the clamp condition lambda2(A) = 1.
#include <fmt/format.h>

#include <limits>
#include <optional>
#include <utility>

#include "indentation/contact/contact_model.hpp"
#include "indentation/depth_newton.hpp"
#include "indentation/depth_path_puncture.hpp"
#include "indentation/free_part.hpp"
#include "numerics/root_above_branch.hpp"
#include "numerics/shooting.hpp"

namespace puncture::detail {

template <class Contact>
class IndentationShooting {
 public:
  using Law = typename Contact::law_type;

  // `record_unloaded`: whether the state at zero force samples the flat membrane (the loaded
  // states always sample Part I; Equilibrium fields are made from the samples on request).
  // `dome`: under a gas pressure, the inflated membrane before contact (the state at zero
  // force; inflated_dome in indentation/inflated_dome.hpp), instead of the contact's flat one.
  IndentationShooting(const Law& law, const ShootingSettings& settings,
                      const typename Contact::Settings& contact, bool record_unloaded = true,
                      std::optional<ScaledSolution> dome = std::nullopt)
      : part_one_(law, settings),
        coarse_part_one_(law, coarse(settings)),
        contact_(part_one_, contact),
        record_unloaded_(record_unloaded),
        dome_(std::move(dome)) {}
  // The contact model refers to part_one_.
  IndentationShooting(const IndentationShooting&) = delete;
  IndentationShooting& operator=(const IndentationShooting&) = delete;

  const Contact& contact() const { return contact_; }
  const ShootingSettings& settings() const { return part_one_.settings(); }
  double parameter_floor(Configuration configuration) const {
    return contact_.parameter_floor(configuration);
  }

  // The equilibrium at force f in `stage` (the contact model picks the configuration); without
  // `record` its fields are not sampled.  `rough`: the root of the coarse integration alone,
  // integrated finely once (its clamp residual ~1e-7, so usually judged not converged), for the
  // steps of a search that polishes its own end.
  ScaledSolution solve(Stage stage, double f, bool record = true, bool rough = false) const {
    if (f == 0.0) return dome_ ? *dome_ : contact_.unloaded(record_unloaded_);
    ScaledSolution sol;
    sol.f = f;
    if (settings().dome_later_state) {
      sol.configuration = contact_.configuration(stage, false);
      sol.status = Status::OutsideModel;
      sol.message = kLaterStateByForce;
      return sol;
    }
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
    auto fine = [&](double p) { return counted(plan.configuration, p); };
    std::optional<double> root = coarse_then_fine(plan, f, fine, evals, rough);
    if (!root && plan.branch_below) root = above_branch(plan, f, fine);
    if (!root)
      root = shoot_increasing(fine,
                              plan.lo,
                              plan.g_lo,
                              plan.cap,
                              settings().max_iterations,
                              plan.initial_step,
                              {good_enough(f), plan.g_cap});
    // The bracket's low end may meet the clamp condition already: the held membrane within
    // ~1e-14 of its branch's end (leaving the edge vertically), where the root t ~ 1e-18 lies
    // so close to 0 that a tolerance relative to it takes TOMS 748 past its iteration limit.
    if (!root && std::abs(plan.g_lo) <= settings().shooting_tol) root = plan.lo;
    if (!root) {
      sol.message = plan.no_root_message;
      sol.evaluations = evals;
      return sol;
    }
    sol = assemble(plan.configuration, f, *root, record);
    sol.evaluations += evals;
    accept_collapsed_bracket(sol);
    if (!sol.ok() && sol.integrated && locks(sol)) {
      sol.status = Status::BeyondLocking;
      sol.message = fmt::format(
          "the force is what the membrane carries as the material locks (the largest I1, {:.10g}, "
          "is within {:g} of its locking value, where the clamp condition cannot be resolved)",
          sol.max_i1,
          kLockingMargin);
    }
    return sol;
  }

  // The state of `configuration` at force f and parameter p, integrated once.  Its residual is
  // zero only at an equilibrium; status is Converged when it is within the shooting tolerance.
  // With `record`, Part I (and the parts in contact) are sampled.
  // Without `maxima` the largest I1 is not searched between the steps of Part I (nor of the
  // parts in contact, where the contact model offers that): sol.max_i1 is then a lower bound,
  // for the iterations of a search that assembles its end again.
  ScaledSolution assemble(Configuration c, double f, double p, bool record,
                          bool maxima = true) const {
    ScaledSolution sol;
    sol.f = f;
    sol.parameter = p;
    sol.configuration = c;
    sol.evaluations = 1;
    const auto st = contact_.free_start(c, f, p);
    if (!st) return outside_domain(std::move(sol));
    if (!run_free_part(*st, record, sol, maxima)) return sol;
    bool attached;
    if constexpr (requires { contact_.attach(c, *st, p, record, sol, maxima); })
      attached = contact_.attach(c, *st, p, record, sol, maxima);
    else
      attached = contact_.attach(c, *st, p, record, sol);
    if (!attached) return sol;
    return judged(std::move(sol));
  }

  // The state of `c` given by the contact model's own pair (q, p), its force an output
  // (Contact::contact_start: the flat punch's Part III stretch and top stretch with Part II),
  // integrated once; depth control near a limit load, where the force is ill-suited.
  ScaledSolution assemble_at_contact(Configuration c, double q, double p, bool record) const {
    ScaledSolution sol;
    sol.parameter = p;
    sol.configuration = c;
    sol.evaluations = 1;
    std::optional<FreeStart> st;
    if constexpr (requires { contact_.contact_start(c, q, p, record, sol); })
      st = contact_.contact_start(c, q, p, record, sol);
    if (!st) return outside_domain(std::move(sol));
    // The contact's parts are set: Part I adds its height and may hold the largest I1.
    const double contact_depth = sol.depth, edge_s1 = sol.edge_s1, ratio = sol.tension_ratio;
    const double i1 = sol.max_i1, i1_r = sol.max_i1_r, i1_radius = sol.max_i1_radius;
    if (!run_free_part(*st, record, sol)) return sol;
    sol.depth += contact_depth;
    sol.edge_s1 = edge_s1;
    sol.tension_ratio = ratio;
    if (i1 > sol.max_i1) {
      sol.max_i1 = i1;
      sol.max_i1_r = i1_r;
      sol.max_i1_radius = i1_radius;
    }
    return judged(std::move(sol));
  }

  // Clamp residual of a configuration's Part I at (f, p); empty outside the material's domain.
  std::optional<double> residual(Configuration c, double f, double p) const {
    return part_one_.residual(f, contact_.free_start(c, f, p));
  }
  // Clamp residual of Part I from `start` on the coarse integration (a contact model's own
  // searches use it as the shooting does).
  std::optional<double> coarse_free_residual(double f, const FreeStart& start) const {
    return coarse_part_one_.residual(f, start);
  }
  const IntegrationSettings& coarse_integration() const {
    return coarse_part_one_.settings().integration;
  }

  // From a state shallower than d (the force bracket's end), the state at depth d followed in
  // depth control: Newton on (force, shooting parameter) with the clamp and depth residuals
  // (DepthNewton) at depths stepped towards d, each started from the linear extrapolation of the
  // last two states; a failed step is halved.  Well posed through a fold of the force, where the
  // force search is not.  Empty when the states end (or change configuration) before d.
  // `from` becomes the deepest state reached.
  std::optional<ScaledSolution> continue_in_depth(ScaledSolution& from, double d) const {
    const DepthControl control = control_of(from.configuration);
    DepthNewton<IndentationShooting> newton(*this, settings().shooting_tol, false, control);
    const auto first = [&](const ScaledSolution& s) { return depth_unknown(control, s); };
    ScaledSolution last = from;
    std::optional<ScaledSolution> before;
    // Steps relative to the depth reached (a local continuation), growing while Newton
    // converges; a step below 1e-4 of the depth that still fails ends the states here.
    double step = std::min(d - from.depth, kFirstDepthStep * from.depth);
    int failures = 0;  // failed steps cost the most (integrations beyond the states' end)
    for (int k = 0; k < kMaxDepthSteps && last.depth < d * (1.0 - kDepthMatch); ++k) {
      const double target = std::min(d, last.depth + step);
      double f = first(last), p = last.parameter;
      if (before && last.depth > before->depth) {
        const double t = (target - last.depth) / (last.depth - before->depth);
        const double f_next = first(last) + t * (first(last) - first(*before));
        const double p_next = last.parameter + t * (last.parameter - before->parameter);
        const bool valid = control == DepthControl::Force ? f_next > 0.0 : f_next > p_next;
        if (valid && p_next > parameter_floor(last.configuration)) {
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
    if (auto out = refine_at_depth(last, d, settings().shooting_tol, true)) return out;
    ScaledSolution out = assemble(last.configuration, last.f, last.parameter, true);
    if (!out.ok()) return std::nullopt;
    return out;
  }

  // Depth control of a configuration: by its contact's own quantity where the contact offers
  // one (DepthControl), else by the force.
  DepthControl control_of(Configuration c) const {
    if constexpr (requires { contact_.contact_controls(c); })
      if (contact_.contact_controls(c)) return DepthControl::Contact;
    return DepthControl::Force;
  }

  // The state at normalised depth d from the state `s` near it, by Newton in depth control to
  // `tol` (clamp residual and relative depth), sampled with `record`; empty if Newton fails.
  // A force search leaves a state within its force's noise of the depth, which near a limit
  // load (the depth running away from the force) is up to ~1e-6 of it.
  std::optional<ScaledSolution> refine_at_depth(const ScaledSolution& s, double d, double tol,
                                                bool record) const {
    const DepthControl control = control_of(s.configuration);
    DepthNewton<IndentationShooting> newton(*this, tol, record, control);
    auto out = newton.solve(s.configuration, d, depth_unknown(control, s), s.parameter);
    if (out) out->evaluations += s.evaluations;
    return out;
  }
  // The shooting at force f takes a parameter whose clamp residual is within 1e-2 of the
  // tolerance as its root (its error then lies far below the integration's), relative to the
  // strains' scale: at small loads they go as f^(2/3) (membrane theory, f ~ depth^3), and a
  // residual of 1e-12 at a strain of 1e-9 would leave the state's depth 1e-3 off.
  double good_enough(double f) const {
    const double strain_scale = std::min(1.0, std::pow(f, 2.0 / 3.0));
    return 1e-2 * settings().shooting_tol * strain_scale;
  }

  static constexpr const char* kLaterStateByForce =
      "a later inflated state beyond a hemisphere is followed in depth control alone, from its "
      "dome (the puncture along the path): the shooting at a force near zero force finds the "
      "first state's branch, so no state is solved at a force or by a force search";

  static constexpr int kMaxDepthSteps = 100;
  static constexpr int kMaxDepthFailures = 10;
  static constexpr double kFirstDepthStep = 0.05;
  static constexpr double kSmallestDepthStep = 1e-4;

  // A depth within this relative distance of the requested one is a root of the depth search.
  static constexpr double kDepthMatch = 1e-5;
  // ... and one further away than this is brought to it in depth control (refine_at_depth).
  static constexpr double kDepthPolish = 1e-9;

  // The equilibrium at normalised depth d in `stage`: by Newton in depth control from a nearby
  // force solve (newton_at_depth), or, where that fails, with the force bracketed from zero (a
  // search over solve(); the loading curve's own DepthNewton falls back on this too).
  // `noise_tol` > 0 (the loading curve's): newton_at_depth may end on a state whose residuals
  // are the evaluations' noise, within noise_tol (DepthNewton::guarded).
  ScaledSolution solve_at_depth(Stage stage, double d, double f_guess = 0.0,
                                double noise_tol = 0.0) const {
    if (d == 0.0) return solve(stage, 0.0);
    if (settings().dome_later_state) {  // no force search there: from the dome in depth control
      if (auto on_branch = dome_branch_at_depth(*this, stage, d)) return std::move(*on_branch);
      ScaledSolution out = solve(stage, 1.0);  // the refusal, with its status and message
      out.message =
          "the requested depth cannot be reached in depth control from the dome: " + out.message;
      return out;
    }
    if (auto fast = newton_at_depth(stage, d, f_guess, noise_tol)) return std::move(*fast);
    ScaledSolution last_failure;
    std::optional<ScaledSolution> deepest;  // the deepest state short of d the search met
    auto keep_if_deepest = [&](const ScaledSolution& sol) {
      if (sol.ok() && sol.depth < d && (!deepest || sol.depth > deepest->depth)) deepest = sol;
    };
    // Past a limit load, with a state short of d in a configuration the contact controls, the
    // force search hands over to depth control from that state: it would bisect towards the
    // limit load, each solve longer than the last, while the depth runs away from the force
    // (1e-9 of it moves the depth by 1e-1); its remaining calls are skipped.  Should depth
    // control end short of d, the force search runs again in full for the deepest state.
    for (const bool may_hand_over : {true, false}) {
      bool handed_over = false;
      auto residual = [&](double f) -> std::optional<double> {
        if (handed_over) return std::nullopt;
        auto sol = solve(stage, f);
        if (!sol.ok()) {
          handed_over = may_hand_over && sol.status == Status::LimitLoad && deepest &&
                        control_of(deepest->configuration) == DepthControl::Contact;
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
      // shooting's noise (up to ~2e-6 relative at micrometre depths, where the depth goes as
      // the cube root of the force; more near a limit load): then it is brought to d.
      if (f && !handed_over) {
        ScaledSolution sol = solve(stage, *f);
        if (sol.ok() && std::abs(sol.depth - d) <= kDepthMatch * d) {
          if (std::abs(sol.depth - d) <= kDepthPolish * d) return sol;
          auto refined = refine_at_depth(sol, d, settings().shooting_tol, true);
          return refined ? *refined : sol;
        }
        keep_if_deepest(sol);
      }
      if (!handed_over) break;
      ScaledSolution from = *deepest;
      if (auto reached = continue_in_depth(from, d)) return *reached;
    }
    // Near a limit load the depth grows much faster than the force, so the force search may
    // stop short of the depth although states exist beyond: follow them in depth control.
    // Only where the states may go on: not past locking (the depth is bounded there while the
    // force is not) nor into a configuration the model does not cover.
    const bool may_go_on = last_failure.status == Status::Converged ||
                           last_failure.status == Status::NoConvergence ||
                           last_failure.status == Status::LimitLoad;
    if (deepest && may_go_on) {
      if (auto reached = continue_in_depth(*deepest, d)) return *reached;
      // Ended by a change of configuration the contact model's search does not find from a
      // small force (the sphere's equator on a dome beyond a hemisphere): from the deepest state.
      if (auto reached = reached_past_change(*this, *deepest, d); reached && reached->ok())
        return *reached;
    }
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
                            : "neither the force search nor depth control reaches it" +
                                  (last_failure.message.empty() ? std::string()
                                                                : ": " + last_failure.message);
    out.deepest_state = true;
    return out;
  }

  // The state at depth d by Newton in depth control (DepthNewton) from a force solve near it.
  // The force is found first by secant steps in (log depth, log force) over rough force solves
  // (solve's `rough`), from f_guess or from f = d^3 (the small-deflection law
  // f = 3 C d^3 / (2 pi) with C ~ 2, the paper's geometry), until the depth is within 5 % of d;
  // Newton starts from that state carried to d by the last local powers of f and p - p0 (near
  // zero load f ~ d^3, p - p0 ~ d^2).  The configuration is confirmed by the contact's plan at
  // the force found.  Empty when a step fails: the force search of solve_at_depth runs then.
  // With `noise_tol` > 0 Newton is guarded (DepthNewton::guarded) and the depth may miss d by
  // that much (relative), the noise it ends on.
  std::optional<ScaledSolution> newton_at_depth(Stage stage, double d, double f_guess,
                                                double noise_tol = 0.0) const {
    ScaledSolution near = solve(stage, f_guess > 0.0 ? f_guess : d * d * d, false, true);
    const auto usable = [](const ScaledSolution& x) {
      return x.integrated && std::abs(x.residual) <= kRoughResidual && x.depth > 0.0;
    };
    int evaluations = near.evaluations;
    std::optional<ScaledSolution> before;
    auto power = [&](double fallback, auto&& of) {
      if (!before || !(before->depth > 0.0) || before->depth == near.depth) return fallback;
      const double k = std::log(of(near) / of(*before)) / std::log(near.depth / before->depth);
      return std::isfinite(k) ? std::clamp(k, 0.5, 8.0) : fallback;
    };
    const auto force = [](const ScaledSolution& x) { return x.f; };
    // Guarded (near zero load on a noisy model) without a gas pressure, the powers are measured:
    // a Newton started
    // with p - p0 ~ d^2 from a state 5 % short of d misses p by ~2 % (the sphere-tipped probe's
    // p - 1 goes as d^1.5) and diverges on that ill-conditioned pair.
    for (int k = 0; k < kNearSolves && usable(near) &&
                    (std::abs(std::log(d / near.depth)) > std::log(kNearEnough) ||
                     (noise_tol > 0.0 && !before && part_one_.pressure() == 0.0));
         ++k) {
      const double f_next = near.f * std::pow(d / near.depth, power(kFirstPower, force));
      before = std::move(near);
      near = solve(stage, f_next, false, true);
      evaluations += near.evaluations;
    }
    if (!usable(near) || near.configuration == Configuration::Unloaded) return std::nullopt;
    const Configuration c = near.configuration;
    const double floor = parameter_floor(c), ratio = d / near.depth;
    if (before && before->configuration != c) before.reset();
    const double p_power =
        power(2.0, [&](const ScaledSolution& x) { return std::max(x.parameter - floor, 1e-300); });
    const double p = floor + (near.parameter - floor) * std::pow(ratio, p_power);
    if (!(p > floor)) return std::nullopt;
    DepthNewton<IndentationShooting> newton(*this, settings().shooting_tol);
    newton.without_maxima(false);  // the state found is assembled again below
    if (noise_tol > 0.0) newton.guarded(noise_tol);
    const auto found = newton.solve(c, d, near.f * std::pow(ratio, power(kFirstPower, force)), p);
    const double depth_tol = std::max(kDepthPolish, noise_tol);
    if (!found || !(std::abs(found->depth - d) <= depth_tol * d)) return std::nullopt;
    auto residual_at = [&](Configuration cc, double q) { return residual(cc, found->f, q); };
    if (contact_.plan(stage, found->f, residual_at).configuration != c) return std::nullopt;
    // The same integration with the fields sampled: the same state.
    ScaledSolution out = assemble(c, found->f, found->parameter, true);
    if (!out.ok()) return std::nullopt;
    out.evaluations += evaluations + found->evaluations + 1;
    return out;
  }
  static constexpr int kNearSolves = 5;
  static constexpr double kNearEnough = 1.05;
  // The first step's power of the depth: between the small-deflection 3 and the ~1.5 of the
  // paper's membrane at 20 to 35 mm.
  static constexpr double kFirstPower = 2.0;
  static constexpr double kRoughResidual = 1e-5;

 private:
  // The coarse integration of the shooting's first phase: about a third of the fine one's steps.
  static ShootingSettings coarse(ShootingSettings s) {
    s.integration.rel_tol = std::max(s.integration.rel_tol, kCoarseRelTol);
    s.integration.abs_tol = std::max(s.integration.abs_tol, 1e-2 * kCoarseRelTol);
    return s;
  }
  static constexpr double kCoarseRelTol = 1e-6;

  // The shooting's root found on the coarse integration, then polished by secant steps on the
  // fine residual from there: the coarse root lies within ~1e-6 of the fine one, where two or
  // three secant steps converge, so most of the search costs a third.  Only where the strains
  // (~f^(2/3)) are large against the coarse tolerance.  Empty when the coarse search finds no
  // root or the polish leaves the bracket, meets a stand-in residual or does not converge in
  // kPolishSteps: the fine search then runs in full.
  template <class Fine>
  std::optional<double> coarse_then_fine(const ShootingPlan& plan, double f, Fine& fine, int& evals,
                                         bool rough) const {
    if (std::pow(f, 2.0 / 3.0) < 1e4 * kCoarseRelTol) return std::nullopt;
    auto coarse = [&](double p) {
      ++evals;
      return coarse_part_one_.residual(f, contact_.free_start(plan.configuration, f, p));
    };
    const auto p_coarse = shoot_increasing(coarse,
                                           plan.lo,
                                           plan.g_lo,
                                           plan.cap,
                                           settings().max_iterations,
                                           plan.initial_step,
                                           {1e-2 * kCoarseRelTol, std::nullopt});
    if (!p_coarse || rough) return p_coarse;
    const double hi = std::isfinite(plan.cap) ? plan.cap : 2.0 * *p_coarse + 1.0;
    const double scale = std::max(std::abs(*p_coarse - parameter_floor(plan.configuration)), 1e-8);
    return polish_coarse_root(
        fine, coarse, *p_coarse, scale, plan.lo, hi, good_enough(f), 1e-2, kPolishSteps);
  }
  static constexpr int kPolishSteps = 4;

  // The root of a plan whose bracket starts at a turned-back stand-in (ShootingPlan::
  // branch_below), from its cap down; residuals that are the stand-in or missing (the cap did
  // not carry the force) lie below the branch point.  Empty when that search fails: TOMS 748
  // on the plan's bracket runs then.
  template <class Fine>
  std::optional<double> above_branch(const ShootingPlan& plan, double f, Fine& fine) const {
    if (!plan.g_cap || !std::isfinite(plan.cap) || !(plan.cap > plan.lo)) return std::nullopt;
    auto defined = [&](double p) -> std::optional<double> {
      const std::optional<double> g = fine(p);
      if (!g || *g == kTurnedBack) return std::nullopt;
      return g;
    };
    BranchRootSearch search;
    search.up_step = 0.5 * (plan.cap - plan.lo);
    search.probe = 1e-5 * (plan.cap - plan.lo);
    // Residuals below the integration's absolute tolerance are its noise (~1e-13 near zero
    // load, where good_enough asks ~1e-15 and the bracket's last steps only met noise).
    search.tol = std::max(good_enough(f), settings().integration.abs_tol);
    search.max_evaluations = settings().max_iterations;
    search.below = plan.lo;
    const auto root = root_above_branch(defined, plan.cap, search);
    if (!root) return std::nullopt;
    return root->x;
  }

  static ScaledSolution outside_domain(ScaledSolution sol) {
    sol.status = Status::BeyondLocking;
    sol.message = "the shooting parameter is outside the material's domain";
    return sol;
  }

  // Part I from `st` at force sol.f into sol: clamp residual, height, largest I1; false (with
  // the message) when it cannot be integrated to the clamp.
  bool run_free_part(const FreeStart& st, bool record, ScaledSolution& sol,
                     bool find_maximum = true) const {
    const auto run = part_one_.run(sol.f, st, record ? &sol.part_one : nullptr, find_maximum);
    if (!run.ok) {
      sol.message = run.turned_back ? "Part I turns back towards the axis before the clamp"
                                    : "Part I cannot be integrated to the clamp (material locks)";
      return false;
    }
    sol.residual = run.residual;
    sol.r_top = st.r0;
    sol.edge_radius = st.r0 * st.state[2];
    sol.corner_slope = st.slope;
    sol.tension_ratio = st.ratio;
    sol.edge_s1 = membrane_stress(part_one_.law(), st.state[1], st.state[2]).s1;
    sol.max_i1 = run.max_i1;
    sol.max_i1_r = run.max_i1_r;
    sol.max_i1_radius = run.max_i1_radius;
    sol.wrinkle_r = run.wrinkle_r;
    sol.wrinkle_radius = run.wrinkle_radius;
    // From the inflated pole, if any (+ 0 without pressure: the height itself, bit for bit).
    sol.depth = run.height + settings().dome_height;
    return true;
  }

  // A state within kLockingMargin (relative) of the material's locking I1: there the clamp
  // residual jumps by more than the shooting's tolerance between adjacent parameters (~1e-8 per
  // ulp at I1 = 128 - 1e-6 for Gent J_lim = 125).
  bool locks(const ScaledSolution& sol) const {
    const double locking = part_one_.locking_i1();
    return std::isfinite(locking) && sol.max_i1 >= locking * (1.0 - kLockingMargin);
  }
  static constexpr double kLockingMargin = 1e-6;

  // An integrated state judged by its clamp residual (and, when it meets it, by accept_state).
  ScaledSolution judged(ScaledSolution sol) const {
    sol.integrated = true;
    sol.shooting_tol = settings().shooting_tol;
    if (std::abs(sol.residual) <= settings().shooting_tol) {
      accept_state(sol);
    } else if (sol.residual == kTurnedBack) {
      // The bracket closed on the jump from a Part I that turns back (hoop compression next to
      // the probe, e.g. a sharp cone at small forces) to one that overshoots: no tension-only
      // state in between.
      sol.status = Status::Wrinkles;
      sol.message =
          "Part I turns back towards the axis next to the probe at every parameter below the "
          "clamp condition: the hoop stress there turns compressive and the membrane wrinkles, "
          "outside the tension-only membrane theory";
    } else {
      sol.status = Status::NoConvergence;
      sol.message = fmt::format("the shooting stalled at clamp residual {:.3g}", sol.residual);
    }
    return sol;
  }

  FreePart<Law> part_one_;
  FreePart<Law> coarse_part_one_;
  Contact contact_;
  bool record_unloaded_;
  std::optional<ScaledSolution> dome_;
};

}  // namespace puncture::detail
