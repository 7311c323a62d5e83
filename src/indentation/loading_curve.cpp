#include "puncture/loading_curve.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>

#include "indentation/depth_newton.hpp"
#include "indentation/reported_failure.hpp"
#include "indentation/scaled_problem.hpp"
#include "numerics/shooting.hpp"

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
  return detail::shoot_increasing(
      residual, f_lo, g_lo, kInf, o.max_shooting_iterations, std::max(0.25 * f_lo, 0.05));
}

std::string crack_location(const detail::ScaledSolution& sol) {
  const double l3 = sol.part_three_stretch;
  const double i1_tip = 2.0 * l3 * l3 + 1.0 / (l3 * l3 * l3 * l3);
  if (i1_tip > sol.max_i1 * (1.0 + 1e-9)) return "Part III, under the indenter's tip";
  const double tol = 1e-9;
  if (std::abs(sol.max_i1_r - sol.r_corner) <= tol) {
    std::string where = sol.configuration == Configuration::SlipWithPartTwo
                            ? "Part II at the indenter's corner"
                            : "Part I at the indenter's corner";
    if (i1_tip >= sol.max_i1 * (1.0 - 1e-9))
      where += " (without friction Part III, under the tip, is as stretched)";
    return where;
  }
  if (sol.configuration == Configuration::SlipWithPartTwo && sol.max_i1_r < sol.r_top)
    return "Part II, on the indenter's side";
  return "Part I, off the indenter";
}

// The stick -> slip boundary with the held state at the switch (when it switches), which the
// puncture search needs too: the loading curve locates it once for both.
struct SwitchPoint {
  StageBoundary boundary;
  std::optional<detail::ScaledSolution> held;
};

SwitchPoint locate_switch(const Problem& p, const SolverOptions& options) {
  SwitchPoint out;
  StageBoundary& b = out.boundary;
  if (const auto errors = validation_errors(p); !errors.empty()) {
    b.status = Status::InvalidInput;
    b.message = errors.front();
    return out;
  }
  const auto o = without_fields(options);
  const double scale = force_scale_n(p);
  const double big_a = p.geometry.clamp_radius_mm;
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
  std::optional<detail::ScaledSolution> at_switch;
  if (p.stick.rule == StickRule::Force) {
    at_switch = detail::solve_scaled(p, p.stick.threshold / scale, Stage::Stick, o);
  } else if (p.stick.rule == StickRule::Depth) {
    at_switch = detail::solve_scaled_at_depth(p, p.stick.threshold / big_a, Stage::Stick, o);
  } else {  // EdgeTension: s1 H at the edge [N/mm] reaches the threshold
    const double target =
        p.stick.threshold / (p.material.shear_modulus_mpa * p.geometry.thickness_mm);
    const auto f =
        first_force_where(p, Stage::Stick, 0.0, -target, o, [&](const detail::ScaledSolution& s) {
          return s.edge_s1 - target;
        });
    if (f) at_switch = detail::solve_scaled(p, *f, Stage::Stick, o);
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

}  // namespace

StageBoundary stick_slip_boundary(const Problem& p, const SolverOptions& options) {
  return detail::reporting_failures<StageBoundary>(
      [&] { return locate_switch(p, options).boundary; });
}

namespace {

// The puncture point, given the problem's stick -> slip switch (locate_switch with the same
// options); `at_switch` tells whether it is the sliding state at the switch (the jump to
// sliding already reaches the critical I1).
PuncturePrediction find_puncture(const Problem& p, const SolverOptions& options,
                                 const SwitchPoint& switch_point, bool& at_switch) {
  at_switch = false;
  PuncturePrediction out;
  if (const auto errors = validation_errors(p); !errors.empty()) {
    out.message = errors.front();
    return out;
  }
  const auto o = without_fields(options);
  const double scale = force_scale_n(p);
  const double big_a = p.geometry.clamp_radius_mm;
  const double i1c = p.critical_i1;
  const StageBoundary& boundary = switch_point.boundary;
  if (boundary.status != Status::Converged) {
    out.message = boundary.message;
    return out;
  }
  auto over_critical = [&](const detail::ScaledSolution& s) {
    return detail::max_first_invariant(s) - i1c;
  };
  std::optional<double> f_puncture;
  Stage stage = Stage::Slip;
  double slip_from_f = 0.0, slip_from_g = 3.0 - i1c;
  if (boundary.first_stage == Stage::Stick) {
    const double f_switch = boundary.switches ? boundary.force_stuck_n / scale : kInf;
    bool punctures_stuck = !boundary.switches;
    if (boundary.switches) {
      const auto s = switch_point.held ? *switch_point.held
                                       : detail::solve_scaled(p, f_switch, Stage::Stick, o);
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
  if (!f_puncture && stage == Stage::Slip) {
    // Usually the crack starts at the corner once Part II exists, where a direct solve applies;
    // it holds if the loading path reaches that force in the slip stage.  max I1 grows with the
    // force along the path, so the first crossing is then this one.
    if (const auto direct = detail::puncture_at_corner(p, o); direct && direct->f >= slip_from_f)
      f_puncture = direct->f;
    else
      f_puncture = first_force_where(p, Stage::Slip, slip_from_f, slip_from_g, o, over_critical);
  }
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
  // The force searches count a failed solve as beyond the root, so a stage whose solutions end
  // (a held membrane that would wrap the side, locking) before the largest I1 reaches the
  // critical value would return that end: not a puncture.  At a true root the largest I1 is
  // the critical one to ~1e-8 relative (the corner solve's tolerance; the path search brackets
  // the force to a few ulps): 1e-6 relative leaves a margin.
  if (const double reached = detail::max_first_invariant(sol);
      !at_switch && reached < i1c * (1.0 - 1e-6)) {
    const auto beyond = detail::solve_scaled(p, *f_puncture * (1.0 + 1e-9), stage, o);
    out.message = fmt::format(
        "no puncture found: in the {} stage the largest I1 reaches only {:.8g} (critical {:g}) "
        "at {:.6g} N, where the solutions end{}",
        to_string(stage),
        reached,
        i1c,
        *f_puncture * scale,
        beyond.ok() ? std::string() : ": " + beyond.message);
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
  out.crack_radius_mm = out.state.max_first_invariant_radius_mm;
  return out;
}

}  // namespace

PuncturePrediction predict_puncture(const Problem& p, const SolverOptions& options) {
  return detail::reporting_failures<PuncturePrediction>([&] {
    bool at_switch = false;
    return find_puncture(p, options, locate_switch(p, without_fields(options)), at_switch);
  });
}

namespace {

// Extrapolation of (f, p) to a new depth from the last converged points of a segment: the
// predictor of the Newton corrector.  Near zero depth f ~ depth^3 and p - 1 ~ depth^2
// (membrane theory), so it works with log f and log(p - p0) (p0 the parameter's floor) against
// log depth: from one point with those powers, from two to four by Lagrange interpolation.
struct Predictor {
  std::vector<std::array<double, 3>> history;  // depth, f, parameter
  bool usable() const { return !history.empty(); }
  std::array<double, 2> at(double d, double floor) const {
    const std::size_t n = history.size(), m = std::min<std::size_t>(n, 4);
    if (n == 1) {
      const auto& h = history.front();
      const double ratio = d / h[0];
      return {h[1] * ratio * ratio * ratio, floor + (h[2] - floor) * ratio * ratio};
    }
    std::array<double, 2> out{0.0, 0.0};
    for (std::size_t i = n - m; i < n; ++i) {
      double w = 1.0;
      for (std::size_t j = n - m; j < n; ++j)
        if (j != i) w *= std::log(d / history[j][0]) / std::log(history[i][0] / history[j][0]);
      out[0] += w * std::log(history[i][1]);
      out[1] += w * std::log(history[i][2] - floor);
    }
    return {std::exp(out[0]), floor + std::exp(out[1])};
  }
};

// Fills out.points along the depth grid; false (with out.status/message) on failure.
template <class Law>
bool follow_curve(const Problem& p, const Law& law, const detail::ScaledSettings& settings,
                  const SolverOptions& o, const StageBoundary& boundary, double end_depth,
                  bool has_switch, const std::optional<detail::ScaledSolution>& onset,
                  const CurveOptions& curve, LoadingCurve& out) {
  const double scale = force_scale_n(p);
  const double big_a = p.geometry.clamp_radius_mm;
  const detail::ForceSolver<Law> solver(law, settings);
  detail::DepthNewton<Law> newton(solver, o.curve_tol);
  Predictor predictor;
  Stage segment_stage = boundary.first_stage;
  Configuration last_configuration = Configuration::Unloaded;
  auto stage_at = [&](double depth) {
    if (boundary.first_stage == Stage::Slip) return Stage::Slip;
    if (!boundary.switches || depth <= boundary.depth_mm) return Stage::Stick;
    return Stage::Slip;
  };
  auto expected_configuration = [&](double depth, Stage stage) {
    if (stage == Stage::Stick) return Configuration::Stick;
    return out.part_two_onset_depth_mm && depth >= *out.part_two_onset_depth_mm
               ? Configuration::SlipWithPartTwo
               : Configuration::SlipWithoutPartTwo;
  };
  auto add_point = [&](double depth, Stage stage) -> bool {
    if (stage != segment_stage) {
      predictor.history.clear();
      newton.reset();
      segment_stage = stage;
    }
    const double d = depth / big_a;
    std::optional<detail::ScaledSolution> sol;
    if (d > 0.0 && !predictor.usable()) {
      // Seed a new segment with one solve at a known force: a small one at the start of the
      // curve (the power-law predictor carries it to the first depth), the held force at the
      // stick -> slip switch.
      const double f_seed = out.points.size() > 1 ? out.points.back().normalized_force : 1e-4;
      const auto seed = stage == Stage::Stick ? solver.stick(f_seed) : solver.slip(f_seed);
      if (seed.ok()) {
        predictor.history = {{seed.depth, seed.f, seed.parameter}};
        last_configuration = seed.configuration;
      }
    }
    if (d > 0.0 && predictor.usable()) {
      const Configuration c = expected_configuration(depth, stage);
      auto guess = predictor.at(d, solver.parameter_floor(c));
      if (c != last_configuration) {
        newton.reset();
        if (c == Configuration::SlipWithPartTwo && onset) {
          // Part II starts with zero length at the onset: its top stretch starts from the onset
          // Part III stretch, while the force keeps following the curve.
          guess[1] = onset->parameter;
          predictor.history = {{onset->depth, onset->f, onset->parameter}};
        }
      }
      sol = newton.solve(c, d, guess[0], guess[1]);
    }
    if (!sol) {
      newton.reset();
      const double f_guess = predictor.history.empty() ? 0.0 : predictor.history.back()[1];
      sol = detail::solve_scaled_at_depth(p, d, stage, o, f_guess);
    }
    if (!sol->ok()) {
      out.status = sol->status;
      out.message =
          fmt::format("at depth {:.6g} mm ({} stage): {}", depth, to_string(stage), sol->message);
      return false;
    }
    if (sol->configuration != Configuration::Unloaded)
      predictor.history.push_back({d, sol->f, sol->parameter});
    last_configuration = sol->configuration;
    CurvePoint pt;
    pt.depth_mm = depth;
    pt.force_n = sol->f * scale;
    pt.normalized_force = sol->f;
    pt.stage = stage;
    pt.configuration = sol->configuration;
    pt.part_three_stretch = sol->part_three_stretch;
    pt.part_two_length_mm = sol->part_two_length * big_a;
    pt.corner_slope_rad = sol->corner_slope;
    pt.max_first_invariant = detail::max_first_invariant(*sol);
    out.points.push_back(pt);
    return true;
  };
  const int n = curve.points;
  // The last depth is end_depth itself (end_depth * (n - 1) / (n - 1) may miss it by an ulp).
  auto grid = [&](int k) { return k == n - 1 ? end_depth : end_depth * k / (n - 1); };
  for (int k = 0; k < n; ++k) {
    const double depth = grid(k);
    const double prev_depth = k == 0 ? -1.0 : grid(k - 1);
    if (has_switch && depth >= boundary.depth_mm && prev_depth < boundary.depth_mm) {
      // Both sides of the switch, at the switch depth (which may be a grid depth: the last one
      // when the membrane punctures as it starts sliding).
      if (!add_point(boundary.depth_mm, Stage::Stick)) return false;
      if (!add_point(boundary.depth_mm, Stage::Slip)) return false;
      out.stick_slip.force_sliding_n = out.points.back().force_n;
    }
    if (!(has_switch && depth == boundary.depth_mm) && !add_point(depth, stage_at(depth)))
      return false;
    if (curve.progress) curve.progress(k + 1, n);
  }
  return true;
}

}  // namespace

namespace {

LoadingCurve unguarded_loading_curve(const Problem& p, const CurveOptions& curve,
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
  const auto switch_point = locate_switch(p, o);
  const StageBoundary& boundary = switch_point.boundary;
  if (boundary.status != Status::Converged) {
    out.status = boundary.status;
    out.message = boundary.message;
    return out;
  }
  bool puncture_at_switch = false;
  out.puncture = find_puncture(p, options, switch_point, puncture_at_switch);
  double end_depth = curve.max_depth_mm;
  if (end_depth <= 0.0) {
    if (!out.puncture.found) {
      out.status = Status::NoConvergence;
      out.message = "cannot end the curve at puncture: " + out.puncture.message;
      return out;
    }
    // A puncture at the switch is the sliding state at the switch depth (its own depth agrees
    // to the solver's accuracy): the curve ends with the switch.
    end_depth = puncture_at_switch ? boundary.depth_mm : out.puncture.depth_mm;
  }
  const bool has_switch = boundary.switches && boundary.depth_mm <= end_depth;
  if (has_switch) {
    out.stick_slip.occurs = true;
    out.stick_slip.depth_mm = boundary.depth_mm;
    out.stick_slip.force_stuck_n = boundary.force_stuck_n;
  }
  // Part II onset in the slip stage.
  // Part II onset on the sliding branch; a membrane held past that depth slides straight into
  // the configuration with Part II at the switch.
  std::optional<detail::ScaledSolution> onset;
  if (boundary.first_stage == Stage::Slip || boundary.switches) {
    onset = detail::part_two_onset(p, o);
    if (onset) {
      out.part_two_onset_depth_mm = onset->depth * big_a;
      out.part_two_onset_force_n = onset->f * scale;
      if (boundary.switches && onset->depth * big_a < boundary.depth_mm) {
        out.part_two_onset_at_switch = true;
        out.part_two_onset_depth_mm = boundary.depth_mm;
        out.part_two_onset_force_n.reset();  // the sliding force at the switch, set below
        onset.reset();
      }
    }
  }
  const detail::ScaledSettings settings = detail::scaled_settings(p, o);
  const bool ok = std::visit(
      [&](const auto& law) {
        return follow_curve(
            p, law, settings, o, boundary, end_depth, has_switch, onset, curve, out);
      },
      p.material.law);
  if (!ok) return out;
  if (out.part_two_onset_at_switch) {
    if (out.stick_slip.occurs)
      out.part_two_onset_force_n = out.stick_slip.force_sliding_n;
    else  // the curve ends before the switch
      out.part_two_onset_depth_mm.reset();
  }
  out.status = Status::Converged;
  return out;
}

}  // namespace

LoadingCurve loading_curve(const Problem& p, const CurveOptions& curve,
                           const SolverOptions& options) {
  return detail::reporting_failures<LoadingCurve>(
      [&] { return unguarded_loading_curve(p, curve, options); });
}

}  // namespace puncture
