#pragma once
// The puncture found by following the sliding loading path in depth, for a membrane inflated at
// a held pressure beyond a hemisphere, or whose force searches fail (docs/model.md §17, "Beyond a
// hemisphere"): near the inflation limit point one force carries states of several inflated
// branches, and a force search closes on another branch's.  Depth control from the dome stays on
// the path: it steps down in depth (IndentationShooting::continue_in_depth), through force
// maxima, until the criterion is met, and locates the crossing by TOMS 748 on the depth.
#include <array>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <optional>

#include "indentation/depth_fold.hpp"
#include "indentation/depth_newton.hpp"
#include "indentation/scaled_solution.hpp"

namespace puncture::detail {

// What the path followed in depth meets first.
enum class DepthPathEnd {
  Puncture,    // the criterion is met: `state` is the puncture
  StatesEnd,   // no state one step deeper (the depth turns back, or the model ends): `state`
               // the deepest reached
  NotStarted,  // no first state near the dome on its branch
};

struct DepthPathResult {
  DepthPathEnd end = DepthPathEnd::NotStarted;
  ScaledSolution state;
  // The last state before the force first falls from one step to the next (a force maximum
  // within one step), if it does before `state`.
  std::optional<ScaledSolution> peak;
  // Where the states end because the depth turns back (depth_fold.hpp), the located fold.
  std::optional<DepthFold> fold;
  // ... and the deepest state depth control reached past `state` on the way to it (the start of
  // the continuation through the fold, depth_arclength.hpp).
  std::optional<ScaledSolution> deepest;
};

// The steps in normalised depth (/ A): 1 % of the clamp radius, 0.25 mm on the paper's membrane,
// short against the depths where the force turns (tens of millimetres); the path is followed to
// at most kDepthPathEnd clamp radii.
inline constexpr double kDepthPathStep = 0.01;
inline constexpr double kDepthPathEnd = 10.0;
// The force a step may lose before it counts as falling (relative): the states' own noise is
// ~1e-9 of it.
inline constexpr double kDepthPathForceNoise = 1e-7;

// The contact model's change of configuration on the sliding path (the flat punch's Part II
// appears, the sphere's contact reaches its equator) deeper than the path's state `last`, still
// in the old configuration: the state at the change, in the new configuration.  Searched from
// last's force up where the contact model can (the sphere: under a gas pressure its search from a
// small force finds no onset, docs/model.md §17, "Beyond a hemisphere"), and where that finds
// none from a small force (the search that found every change before), except on a later
// inflated state (whose search from a small force finds the first state's change).
template <class Shooting>
std::optional<ScaledSolution> change_past(const Shooting& shooting, const ScaledSolution& last) {
  const auto& contact = shooting.contact();
  const Configuration next = contact.configuration(Stage::Slip, true);
  if (next == last.configuration) return std::nullopt;
  auto change = [&] {
    if constexpr (requires { contact.slip_change(shooting, last.f); }) {
      auto from_path = contact.slip_change(shooting, last.f);
      if (from_path || shooting.settings().dome_later_state) return from_path;
    }
    return contact.slip_change(shooting);
  }();
  if (!change || !(change->depth > last.depth)) return std::nullopt;
  return change;
}

// The state at normalised depth `target` on the sliding path past the contact's change of
// configuration between the path's state `last` and `target`, and the state at the change.
struct PastChange {
  ScaledSolution change;
  ScaledSolution state;
};

// By Newton in depth control from the change's parameter and the force extrapolated from `last`
// through the change (the new configuration starts where the old one ends, as on the loading
// curve; from the change's own force the Jacobian's differences would leave the new
// configuration, whose part past the change has zero length there).
template <class Shooting>
std::optional<PastChange> past_change_on_path(const Shooting& shooting, const ScaledSolution& last,
                                              double target) {
  auto change = change_past(shooting, last);
  if (!change || !(change->depth < target)) return std::nullopt;
  const double slope = (change->f - last.f) / (change->depth - last.depth);
  DepthNewton<Shooting> newton(shooting, shooting.settings().shooting_tol, true);
  // (The flat punch's change is assembled without Part II, of zero length there.)
  auto out = newton.solve(shooting.contact().configuration(Stage::Slip, true),
                          target,
                          change->f + slope * (target - change->depth),
                          change->parameter);
  if (!out || !out->ok()) return std::nullopt;
  return PastChange{std::move(*change), std::move(*out)};
}

inline constexpr double kStepPastChange = 1e-3;

// The state at normalised depth d from the path's state `last`, past the contact's change of
// configuration between them: a step of kStepPastChange of the depth past the change
// (past_change_on_path: Newton from the change's parameter, which a longer step may not meet),
// then on in depth control.  Where a force search closes on another
// branch's state past the change (the sphere's equator on a dome beyond a hemisphere,
// docs/model.md §17).
template <class Shooting>
std::optional<ScaledSolution> reached_past_change(const Shooting& shooting,
                                                  const ScaledSolution& last, double d) {
  const auto change = change_past(shooting, last);
  if (!change || !(change->depth < d)) return std::nullopt;
  const double first = std::min(d, change->depth * (1.0 + kStepPastChange));
  auto passed = past_change_on_path(shooting, last, first);
  if (!passed) return std::nullopt;
  if (first == d) return std::move(passed->state);
  ScaledSolution from = std::move(passed->state);
  return shooting.continue_in_depth(from, d);
}

// Where continue_in_depth ends at the contact model's change of configuration between `last` and
// depth `target`: the state at `target` in the new configuration (past_change_on_path).
template <class Shooting>
std::optional<ScaledSolution> resumed_past_change(const Shooting& shooting,
                                                  const ScaledSolution& last, double target) {
  auto passed = past_change_on_path(shooting, last, target);
  if (!passed) return std::nullopt;
  return std::move(passed->state);
}

inline constexpr double kSameBranch = 0.05;

// The force of the path's first state (normalised): small, as the loading curve seeds its path.
inline constexpr double kPathStartForce = 1e-4;

// The path's first state, at force kPathStartForce, on the dome's branch.  On a later inflated
// state (ShootingSettings::dome_later_state) the shooting's search finds the first state's branch,
// so the parameter is bracketed next to the dome's pole stretch instead, on either side (the
// residual falls with it on the middle, unstable branch): steps from 1e-6 of it, doubling, up to
// kSameBranch of it (at this force the root lies ~1e-4 from it), refined by TOMS 748.  Not ok
// when none is found there.
template <class Shooting>
ScaledSolution dome_branch_start(const Shooting& shooting, Stage stage) {
  if (!shooting.settings().dome_later_state) return shooting.solve(stage, kPathStartForce);
  ScaledSolution none;
  none.status = Status::NoConvergence;
  none.message = "no state next to the later inflated state's dome at a small force";
  const Configuration c = shooting.contact().configuration(stage, false);
  const double f = kPathStartForce, p0 = shooting.settings().dome_pole_stretch;
  const auto g0 = shooting.residual(c, f, p0);
  if (!g0) return none;
  if (*g0 == 0.0) return shooting.assemble(c, f, p0, false);
  std::array<double, 2> near{p0, p0}, g_near{*g0, *g0};  // below and above p0
  for (double step = 1e-6 * p0; step <= kSameBranch * p0; step *= 2.0) {
    for (int side = 0; side < 2; ++side) {
      const double far = p0 + (side == 0 ? -step : step);
      const auto g_far = shooting.residual(c, f, far);
      if (!g_far) continue;
      if ((*g_far < 0.0) == (g_near[side] < 0.0)) {
        near[side] = far;
        g_near[side] = *g_far;
        continue;
      }
      const double lo = std::min(near[side], far), hi = std::max(near[side], far);
      const double g_lo = side == 0 ? *g_far : g_near[side],
                   g_hi = side == 0 ? g_near[side] : *g_far;
      std::uintmax_t iterations = 100;
      bool failed = false;
      const auto bracket = boost::math::tools::toms748_solve(
          [&](double q) {
            const auto g = shooting.residual(c, f, q);
            if (!g) failed = true;
            return g.value_or(0.0);
          },
          lo,
          hi,
          g_lo,
          g_hi,
          boost::math::tools::eps_tolerance<double>(50),
          iterations);
      if (failed) return none;
      ScaledSolution s = shooting.assemble(c, f, 0.5 * (bracket.first + bracket.second), false);
      return s.ok() ? s : none;
    }
  }
  return none;
}

// The state at normalised depth d on a later inflated state's branch (dome_branch_start), by
// Newton in depth control: shallower than the branch's first state, from the line through the
// dome and that state (the force of a pre-tensioned membrane grows about linearly from the pole);
// deeper, stepped on from it (continue_in_depth), past a change of configuration by
// reached_past_change.  Empty where Newton fails.
template <class Shooting>
std::optional<ScaledSolution> dome_branch_at_depth(const Shooting& shooting, Stage stage,
                                                   double d) {
  ScaledSolution start = dome_branch_start(shooting, stage);
  if (!start.ok() || !(start.depth > 0.0)) return std::nullopt;
  if (d > start.depth) {
    if (auto out = shooting.continue_in_depth(start, d)) return out;
    auto out = reached_past_change(shooting, start, d);  // start: the deepest state reached
    if (!out || !out->ok()) return std::nullopt;
    return out;
  }
  const double t = d / start.depth, p0 = shooting.settings().dome_pole_stretch;
  DepthNewton<Shooting> newton(shooting, shooting.settings().shooting_tol, true);
  auto out = newton.solve(start.configuration, d, start.f * t, p0 + (start.parameter - p0) * t);
  if (!out || !out->ok()) return std::nullopt;
  return out;
}

// Where depth control cannot step on (the sphere's contact reaching its side where the onset is
// not found from the path's last state): the state at depth `target` by the shooting's own search
// (a force search, then Newton in depth), taken only if it continues the path from `last`: its
// pole (Part III) stretch within kSameBranch of last's and its force within kSameBranch of it too
// (a step of 0.01 A moves them by ~1 %).
template <class Shooting>
std::optional<ScaledSolution> rejoined_by_force(const Shooting& shooting,
                                                const ScaledSolution& last, double target) {
  ScaledSolution s = shooting.solve_at_depth(Stage::Slip, target, last.f);
  if (!s.ok() || !(std::abs(s.depth / target - 1.0) < 1e-6)) return std::nullopt;
  if (!(std::abs(s.part_three_stretch / last.part_three_stretch - 1.0) < kSameBranch) ||
      !(std::abs(s.f / last.f - 1.0) < kSameBranch))
    return std::nullopt;
  return s;
}

// Excess(state) < 0 before the puncture, >= 0 at and beyond it (the criterion's excess).
template <class Shooting, class Excess>
DepthPathResult puncture_along_depth(const Shooting& shooting, Excess&& excess) {
  DepthPathResult out;
  // The first state near the dome, at a small force (as the loading curve seeds its path).
  // It must lie on the dome's branch: its pole (Part III) stretch within kSameBranch of the
  // dome's (0.3 % apart on the paper's membrane at 0.9 kPa; the branches' 90 % and more).
  ScaledSolution last = dome_branch_start(shooting, Stage::Slip);
  const ScaledSolution dome = shooting.solve(Stage::Slip, 0.0);
  if (!last.ok() || !(last.depth > 0.0) || excess(last) >= 0.0 ||
      !(std::abs(last.part_three_stretch / dome.part_three_stretch - 1.0) < kSameBranch))
    return out;
  ScaledSolution from = last;
  while (last.depth < kDepthPathEnd) {
    const double target = last.depth + kDepthPathStep;
    auto next = shooting.continue_in_depth(from, target);
    if (!next) next = resumed_past_change(shooting, last, target);
    if (!next) next = rejoined_by_force(shooting, last, target);
    if (!next || !next->ok()) {
      out.end = DepthPathEnd::StatesEnd;
      // Depth control got deeper than `last` (to `from`) in its configuration: a fold there?
      if (from.depth > last.depth) {
        out.fold = depth_fold_after(shooting, last, from);
        if (out.fold) out.deepest = from;
      }
      out.state = std::move(last);
      return out;
    }
    // Depth control goes on through a force maximum (as the loading curve); the first is kept.
    if (!out.peak && next->f < last.f * (1.0 - kDepthPathForceNoise)) out.peak = last;
    if (excess(*next) >= 0.0) {
      // The crossing between the two states, each trial state reached from the shallower one.
      const ScaledSolution below = last, above = *next;
      std::optional<ScaledSolution> best;
      bool failed = false;
      auto g = [&](double d) {
        const double tol = shooting.settings().shooting_tol;
        auto s = shooting.refine_at_depth(below, d, tol, true);
        // Past a change of configuration between the two, from the deeper one.
        if (!s || !s->ok()) s = shooting.refine_at_depth(above, d, tol, true);
        if (!s || !s->ok()) {
          failed = true;
          return 0.0;
        }
        const double e = excess(*s);
        if (!best || std::abs(e) < std::abs(excess(*best))) best = std::move(*s);
        return e;
      };
      std::uintmax_t iterations = 60;
      boost::math::tools::toms748_solve(g,
                                        below.depth,
                                        above.depth,
                                        excess(below),
                                        excess(above),
                                        boost::math::tools::eps_tolerance<double>(45),
                                        iterations);
      if (failed || !best) {
        out.end = DepthPathEnd::StatesEnd;
        out.state = below;
        return out;
      }
      out.end = DepthPathEnd::Puncture;
      out.state = std::move(*best);
      return out;
    }
    last = std::move(*next);
    from = last;
  }
  out.end = DepthPathEnd::StatesEnd;
  out.state = std::move(last);
  return out;
}

}  // namespace puncture::detail
