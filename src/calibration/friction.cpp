// Friction from the size of the hole a dry membrane leaves (paper §4.2).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "inversion.hpp"
#include "puncture/calibration.hpp"

namespace puncture {

namespace {

// 0, then 5 points per decade from max / 500 to max: the Part III stretch falls fastest
// between mu' ~ 0.5 and 3 (from near its frictionless value to near 1), and a root is refined
// inside its bracket whatever the spacing; the grid only has to separate several solutions.
std::vector<double> friction_grid(double max_friction) {
  std::vector<double> grid{0.0};
  constexpr int kPerDecade = 5;
  const double lo = std::log10(max_friction / 500.0);
  const double hi = std::log10(max_friction);
  const int n = static_cast<int>(std::ceil((hi - lo) * kPerDecade));
  for (int k = 0; k <= n; ++k) grid.push_back(std::pow(10.0, lo + (hi - lo) * k / n));
  grid.back() = max_friction;
  return grid;
}

std::string what_is_measured(HoleMethod method, double force_n) {
  return method == HoleMethod::AtMeasuredForce
             ? fmt::format("the sliding equilibrium at {:.6g} N", force_n)
             : std::string("the predicted puncture");
}

// The inversion of one target, with the reason when it is out of reach.
Inversion invert_ratio(const detail::Model& model, const std::vector<ScanSample>& samples,
                       double target, double max_friction, const std::string& where) {
  auto out = detail::invert(model, samples, target, 1e-9 * std::max(1.0, max_friction));
  if (out.ok()) {
    if (out.solutions.size() > 1) {
      std::string all;
      for (const double s : out.solutions)
        all += fmt::format("{}{:.6g}", all.empty() ? "" : ", ", s);
      out.message = fmt::format(
          "several friction coefficients give a Part III stretch of {:.6g} "
          "in {}: {}",
          target,
          where,
          all);
    }
    return out;
  }
  const ScanSample* largest = nullptr;
  const ScanSample* smallest = nullptr;
  for (const auto& s : samples) {
    if (!s.model) continue;
    if (!largest || *s.model > *largest->model) largest = &s;
    if (!smallest || *s.model < *smallest->model) smallest = &s;
  }
  std::string why;
  if (!largest)
    why = "the solver failed at every friction coefficient tried";
  else if (target > *largest->model)
    why = fmt::format(
        "the largest attainable is {:.6g} (mu' = {:.6g}); a larger stretch needs "
        "less friction than none",
        *largest->model,
        largest->parameter);
  else if (target < *smallest->model)
    why = fmt::format("the smallest attainable is {:.6g} (mu' = {:.6g}, the model's limit)",
                      *smallest->model,
                      smallest->parameter);
  else
    why = "the target lies where the solver failed";
  const auto failed = detail::failed_samples(samples);
  if (!failed.empty()) why += fmt::format("; the solver failed at mu' {}", failed);
  if (!out.message.empty()) why += "; " + out.message;
  out.message = fmt::format(
      "no friction coefficient in [0, {:.6g}] gives a Part III stretch of "
      "{:.6g} in {}: {}",
      max_friction,
      target,
      where,
      why);
  return out;
}

}  // namespace

std::string to_string(HoleMethod method) {
  return method == HoleMethod::AtMeasuredForce ? "at-measured-force" : "at-predicted-puncture";
}

FrictionEstimate friction_from_hole(const Problem& problem, const HoleMeasurement& hole,
                                    HoleMethod method, const FrictionOptions& options) {
  if (auto errors = validation_errors(problem, Unknown::Friction); !errors.empty())
    throw InvalidInput(std::move(errors), "invalid problem:");
  Problem base = problem;
  base.friction = 0.0;  // the unknown: the problem's own is ignored
  if (!sharp_flat_punch(problem.indenter))
    throw InvalidInput(
        "indenter",
        "the friction calibration is implemented for the sharp flat punch only, not the " +
            describe(problem.indenter));
  if (problem.preload.pressure_mpa > 0.0)
    throw InvalidInput(
        "preload.pressure_mpa",
        "the friction calibration is not implemented for an inflated membrane (pressure > 0) yet");
  if (problem.preload.gas_volume_mm3)
    throw InvalidInput("preload.gas_volume_mm3",
                       "the friction calibration is not implemented over a sealed gas chamber yet");
  if (!std::isfinite(hole.ratio) || hole.ratio <= 0.0)
    throw InvalidInput(
        "hole.ratio",
        fmt::format(
            "hole ratio (indenter diameter / hole diameter) must be a finite number > 0, got {}",
            hole.ratio));
  if (!std::isfinite(hole.ratio_sd) || hole.ratio_sd < 0.0)
    throw std::invalid_argument(fmt::format(
        "hole ratio standard deviation must be a finite number >= 0, got {}", hole.ratio_sd));
  if (method == HoleMethod::AtMeasuredForce &&
      (!hole.puncture_force_n || !std::isfinite(*hole.puncture_force_n) ||
       *hole.puncture_force_n <= 0.0))
    throw std::invalid_argument(
        hole.puncture_force_n
            ? fmt::format("puncture force must be a finite number > 0 N, got {}",
                          *hole.puncture_force_n)
            : std::string("puncture force: the measured force is needed at the measured force"));
  if (!std::isfinite(options.max_friction) || options.max_friction <= 0.0 ||
      options.max_friction > 10.0)
    throw std::invalid_argument(
        fmt::format("largest friction searched must be in (0, 10], got {}", options.max_friction));

  SolverOptions solver = options.solver;
  solver.record_fields = false;
  const double force = method == HoleMethod::AtMeasuredForce ? *hole.puncture_force_n : 0.0;
  const auto with_friction = [&](double mu) {
    Problem q = base;
    q.friction = mu;
    return q;
  };
  const detail::Model model = [&](double mu) -> std::optional<double> {
    if (method == HoleMethod::AtMeasuredForce) {
      const auto state = solve_at_force(with_friction(mu), force, Stage::Slip, solver);
      if (!state.ok()) return std::nullopt;
      return state.part_three_stretch;
    }
    const auto puncture = predict_puncture(with_friction(mu), solver);
    if (!puncture.ok()) return std::nullopt;
    return puncture.part_three_stretch;
  };

  FrictionEstimate out;
  out.method = method;
  out.force_n = force;
  out.max_friction = options.max_friction;
  out.scan = detail::scan(model, friction_grid(options.max_friction));
  out.stretch_at_zero_friction = out.scan.front().model;
  out.stretch_at_max_friction = out.scan.back().model;

  const auto where = what_is_measured(method, force);
  out.friction = invert_ratio(model, out.scan, hole.ratio, options.max_friction, where);
  if (hole.ratio_sd > 0.0) {
    out.friction_for_ratio_plus_sd =
        invert_ratio(model, out.scan, hole.ratio + hole.ratio_sd, options.max_friction, where);
    out.friction_for_ratio_minus_sd =
        invert_ratio(model, out.scan, hole.ratio - hole.ratio_sd, options.max_friction, where);
  } else {
    out.friction_for_ratio_plus_sd.message = out.friction_for_ratio_minus_sd.message =
        "no standard deviation of the ratio given";
  }

  if (out.friction.ok()) {
    const Problem fitted = with_friction(out.friction.value);
    if (method == HoleMethod::AtMeasuredForce) {
      const auto state = solve_at_force(fitted, force, Stage::Slip, solver);
      if (state.ok()) out.max_first_invariant = state.max_first_invariant;
    } else {
      const auto puncture = predict_puncture(fitted, solver);
      if (puncture.ok()) {
        out.max_first_invariant = puncture.state.max_first_invariant;
        out.puncture_force_n = puncture.force_n;
        out.puncture_depth_mm = puncture.depth_mm;
      }
    }
  }
  return out;
}

}  // namespace puncture
