// Profile of the force-depth fit over the stick threshold (stick_threshold_profile.hpp).
#include "calibration/stick_threshold_profile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

#include "calibration/curve_model.hpp"
#include "calibration/fit_verdict.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The fit with the switch after the first k distinct model depths.
struct Place {
  CurveFit fit;
  double ssr = kInf;           // curve residuals [N^2]; infinite when the fit failed
  double puncture_chi2 = 0.0;  // the puncture point's residuals over their sd, squared
  bool usable() const { return std::isfinite(ssr); }
};

// The depth of the switch for a threshold of the problem's rule (infinite: no switch).
double switch_depth(Problem p, double threshold, const SolverOptions& solver) {
  p.stick.threshold = threshold;
  const auto b = stick_slip_boundary(p, solver);
  if (!b.ok()) return std::numeric_limits<double>::quiet_NaN();
  return b.switches ? b.depth_mm : kInf;
}

// The threshold of the problem's rule that puts the switch at `depth_mm` (the held state's
// measure there); NaN when it cannot be found.
double threshold_at(const Problem& p, double depth_mm, const SolverOptions& solver) {
  switch (p.stick.rule) {
    case StickRule::Depth:
      return depth_mm;
    case StickRule::Force: {
      Problem q = p;
      q.stick = {StickRule::Depth, depth_mm};
      const auto b = stick_slip_boundary(q, solver);
      return b.ok() && b.switches ? b.force_stuck_n : std::numeric_limits<double>::quiet_NaN();
    }
    case StickRule::EdgeTension: {
      // The switch depth grows with the threshold: bracket, then TOMS 748.
      const auto f = [&](double t) {
        const double d = switch_depth(p, t, solver);
        return std::isnan(d) ? d : std::min(d, 1e6) - depth_mm;
      };
      double lo = p.stick.threshold > 0.0 ? p.stick.threshold : 1e-3, hi = lo;
      double f_lo = f(lo), f_hi = f_lo;
      for (int i = 0; i < 60 && std::isfinite(f_lo) && f_lo > 0.0; ++i) {
        hi = lo;
        f_hi = f_lo;
        lo /= 2.0;
        f_lo = f(lo);
      }
      for (int i = 0; i < 60 && std::isfinite(f_hi) && f_hi < 0.0; ++i) {
        lo = hi;
        f_lo = f_hi;
        hi *= 2.0;
        f_hi = f(hi);
      }
      if (!std::isfinite(f_lo) || !std::isfinite(f_hi) || f_lo > 0.0 || f_hi < 0.0)
        return std::numeric_limits<double>::quiet_NaN();
      if (f_lo == 0.0) return lo;
      if (f_hi == 0.0) return hi;
      std::uintmax_t iterations = 60;
      const auto r = boost::math::tools::toms748_solve(
          f, lo, hi, f_lo, f_hi, boost::math::tools::eps_tolerance<double>(40), iterations);
      return 0.5 * (r.first + r.second);
    }
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

// A place when no other parameter is free: the model's curve at the test's own parameters.
CurveFit evaluate_place(const CurveTest& test, const CurveFitOptions& options) {
  const CurveModel model(test, 0, {}, options.solver, test.puncture.has_value());
  const ModelCurve at = model.evaluate(nullptr);
  CurveFit fit;
  fit.curve_evaluations = model.solves();
  if (!at.ok) {
    fit.status = Status::NoConvergence;
    fit.message = "the model fails at the test's parameters: " + at.message;
    return fit;
  }
  CurveTestFit tf;
  tf.name = test.name;
  tf.depth_mm = test.depth_mm;
  tf.force_n = test.force_n;
  tf.model_force_n = at.force_n;
  double ssr = 0.0, mean = 0.0, sst = 0.0;
  for (const double f : test.force_n) mean += f / static_cast<double>(test.force_n.size());
  for (std::size_t i = 0; i < at.force_n.size(); ++i) {
    tf.residual_n.push_back(at.force_n[i] - test.force_n[i]);
    ssr += tf.residual_n.back() * tf.residual_n.back();
    sst += (test.force_n[i] - mean) * (test.force_n[i] - mean);
  }
  const auto n = static_cast<double>(at.force_n.size());
  tf.rms_residual_n = std::sqrt(ssr / n);
  tf.measured_puncture = test.puncture;
  if (at.puncture_force_n && at.puncture_depth_mm)
    tf.model_puncture = MeasuredPuncture{*at.puncture_depth_mm, *at.puncture_force_n};
  fit.tests.push_back(std::move(tf));
  fit.fitted_problems.push_back(test.problem);
  fit.points = static_cast<int>(n);
  fit.residual_sd_n = std::sqrt(ssr / n);
  fit.r_squared = sst > 0.0 ? 1.0 - ssr / sst : 0.0;
  fit.status = Status::Converged;
  outside_model_by_r_squared(fit, options.min_r_squared);
  return fit;
}

}  // namespace

CurveFit fit_with_stick_threshold_profile(const CurveFitProblem& problem,
                                          const CurveFitOptions& options) {
  const CurveTest& test = problem.tests.front();
  CurveFitOptions inner = options;
  inner.free.erase(std::find(inner.free.begin(), inner.free.end(), CurveParameter::StickThreshold));

  // The distinct model depths: a switch between u[k - 1] and u[k] holds the first k.
  std::vector<double> u;
  for (const double d : test.depth_mm) {
    const double model = d - test.contact_offset_mm;
    if (model > 0.0 && (u.empty() || model > u.back())) u.push_back(model);
  }
  const int m = static_cast<int>(u.size());
  CurveFit fail;
  fail.status = Status::NoConvergence;
  if (m < 2) {
    fail.message =
        "the record has fewer than 2 distinct depths past the contact: no place for "
        "a stick -> slip switch";
    return fail;
  }
  const auto proxy_depth = [&](int k) {
    if (k == 0) return 0.5 * u[0];
    if (k == m)
      return u[static_cast<std::size_t>(m - 1)] +
             0.5 * (u[static_cast<std::size_t>(m - 1)] - u[static_cast<std::size_t>(m - 2)]);
    return 0.5 * (u[static_cast<std::size_t>(k - 1)] + u[static_cast<std::size_t>(k)]);
  };

  std::map<int, Place> places;
  int iterations = 0, curves = 0;
  const auto at = [&](int k) -> const Place& {
    if (const auto it = places.find(k); it != places.end()) return it->second;
    CurveFitProblem pk = problem;
    auto& t = pk.tests.front();
    t.problem.stick = {StickRule::Depth, proxy_depth(k)};
    // Warm start: the estimates at the nearest place fitted.
    int nearest = -1;
    for (const auto& [j, pl] : places)
      if (pl.usable() && (nearest < 0 || std::abs(j - k) < std::abs(nearest - k))) nearest = j;
    if (nearest >= 0)
      for (const auto& fp : places.at(nearest).fit.parameters)
        set_value(fp.parameter, t.problem, fp.value);
    Place pl;
    pl.fit = inner.free.empty() ? evaluate_place(t, inner) : fit_curves(pk, inner);
    iterations += pl.fit.iterations;
    curves += pl.fit.curve_evaluations;
    if (!pl.fit.tests.empty()) {
      const auto& tf = pl.fit.tests.front();
      pl.ssr = 0.0;
      for (const double r : tf.residual_n) pl.ssr += r * r;
      if (tf.measured_puncture && tf.model_puncture) {
        const double df = (tf.model_puncture->force_n - tf.measured_puncture->force_n) /
                          (options.puncture_force_sd_fraction * tf.measured_puncture->force_n);
        const double dd = (tf.model_puncture->depth_mm - tf.measured_puncture->depth_mm) /
                          (options.puncture_depth_sd_fraction * tf.measured_puncture->depth_mm);
        pl.puncture_chi2 = df * df + dd * dd;
      }
    }
    return places.emplace(k, std::move(pl)).first->second;
  };
  // Brent's cost: the curves' sum of squares and the puncture point's, in N^2 by each place's
  // own residual variance (the final comparison uses the best place's).
  const auto brent_cost = [&](int k) {
    const Place& pl = at(k);
    if (!pl.usable()) return std::numeric_limits<double>::max();
    return pl.ssr + pl.fit.residual_sd_n * pl.fit.residual_sd_n * pl.puncture_chi2;
  };
  const auto place_of = [&](double s) {
    return std::clamp(static_cast<int>(std::lround(s)), 0, m);
  };
  // The profile is not unimodal over the whole record (measured: holding every point lets G
  // come down and costs less than a switch 5 mm off the true one), so a grid of places first,
  // then Brent's method between the best grid place's neighbours.
  const int grid = std::min(m, 24);
  int grid_best = 0;
  for (int i = 0; i <= grid; ++i)
    if (brent_cost(m * i / grid) < brent_cost(m * grid_best / grid)) grid_best = i;
  std::uintmax_t brent_iterations = 60;
  boost::math::tools::brent_find_minima([&](double s) { return brent_cost(place_of(s)); },
                                        m * std::max(grid_best - 1, 0) / grid - 0.5,
                                        m * std::min(grid_best + 1, grid) / grid + 0.5,
                                        20,
                                        brent_iterations);
  int best = -1;
  for (const auto& [k, pl] : places)
    if (pl.usable() && (best < 0 || brent_cost(k) < brent_cost(best))) best = k;
  if (best < 0) {
    fail.message = "the fit fails at every place of the stick -> slip switch tried: " +
                   places.begin()->second.fit.message;
    fail.iterations = iterations;
    fail.curve_evaluations = curves;
    return fail;
  }
  // The profile in residual variances of the best place, the threshold counted a parameter.
  int curve_p = 1;
  for (const auto f : inner.free) curve_p += f != CurveParameter::CriticalI1;
  const double quantile =
      boost::math::quantile(boost::math::chi_squared_distribution<double>(1.0), 0.95);
  int k_lo = best, k_hi = best;
  for (int restarts = 0; restarts <= m; ++restarts) {
    // Brent assumes one minimum: walk to the neighbours while they are lower.
    while (best > 0 && brent_cost(best - 1) < brent_cost(best)) --best;
    while (best < m && brent_cost(best + 1) < brent_cost(best)) ++best;
    const Place& top = places.at(best);
    const int dof = top.fit.points - curve_p;
    const double s2 = dof > 0 ? top.ssr / dof : kInf;
    const auto rise = [&](int k) {
      const Place& pl = at(k);
      if (!pl.usable() || !(s2 > 0.0) || !std::isfinite(s2)) return kInf;
      return (pl.ssr - top.ssr) / s2 + pl.puncture_chi2 - top.puncture_chi2;
    };
    k_lo = k_hi = best;
    while (k_lo > 0 && rise(k_lo - 1) <= quantile) --k_lo;
    while (k_hi < m && rise(k_hi + 1) <= quantile) ++k_hi;
    // A place inside the interval below the best (a second minimum behind a rise smaller than
    // the quantile): start again from it.
    int lowest = best;
    for (int k = k_lo; k <= k_hi; ++k)
      if (brent_cost(k) < brent_cost(lowest)) lowest = k;
    if (lowest == best) break;
    best = lowest;
  }
  const Place& top = places.at(best);
  const int dof = top.fit.points - curve_p;

  CurveFit fit = top.fit;
  Problem fitted = fit.fitted_problems.front();
  fitted.stick = test.problem.stick;
  auto bounds = default_bounds(CurveParameter::StickThreshold, test.problem);
  for (const auto& b : options.bounds)
    if (b.parameter == CurveParameter::StickThreshold) bounds = b;
  const auto threshold_of = [&](const Problem& p, int index) {
    // The threshold that puts the switch at u[index]; the bounds beyond the record.
    if (index < 0) return bounds.lower;
    if (index >= m) return bounds.upper;
    return threshold_at(p, u[static_cast<std::size_t>(index)], options.solver);
  };
  const double below = threshold_of(fitted, best - 1), above = threshold_of(fitted, best);
  double lower = threshold_of(fitted, k_lo - 1), upper = threshold_of(fitted, k_hi);

  // The ends move with the other parameters (the held force is proportional to G): widened by
  // 1.96 standard errors of each, from their covariance (delta method, central differences).
  const auto& ps = fit.parameters;
  bool have_cov = !fit.correlation.empty() && fitted.stick.rule != StickRule::Depth;
  for (const auto& fp : ps) have_cov = have_cov && fp.standard_error.has_value();
  const auto widened = [&](int index, double end) {
    if (!have_cov || index < 0 || index >= m || !std::isfinite(end)) return 0.0;
    std::vector<double> g(ps.size());
    for (std::size_t j = 0; j < ps.size(); ++j) {
      const double h = 1e-3 * std::max(std::abs(ps[j].value), 1e-3);
      Problem up = fitted, down = fitted;
      set_value(ps[j].parameter, up, ps[j].value + h);
      set_value(ps[j].parameter, down, ps[j].value - h);
      g[j] = (threshold_of(up, index) - threshold_of(down, index)) / (2.0 * h);
    }
    double var = 0.0;
    for (std::size_t i = 0; i < ps.size(); ++i)
      for (std::size_t j = 0; j < ps.size(); ++j)
        var += g[i] * g[j] * *ps[i].standard_error * *ps[j].standard_error * fit.correlation[i][j];
    return std::isfinite(var) && var > 0.0 ? std::sqrt(quantile * var) : 0.0;
  };
  lower = std::max(bounds.lower, lower - widened(k_lo - 1, lower));
  upper = std::min(bounds.upper, upper + widened(k_hi, upper));

  FittedCurveParameter tp;
  tp.parameter = CurveParameter::StickThreshold;
  tp.name = to_token(tp.parameter);
  tp.unit = unit_of(tp.parameter, test.problem);
  tp.value = 0.5 * (below + above);
  tp.profile_interval = true;
  if (std::isfinite(lower) && std::isfinite(upper)) {
    tp.ci_lower = lower;
    tp.ci_upper = upper;
  }
  const double offset = test.contact_offset_mm;
  if (best == 0 || best == m) {
    tp.on_bound = true;
    tp.identifiable = false;
    tp.value = best == 0 ? below : above;
    tp.note = fmt::format(
        "not identifiable: the record fits best with the switch {} ({} {:.6g} {}); it would "
        "take {}",
        best == 0 ? "before its first point" : "past its last point",
        best == 0 ? "a threshold below" : "a threshold above",
        best == 0 ? above : below,
        tp.unit,
        "a test that passes the stick -> slip switch");
  } else {
    tp.note = fmt::format(
        "95 % interval from the profile of the cost ({} at each place of the switch; a rise of "
        "{:.3g} residual variances): the switch lies between the measured depths {:.6g} and "
        "{:.6g} mm",
        inner.free.empty() ? "the curve" : "the others re-fitted",
        quantile,
        u[static_cast<std::size_t>(best - 1)] + offset,
        u[static_cast<std::size_t>(best)] + offset);
  }
  const auto position = static_cast<std::size_t>(
      std::find(options.free.begin(), options.free.end(), CurveParameter::StickThreshold) -
      options.free.begin());
  fit.parameters.insert(fit.parameters.begin() + static_cast<std::ptrdiff_t>(position), tp);
  if (!fit.correlation.empty()) {
    for (auto& row : fit.correlation)
      row.insert(row.begin() + static_cast<std::ptrdiff_t>(position), 0.0);
    std::vector<double> row(fit.parameters.size(), 0.0);
    row[position] = 1.0;
    fit.correlation.insert(fit.correlation.begin() + static_cast<std::ptrdiff_t>(position), row);
  }
  fitted.stick.threshold = std::clamp(tp.value, bounds.lower, bounds.upper);
  fit.fitted_problems.front() = fitted;
  if (dof > 0) fit.residual_sd_n = std::sqrt(top.ssr / dof);
  fit.iterations = iterations;
  fit.curve_evaluations = curves;
  if (tp.on_bound && fit.status == Status::Converged) {
    fit.status = Status::OnBound;
    fit.message = "stick-threshold " + tp.note;
    fit.warnings.push_back(fit.message);
  }
  return fit;
}

}  // namespace puncture::detail
