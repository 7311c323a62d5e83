#pragma once
// The puncture search along the loading path, for any indenter (a shooting, shooting.hpp): the
// stick -> slip switch of the problem's stick rule, then the first force at which the largest I1
// reaches the critical value (or the contact model's direct puncture solve).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "failure/criterion.hpp"
#include "indentation/criterion_on_state.hpp"
#include "indentation/depth_path_puncture.hpp"
#include "indentation/partial_slip_path.hpp"
#include "indentation/partial_slip_puncture.hpp"
#include "indentation/physical_state.hpp"
#include "indentation/scaled_problem.hpp"
#include "numerics/shooting.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Smallest normalised force at which g(solution) >= 0 in `stage`, searching up from f_lo where it
// is negative.  Failed solves (beyond locking) count as beyond the root.
template <class Shooting, class Criterion>
std::optional<double> first_force_where(const Shooting& shooting, Stage stage, double f_lo,
                                        double g_lo, Criterion&& g) {
  // asinh keeps the root and the sign but not the range: a soft law's I1 can reach 1e24 at a
  // force a tenfold past the root, and TOMS 748's secant through such a value lands 20 decades
  // below it, at forces whose strains (~1e-16) the shooting cannot resolve.
  auto residual = [&](double f) -> std::optional<double> {
    const auto sol = shooting.solve(stage, f);
    if (!sol.ok()) return std::nullopt;
    return std::asinh(g(sol));
  };
  // A stage whose solutions end before the criterion is met closes the bracket on a jump (to the
  // beyond-root stand-in), where TOMS 748 falls back to bisections: ~3 log2(1 / eps) = 160
  // iterations to bracket the end to a few ulps, more than one shooting's allowance.
  return shoot_increasing(residual,
                          f_lo,
                          std::asinh(g_lo),
                          kInf,
                          4 * shooting.settings().max_iterations,
                          std::max(0.25 * f_lo, 0.05));
}

// The stick -> slip boundary with the held state at the switch (when it switches), which the
// puncture search needs too: the loading curve locates it once for both.
struct SwitchPoint {
  StageBoundary boundary;
  std::optional<ScaledSolution> held;
};

// "largest I1", "largest principal stretch" (whose name already says "largest"), ...
inline std::string largest_measure(const FailureCriterion& criterion) {
  const std::string name = measure_name(criterion);
  return name.starts_with("largest") ? name : "largest " + name;
}

// The force (/ force scale) of the first touch, where the Coulomb stick rule asks whether
// friction holds the first material held: ~1e-5 N on the paper's membrane.
inline constexpr double kFirstTouchForce = 1e-6;

template <class Shooting>
SwitchPoint locate_switch(const Problem& p, const Shooting& shooting) {
  SwitchPoint out;
  StageBoundary& b = out.boundary;
  b.status = Status::Converged;  // unless the stick stage cannot reach its switch point
  const SolverScales units = solver_scales(p);
  const double scale = units.force_n;
  const double big_a = units.length_mm;
  switch (p.stick.rule) {
    case StickRule::None:
      b.first_stage = Stage::Slip;
      return out;
    case StickRule::Always:
      b.first_stage = Stage::Stick;
      return out;
    default:
      break;
  }
  b.first_stage = Stage::Stick;
  b.switches = true;
  std::optional<ScaledSolution> at_switch;
  if (p.stick.rule == StickRule::Force) {
    at_switch = shooting.solve(Stage::Stick, p.stick.threshold / scale);
  } else if (p.stick.rule == StickRule::Depth) {
    at_switch = shooting.solve_at_depth(Stage::Stick, p.stick.threshold / big_a);
  } else if (p.stick.rule == StickRule::Coulomb) {
    // Held while mu p holds every held point (docs/model.md §15.4); without friction, or when
    // the first material touched already needs more, the membrane slides from the first touch.
    auto beyond = [&](const ScaledSolution& s) { return s.held_traction_ratio - p.friction; };
    const auto first = shooting.solve(Stage::Stick, kFirstTouchForce);
    if (p.friction == 0.0 || (first.ok() && beyond(first) >= 0.0)) {
      b.first_stage = Stage::Slip;
      b.switches = false;
      return out;
    }
    if (const auto f = first_force_where(shooting, Stage::Stick, 0.0, -p.friction, beyond))
      at_switch = shooting.solve(Stage::Stick, *f);
  } else {  // EdgeTension: s1 H at the edge [N/mm] beyond the pre-tension reaches the threshold
    const double target =
        p.stick.threshold / (p.material.shear_modulus_mpa * p.geometry.thickness_mm);
    // The held membrane under the tip carries the pre-tension s_eq(L0) itself (docs/model.md §16):
    // the adhesion holds what the edge carries beyond it (nothing added without pre-stretch).
    // Under a gas pressure the first material touched is the inflated pole's, at its stretch
    // (§17.3).
    const double dome = shooting.settings().dome_pole_stretch;
    const double l0 = dome > 0.0 ? dome : p.preload.prestretch;
    const double pretension =
        l0 == 1.0 ? 0.0 : membrane_stress(shooting.contact().law(), l0, l0).s1;
    const auto f =
        first_force_where(shooting, Stage::Stick, 0.0, -target, [&](const ScaledSolution& s) {
          return s.edge_s1 - pretension - target;
        });
    if (f) at_switch = shooting.solve(Stage::Stick, *f);
  }
  if (!at_switch || !at_switch->ok()) {
    b.status = at_switch ? at_switch->status : Status::NoConvergence;
    b.message = "the stick stage cannot reach its switch point: " +
                (at_switch ? at_switch->message : std::string("no force meets the criterion"));
    return out;
  }
  b.depth_mm = at_switch->depth * big_a;
  b.force_stuck_n = at_switch->f * scale;
  out.held = std::move(at_switch);
  return out;
}

// The puncture's state `sol` (in `stage`) into `out`, converged: the physical state, its force,
// depth and configuration, and where the criterion is met; returns that assessment.
template <class Shooting>
FailureAssessment set_punctured_state(const Problem& p, const SolverOptions& options,
                                      const Shooting& shooting, const FailureCriterion& criterion,
                                      const ScaledSolution& sol, Stage stage,
                                      PuncturePrediction& out) {
  const auto& contact = shooting.contact();
  out.status = Status::Converged;
  out.message.clear();
  out.state = to_physical(p, contact, sol, stage, options);
  out.force_n = out.state.force_n;
  out.normalized_force = solver_scales(p).normalized_force(sol.f);
  out.depth_mm = out.state.depth_mm;
  out.stage = stage;
  out.configuration = sol.configuration;
  out.part_three_stretch = sol.part_three_stretch;
  const FailureAssessment crack = assess_scaled(p, contact, criterion, sol);
  out.crack_reference_radius_mm = crack.reference_radius_mm;
  if (std::holds_alternative<CriticalFirstInvariant>(criterion))
    out.crack_location = contact.crack_location(sol);
  else if (!has_local_measure(criterion))
    out.crack_location = fmt::format(
        "cut through the thickness along the ring at the corner (reference radius {:.6g} mm)",
        crack.reference_radius_mm);
  else
    out.crack_location =
        fmt::format("where the {} is largest: {}", measure_name(criterion), to_string(crack.part));
  out.crack_radius_mm = crack.radius_mm;
  return crack;
}

// The puncture point of one criterion, given the problem's stick -> slip switch (locate_switch
// with the same options); `at_switch` tells whether it is the sliding state at the switch (the
// jump to sliding already reaches the criterion).
// The searches use `shooting`; the state at puncture is made physical with `options` (fields).
template <class Shooting>
PuncturePrediction find_puncture_by_force(const Problem& p, const SolverOptions& options,
                                          const Shooting& shooting, const SwitchPoint& switch_point,
                                          const FailureCriterion& criterion, bool& at_switch) {
  at_switch = false;
  PuncturePrediction out;
  out.criterion = describe(criterion);
  const SolverScales units = solver_scales(p);
  const double scale = units.force_n;
  const double big_a = units.length_mm;
  const auto& contact = shooting.contact();
  // The criteria but the critical I1 read the sampled fields: every state searched is recorded
  // (the shooting's solve() samples by default).
  auto excess = [&](const ScaledSolution& s) { return criterion_excess(p, contact, criterion, s); };
  auto measure = [&](const ScaledSolution& s) { return excess(s) + critical_value(criterion); };
  const StageBoundary& boundary = switch_point.boundary;
  if (!boundary.ok()) {
    out.status = boundary.status;
    out.message = boundary.message;
    return out;
  }
  // The criterion's excess grows along the loading path; its first zero is the puncture.
  auto over_critical = [&](const ScaledSolution& s) { return excess(s); };
  std::optional<double> f_puncture;
  // Set when the membrane punctures as it starts sliding although no sliding state at the switch
  // is reached: the depth at which the sliding membrane reaches the criterion.
  std::optional<double> sliding_criterion_depth_mm;
  // The puncture state when a search found it already: the sliding state at the switch when the
  // jump to sliding fails the membrane, or the contact model's direct puncture solve.
  std::optional<ScaledSolution> found;
  std::optional<double> top_stretch;  // of the corner solve's state, a neighbour's warm start
  Stage stage = Stage::Slip;
  double slip_from_f = 0.0, slip_from_g = unloaded_excess(criterion);
  if (boundary.first_stage == Stage::Stick) {
    const double f_switch = boundary.switches ? boundary.force_stuck_n / scale : kInf;
    bool punctures_stuck = !boundary.switches;
    if (boundary.switches) {
      const auto s =
          switch_point.held ? *switch_point.held : shooting.solve(Stage::Stick, f_switch);
      punctures_stuck = s.ok() && over_critical(s) >= 0.0;
    }
    if (punctures_stuck) {
      stage = Stage::Stick;
      f_puncture =
          first_force_where(shooting, Stage::Stick, 0.0, unloaded_excess(criterion), over_critical);
    } else {
      const auto s = shooting.solve_at_depth(Stage::Slip, boundary.depth_mm / big_a);
      if (!s.ok()) {
        // The sliding state at the switch depth may lie beyond what the solver reaches (a limit
        // load: the depth grows without bound as the force approaches it).  If the sliding
        // membrane reaches the criterion at a smaller depth, it is past it at the switch (the
        // criterion grows along the sliding branch): it punctures as it starts sliding, at the
        // held state's force and depth (the peak a testing machine records).
        if (const auto f_slip = first_force_where(
                shooting, Stage::Slip, 0.0, unloaded_excess(criterion), over_critical)) {
          const auto at = shooting.solve(Stage::Slip, *f_slip);
          if (at.ok() && at.depth <= boundary.depth_mm / big_a &&
              excess(at) >= -1e-6 * critical_value(criterion)) {
            f_puncture = f_switch;
            stage = Stage::Stick;
            at_switch = true;
            sliding_criterion_depth_mm = at.depth * big_a;
          }
        }
        if (!f_puncture) {
          out.status = s.status;
          out.message = "no sliding state at the stick -> slip switch: " + s.message;
          return out;
        }
      } else {
        slip_from_f = s.f;
        slip_from_g = over_critical(s);
        if (slip_from_g >= 0.0) {  // the jump to sliding already fails the membrane
          f_puncture = s.f;
          at_switch = true;
          // It carries the switch depth, as the curve's point there does (to the curve's
          // tolerance), however fast the depth runs away from the force.
          const auto refined =
              shooting.refine_at_depth(s, boundary.depth_mm / big_a, options.curve_tol, true);
          found = refined ? *refined : s;
        }
      }
    }
  }
  if (!f_puncture && stage == Stage::Slip) {
    // Usually the crack starts at the corner once Part II exists, where a direct solve applies;
    // it holds if the loading path reaches that force in the slip stage.  max I1 grows with the
    // force along the path, so the first crossing is then this one.
    const auto i1c = critical_first_invariant(criterion);
    const auto direct =
        i1c ? shooting.contact().direct_puncture(shooting, *i1c, options.puncture_top_stretch_start)
            : std::optional<ScaledSolution>();
    if (direct && direct->f >= slip_from_f) {
      f_puncture = direct->f;
      found = *direct;
      if (direct->configuration == Configuration::SlipWithPartTwo) top_stretch = direct->parameter;
    } else
      f_puncture =
          first_force_where(shooting, Stage::Slip, slip_from_f, slip_from_g, over_critical);
  }
  if (!f_puncture) {
    out.message = fmt::format(
        "no puncture found: {} does not reach the critical value {:g} before the solver fails",
        measure_name(criterion),
        critical_value(criterion));
    return out;
  }
  auto sol = found ? *found : shooting.solve(stage, *f_puncture);
  // A search that closes on the end of the stage's solutions (or of what the model covers: the
  // ball's equator, the cone's shank) brackets it to a few ulps and may return the side beyond
  // (no state): the last state is an ulp or two below.  (Which side the bracket's middle lands
  // on follows the solves' rounding, the report should not.)
  for (int k = 0; k < 16 && !sol.ok() &&
                  (failure_kind(sol.status) == FailureKind::Physical ||
                   failure_kind(sol.status) == FailureKind::OutsideModel);
       ++k) {
    *f_puncture = std::nextafter(*f_puncture, 0.0);
    sol = shooting.solve(stage, *f_puncture);
  }
  if (!sol.ok()) {
    // A search whose bracket closed on the end of what the model covers (the force searches
    // count any failure as beyond the root) met that end, not a puncture.
    if (failure_kind(sol.status) == FailureKind::OutsideModel) {
      out.status = sol.status;
      out.message = "no puncture found before the states leave the model: " + sol.message;
      return out;
    }
    out.message = "the state at puncture did not converge: " + sol.message;
    return out;
  }
  // The force searches count a failed solve as beyond the root, so a stage whose solutions end
  // (a held membrane that would wrap the side, locking) before the largest I1 reaches the
  // critical value would return that end: not a puncture.  At a true root the largest I1 is
  // the critical one to ~1e-8 relative (the corner solve's tolerance; the path search brackets
  // the force to a few ulps): 1e-6 relative leaves a margin.
  const double critical = critical_value(criterion);
  if (const double reached = measure(sol); !at_switch && reached < critical * (1.0 - 1e-6)) {
    const auto beyond = shooting.solve(stage, *f_puncture * (1.0 + 1e-9));
    // Where the states end because the model does (friction on the sphere-tipped probe's side,
    // the ball's equator, the cone's shank), the answer is the model's limit, not the membrane's.
    out.status = !beyond.ok() && failure_kind(beyond.status) == FailureKind::OutsideModel
                     ? Status::OutsideModel
                     : Status::NotReached;
    out.message = fmt::format(
        "no puncture found: in the {} stage the {} reaches only {:.8g} (critical {:g}) "
        "at {:.6g} N, where the solutions end{}",
        to_string(stage),
        largest_measure(criterion),
        reached,
        critical,
        *f_puncture * scale,
        beyond.ok() ? std::string() : ": " + beyond.message);
    return out;
  }

  // Nor is a state far beyond it: a search that closed on a jump of the measure (a spurious
  // root beyond a limit load) found no state reaching it continuously.  1e-3: near a limit load
  // the measure is steep in the force and a true root may overshoot by ~1e-5, while the jumps
  // met were 20 % and more.
  if (const double reached = measure(sol); !at_switch && reached > critical * (1.0 + 1e-3)) {
    out.message = fmt::format(
        "the puncture search closed on a jump of the {} to {:.6g} (critical {:g}) at "
        "{:.6g} N: no state reaches the critical value continuously there",
        largest_measure(criterion),
        reached,
        critical,
        *f_puncture * scale);
    return out;
  }
  out.part_two_top_stretch = top_stretch;
  set_punctured_state(p, options, shooting, criterion, sol, stage, out);
  out.at_switch = at_switch;
  if (sliding_criterion_depth_mm)
    out.crack_location = fmt::format(
        "as the held membrane starts sliding at the stick -> slip switch (sliding, it reaches "
        "the critical {} at depth {:.6g} mm, before the switch depth, and stretches without "
        "bound at this one)",
        measure_name(criterion),
        *sliding_criterion_depth_mm);
  else if (at_switch)
    out.crack_location += " (at the stick -> slip switch)";
  return out;
}

// Under a held gas pressure, sliding from the first touch: the loading path followed in depth
// (depth_path_puncture.hpp), its puncture, or where it ends, with the force maximum met before if
// any (docs/model.md §17).  `by_force`: the force search's failure, or why it is not used.
template <class Shooting>
PuncturePrediction puncture_followed_in_depth(const Problem& p, const SolverOptions& options,
                                              const Shooting& shooting,
                                              const FailureCriterion& criterion,
                                              PuncturePrediction by_force) {
  const auto& contact = shooting.contact();
  auto excess = [&](const ScaledSolution& s) { return criterion_excess(p, contact, criterion, s); };
  const DepthPathResult path = puncture_along_depth(shooting, excess);
  if (path.end == DepthPathEnd::NotStarted) return by_force;
  const SolverScales units = solver_scales(p);
  const ScaledSolution& s = path.state;
  PuncturePrediction out = std::move(by_force);
  out.criterion = describe(criterion);
  if (path.end == DepthPathEnd::Puncture) {
    set_punctured_state(p, options, shooting, criterion, s, Stage::Slip, out);
    return out;
  }
  const double measure = excess(s) + critical_value(criterion);
  const std::string ends = fmt::format(
      "followed in depth, the loading path ends at {:.6g} mm ({:.6g} N, the {} {:.6g}, critical "
      "{:g}): no state is found {:.3g} mm deeper (the depth may turn back there, a fold, or the "
      "contact change its configuration: neither is followed)",
      s.depth * units.length_mm,
      s.f * units.force_n,
      largest_measure(criterion),
      measure,
      critical_value(criterion),
      kDepthPathStep * units.length_mm);
  if (path.fold && !path.peak) {
    const ScaledSolution& turn = path.fold->state;
    out.status = Status::LimitLoad;
    out.message = fmt::format(
        "no puncture found on the loading path: followed in depth, the depth turns back at {:.8g} "
        "mm (within {:.2g} mm; {:.6g} N, the {} {:.6g}, critical {:g}): a fold of the path, where "
        "under depth control the membrane snaps through (its force drops at that depth) before "
        "the criterion is met; the branch beyond the fold is not followed here (the loading curve "
        "follows it and the snap-through) ({})",
        turn.depth * units.length_mm,
        path.fold->depth_uncertainty * units.length_mm,
        turn.f * units.force_n,
        largest_measure(criterion),
        excess(turn) + critical_value(criterion),
        critical_value(criterion),
        out.message);
    return out;
  }
  if (path.peak) {
    out.status = Status::LimitLoad;
    out.message = fmt::format(
        "no puncture found on the loading path: the force reaches a maximum, about {:.6g} N at "
        "{:.6g} mm (within {:.3g} mm), before the criterion is met: held at that force and "
        "pressure the whole membrane snaps through (a global limit point) before the probe "
        "punctures it; {} ({})",
        path.peak->f * units.force_n,
        path.peak->depth * units.length_mm,
        kDepthPathStep * units.length_mm,
        ends,
        out.message);
    return out;
  }
  out.message = fmt::format("{}; {}", out.message, ends);
  return out;
}

// The puncture point of one criterion: under a held pressure on a dome beyond a hemisphere,
// along the path in depth alone (puncture_followed_in_depth: one force carries states of several
// branches there, and a force search may close on another's: 2.07 N at 156 mm instead of the
// path's 1.36 N at 27 mm for an 8 mm sphere at 1 kPa); elsewhere find_puncture_by_force, and
// under a held pressure the path in depth where that fails.
template <class Shooting>
PuncturePrediction find_puncture_by(const Problem& p, const SolverOptions& options,
                                    const Shooting& shooting, const SwitchPoint& switch_point,
                                    const FailureCriterion& criterion, bool& at_switch) {
  const StageBoundary& boundary = switch_point.boundary;
  const bool in_depth =
      p.preload.pressure_mpa > 0.0 && boundary.ok() && boundary.first_stage == Stage::Slip;
  if (in_depth && shooting.settings().dome_overhangs) {
    at_switch = false;
    PuncturePrediction none;
    none.status = Status::NoConvergence;
    none.message =
        "no puncture found: the dome overhangs its clamp, where the force searches are not used";
    return puncture_followed_in_depth(p, options, shooting, criterion, std::move(none));
  }
  PuncturePrediction out =
      find_puncture_by_force(p, options, shooting, switch_point, criterion, at_switch);
  if (out.ok() || !in_depth) return out;
  return puncture_followed_in_depth(p, options, shooting, criterion, std::move(out));
}

// Whether puncture `a` comes before `b` along the loading path: the held stage first, then the
// shallower depth.
inline bool punctures_earlier(const PuncturePrediction& a, const PuncturePrediction& b) {
  if (a.stage != b.stage) return a.stage == Stage::Stick;
  return a.depth_mm < b.depth_mm;
}

// The puncture point: the first of the problem's criteria met along the loading path (each
// searched on its own; of those not found, the first criterion's failure when none is).
template <class Shooting>
PuncturePrediction find_puncture(const Problem& p, const SolverOptions& options,
                                 const Shooting& shooting, const SwitchPoint& switch_point,
                                 bool& at_switch) {
  const auto criteria = failure_criteria(p);
  PuncturePrediction first =
      find_puncture_by(p, options, shooting, switch_point, criteria[0], at_switch);
  for (std::size_t k = 1; k < criteria.size(); ++k) {
    bool switch_k = false;
    auto other = find_puncture_by(p, options, shooting, switch_point, criteria[k], switch_k);
    if (other.ok() && (!first.ok() || punctures_earlier(other, first))) {
      first = std::move(other);
      at_switch = switch_k;
    }
  }
  // After a `coulomb` release the path is a partial slip up to its hand-over
  // (partial_slip_path.hpp): a critical I1 is searched along its family, and a sliding puncture
  // found within that stretch is not the path's.
  if (first.ok() && first.stage == Stage::Stick) return first;
  const auto partial = partial_slip_segment(p, shooting, switch_point.boundary);
  if (!partial) return first;
  std::optional<PuncturePrediction> in_partial;
  for (const auto& c : criteria)
    if (auto found = partial_slip_puncture(p, *partial, c, options.record_fields);
        found && (!in_partial || found->depth_mm < in_partial->depth_mm))
      in_partial = std::move(found);
  if (in_partial) {
    at_switch = false;
    if (criteria.size() > 1 || !std::holds_alternative<CriticalFirstInvariant>(criteria[0]))
      in_partial->message =
          "the criteria other than the critical I1 are not searched within the partial slip";
    return std::move(*in_partial);
  }
  if (first.ok() && first.depth_mm >= partial->release_depth_mm &&
      first.depth_mm < partial->handover_depth_mm) {
    first.status = Status::OutsideModel;
    first.message = fmt::format(
        "no puncture found where the model holds: the sliding model reaches the criterion at "
        "depth {:.6g} mm, within the partial slip after the coulomb release (to {:.6g} mm), "
        "where only a critical I1 is searched (the partial slip's stays below it)",
        first.depth_mm,
        partial->handover_depth_mm);
  }
  return first;
}

}  // namespace puncture::detail
