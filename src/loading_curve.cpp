#include "puncture/loading_curve.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "scaled_problem.hpp"
#include "shooting.hpp"

namespace puncture {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

SolverOptions without_fields(SolverOptions o) {
  o.record_fields = false;
  return o;
}

// Smallest normalised force at which g(solution) >= 0 in `stage`, searching up from f_lo where it
// is negative.  Failed solves (beyond locking) count as beyond the root.
template <class Criterion>
std::optional<double> first_force_where(const Problem& p, Stage stage, double f_lo, double g_lo,
                                        const SolverOptions& o, Criterion&& g) {
  auto residual = [&](double f) -> std::optional<double> {
    const auto sol = detail::solve_scaled(p, f, stage, o);
    if (!sol.ok()) return std::nullopt;
    return g(sol);
  };
  return detail::shoot_increasing(residual, f_lo, g_lo, kInf, o.max_shooting_iterations,
                                  std::max(0.25 * f_lo, 0.05));
}

std::string crack_location(const detail::ScaledSolution& sol) {
  const double l3 = sol.part_three_stretch;
  const double i1_tip = 2.0 * l3 * l3 + 1.0 / (l3 * l3 * l3 * l3);
  if (i1_tip >= sol.max_i1) return "Part III, under the indenter's tip";
  const double tol = 1e-9;
  if (std::abs(sol.max_i1_r - sol.r_corner) <= tol)
    return sol.configuration == Configuration::SlipWithPartTwo
               ? "Part II at the indenter's corner"
               : "Part I at the indenter's corner";
  if (sol.configuration == Configuration::SlipWithPartTwo && sol.max_i1_r < sol.r_top)
    return "Part II, on the indenter's side";
  return "Part I, off the indenter";
}

}  // namespace

StageBoundary stick_slip_boundary(const Problem& p, const SolverOptions& options) {
  StageBoundary b;
  const auto o = without_fields(options);
  const double scale = force_scale_n(p);
  const double big_a = p.geometry.clamp_radius_mm;
  switch (p.stick.rule) {
    case StickRule::None:
      b.first_stage = Stage::Slip;
      return b;
    case StickRule::Always:
      b.first_stage = Stage::Stick;
      return b;
    default:
      break;
  }
  b.first_stage = Stage::Stick;
  b.switches = true;
  std::optional<detail::ScaledSolution> at_switch;
  if (p.stick.rule == StickRule::Force) {
    at_switch = detail::solve_scaled(p, p.stick.threshold / scale, Stage::Stick, o);
  } else if (p.stick.rule == StickRule::Depth) {
    at_switch = detail::solve_scaled_at_depth(p, p.stick.threshold / big_a, Stage::Stick, o);
  } else {  // EdgeTension: s1 H at the edge [N/mm] reaches the threshold
    const double target = p.stick.threshold / (p.material.shear_modulus_mpa * p.geometry.thickness_mm);
    const auto f = first_force_where(p, Stage::Stick, 0.0, -target, o,
                                     [&](const detail::ScaledSolution& s) { return s.edge_s1 - target; });
    if (f) at_switch = detail::solve_scaled(p, *f, Stage::Stick, o);
  }
  if (!at_switch || !at_switch->ok()) {
    b.status = at_switch ? at_switch->status : Status::NoConvergence;
    b.message = "the stick stage cannot reach its switch point: " +
                (at_switch ? at_switch->message : std::string("no force meets the criterion"));
    return b;
  }
  b.depth_mm = at_switch->depth * big_a;
  b.force_stuck_n = at_switch->f * scale;
  return b;
}

PuncturePrediction predict_puncture(const Problem& p, const SolverOptions& options) {
  PuncturePrediction out;
  if (const auto errors = validation_errors(p); !errors.empty()) {
    out.message = errors.front();
    return out;
  }
  const auto o = without_fields(options);
  const double scale = force_scale_n(p);
  const double big_a = p.geometry.clamp_radius_mm;
  const double i1c = p.critical_i1;
  const auto boundary = stick_slip_boundary(p, o);
  if (boundary.status != Status::Converged) {
    out.message = boundary.message;
    return out;
  }
  auto over_critical = [&](const detail::ScaledSolution& s) {
    return detail::max_first_invariant(s) - i1c;
  };
  std::optional<double> f_puncture;
  Stage stage = Stage::Slip;
  bool at_switch = false;
  double slip_from_f = 0.0, slip_from_g = 3.0 - i1c;
  if (boundary.first_stage == Stage::Stick) {
    const double f_switch = boundary.switches ? boundary.force_stuck_n / scale : kInf;
    bool punctures_stuck = !boundary.switches;
    if (boundary.switches) {
      const auto s = detail::solve_scaled(p, f_switch, Stage::Stick, o);
      punctures_stuck = s.ok() && over_critical(s) >= 0.0;
    }
    if (punctures_stuck) {
      stage = Stage::Stick;
      f_puncture = first_force_where(p, Stage::Stick, 0.0, 3.0 - i1c, o, over_critical);
    } else {
      const auto s = detail::solve_scaled_at_depth(p, boundary.depth_mm / big_a, Stage::Slip, o);
      if (!s.ok()) {
        out.message = "no sliding state at the stick -> slip switch: " + s.message;
        return out;
      }
      slip_from_f = s.f;
      slip_from_g = over_critical(s);
      if (slip_from_g >= 0.0) {  // the jump to sliding already reaches the critical I1
        f_puncture = s.f;
        at_switch = true;
      }
    }
  }
  if (!f_puncture && stage == Stage::Slip)
    f_puncture = first_force_where(p, Stage::Slip, slip_from_f, slip_from_g, o, over_critical);
  if (!f_puncture) {
    out.message = fmt::format(
        "no puncture found: I1 does not reach the critical value {:g} before the solver fails",
        i1c);
    return out;
  }
  const auto sol = detail::solve_scaled(p, *f_puncture, stage, options);
  if (!sol.ok()) {
    out.message = "the state at puncture did not converge: " + sol.message;
    return out;
  }
  out.found = true;
  out.state = detail::to_physical(p, sol, stage, options);
  out.force_n = out.state.force_n;
  out.normalized_force = sol.f;
  out.depth_mm = out.state.depth_mm;
  out.stage = stage;
  out.configuration = sol.configuration;
  out.part_three_stretch = sol.part_three_stretch;
  out.crack_reference_radius_mm = out.state.max_first_invariant_reference_radius_mm;
  out.crack_location = crack_location(sol);
  if (at_switch) out.crack_location += " (at the stick -> slip switch)";
  // Current radius of the crack site: r = lambda2 R; at the corner it is the indenter radius.
  out.crack_radius_mm = out.crack_reference_radius_mm;
  for (std::size_t i = 0; i < out.state.fields.size(); ++i)
    if (out.state.fields.reference_radius_mm[i] == out.crack_reference_radius_mm)
      out.crack_radius_mm = out.state.fields.radius_mm[i];
  return out;
}

LoadingCurve loading_curve(const Problem& p, const CurveOptions& curve,
                           const SolverOptions& options) {
  LoadingCurve out;
  if (const auto errors = validation_errors(p); !errors.empty()) {
    out.status = Status::InvalidInput;
    out.message = errors.front();
    return out;
  }
  if (curve.points < 2) {
    out.status = Status::InvalidInput;
    out.message = fmt::format("the curve needs at least 2 points, got {}", curve.points);
    return out;
  }
  const auto o = without_fields(options);
  const double scale = force_scale_n(p);
  const double big_a = p.geometry.clamp_radius_mm;
  const auto boundary = stick_slip_boundary(p, o);
  if (boundary.status != Status::Converged) {
    out.status = boundary.status;
    out.message = boundary.message;
    return out;
  }
  out.puncture = predict_puncture(p, options);
  double end_depth = curve.max_depth_mm;
  if (end_depth <= 0.0) {
    if (!out.puncture.found) {
      out.status = Status::NoConvergence;
      out.message = "cannot end the curve at puncture: " + out.puncture.message;
      return out;
    }
    end_depth = out.puncture.depth_mm;
  }
  const bool has_switch = boundary.switches && boundary.depth_mm < end_depth;
  if (has_switch) {
    out.stick_slip.occurs = true;
    out.stick_slip.depth_mm = boundary.depth_mm;
    out.stick_slip.force_stuck_n = boundary.force_stuck_n;
  }
  auto stage_at = [&](double depth) {
    if (boundary.first_stage == Stage::Slip) return Stage::Slip;
    if (!boundary.switches || depth <= boundary.depth_mm) return Stage::Stick;
    return Stage::Slip;
  };
  // Part II onset in the slip stage.
  if (boundary.first_stage == Stage::Slip || boundary.switches) {
    auto indicator = [&](double f) { return detail::part_two_indicator(p, f, o); };
    const double f_probe = 1e-3;
    if (const auto g0 = indicator(f_probe); g0 && *g0 < 0.0) {
      if (const auto f_on = detail::shoot_increasing(indicator, f_probe, *g0, kInf,
                                                     o.max_shooting_iterations, 0.1)) {
        const auto s = detail::solve_scaled(p, *f_on, Stage::Slip, o);
        if (s.ok()) {
          out.part_two_onset_depth_mm = s.depth * big_a;
          out.part_two_onset_force_n = s.f * scale;
        }
      }
    }
  }
  auto add_point = [&](double depth, Stage stage, double f_guess) -> std::optional<double> {
    const auto s = detail::solve_scaled_at_depth(p, depth / big_a, stage, o, f_guess);
    if (!s.ok()) {
      out.status = s.status;
      out.message = fmt::format("at depth {:.6g} mm ({} stage): {}", depth, to_string(stage),
                                s.message);
      return std::nullopt;
    }
    CurvePoint pt;
    pt.depth_mm = depth;
    pt.force_n = s.f * scale;
    pt.normalized_force = s.f;
    pt.stage = stage;
    pt.configuration = s.configuration;
    pt.part_three_stretch = s.part_three_stretch;
    pt.part_two_length_mm = s.part_two_length * big_a;
    pt.corner_slope_rad = s.corner_slope;
    pt.max_first_invariant = detail::max_first_invariant(s);
    out.points.push_back(pt);
    return s.f;
  };
  double f_prev = 0.0;
  const int n = curve.points;
  for (int k = 0; k < n; ++k) {
    const double depth = end_depth * k / (n - 1);
    const double prev_depth = k == 0 ? 0.0 : end_depth * (k - 1) / (n - 1);
    if (has_switch && depth > boundary.depth_mm && prev_depth <= boundary.depth_mm) {
      // Both sides of the switch, at the switch depth.
      const auto f_stuck = add_point(boundary.depth_mm, Stage::Stick, f_prev);
      if (!f_stuck) return out;
      const auto f_slid = add_point(boundary.depth_mm, Stage::Slip, *f_stuck);
      if (!f_slid) return out;
      out.stick_slip.force_sliding_n = *f_slid * scale;
      f_prev = *f_slid;
    }
    const auto f = add_point(depth, stage_at(depth), f_prev);
    if (!f) return out;
    f_prev = *f;
    if (curve.progress) curve.progress(k + 1, n);
  }
  out.status = Status::Converged;
  return out;
}

}  // namespace puncture
