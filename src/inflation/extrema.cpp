// Local maxima (limit points) and minima of the pressure along the inflation curve: a scan in
// pole stretch, then a root of dp/dlambda0 in each bracket by TOMS 748.
#include <fmt/format.h>

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>

#include "inflation/scaled_inflation.hpp"

namespace puncture {

namespace detail {

SolverOptions differencing_options(const SolverOptions& options) {
  SolverOptions o = options;
  o.integration_rel_tol = std::min(options.integration_rel_tol, 1e-12);
  o.integration_abs_tol = std::min(options.integration_abs_tol, 1e-14);
  o.shooting_tol = std::min(options.shooting_tol, 1e-11);
  o.record_fields = false;
  return o;
}

void check_curve_options(const InflationProblem& problem, const InflationCurveOptions& curve) {
  if (curve.points < 2 || curve.points > 100000)
    throw InvalidInput(
        "points", fmt::format("points must be in the range 2 to 100000, got {}", curve.points));
  if (curve.scan_points < 8 || curve.scan_points > 100000)
    throw InvalidInput(
        "scan_points",
        fmt::format("scan points must be in the range 8 to 100000, got {}", curve.scan_points));
  const double m = curve.max_pole_stretch;
  const double lock = locking_pole_stretch(problem.material.law);
  const double flat = problem.prestretch;
  if (m != 0.0 && (!std::isfinite(m) || m <= flat))
    throw InvalidInput("max_pole_stretch",
                       fmt::format("max pole stretch must be 0 (to the burst) or a finite number "
                                   "> {:g} (the flat state's), got {}",
                                   flat,
                                   m));
  if (m != 0.0 && m >= lock)
    throw InvalidInput(
        "max_pole_stretch",
        fmt::format(
            "max pole stretch must be below the pole stretch at which the {} law locks ({:.6g}), "
            "got {}",
            locking_limit_words(problem.material.law).first,
            lock,
            m));
}

namespace {

// Normalised pressure P(l0), or empty when the solver fails there.
class PressureOfStretch {
 public:
  PressureOfStretch(const InflationProblem& problem, const SolverOptions& options)
      : problem_(problem), o_(differencing_options(options)) {}

  std::optional<double> operator()(double l0) {
    const auto s = solve_inflation(problem_, l0, o_, guess_);
    if (!s.ok()) {
      failure_ = s;
      return std::nullopt;
    }
    guess_ = s.pressure;
    return s.pressure;
  }
  const ScaledInflation& failure() const { return failure_; }

 private:
  const InflationProblem& problem_;
  SolverOptions o_;
  double guess_ = 0.0;
  ScaledInflation failure_;
};

struct FailedSolve {
  ScaledInflation solution;
};

// dP/dl0 by the four-point central difference with step h (error ~ h^4 P^(5) / 30).
double slope(PressureOfStretch& pressure, double l0, double h) {
  double p[4];
  const double at[4] = {l0 - 2.0 * h, l0 - h, l0 + h, l0 + 2.0 * h};
  for (int k = 0; k < 4; ++k) {
    const auto v = pressure(at[k]);
    if (!v) throw FailedSolve{pressure.failure()};
    p[k] = *v;
  }
  return (p[0] - 8.0 * p[1] + 8.0 * p[2] - p[3]) / (12.0 * h);
}

double second_derivative(PressureOfStretch& pressure, double l0, double h) {
  const auto a = pressure(l0 - h), b = pressure(l0), c = pressure(l0 + h);
  if (!a || !b || !c) throw FailedSolve{pressure.failure()};
  return (*a - 2.0 * *b + *c) / (h * h);
}

// The same from pole stretches at or below l0 only, for the end of the range (which may lie
// just below the locking stretch): the five-point backward difference of dP/dl0 (error
// ~ h^4 P^(5) / 5) and the four-point one of d2P/dl0^2 (error ~ h^2 P^(4) 11 / 12).
double backward_slope(PressureOfStretch& pressure, double l0, double h) {
  constexpr double weights[5] = {25.0, -48.0, 36.0, -16.0, 3.0};
  double sum = 0.0;
  for (int k = 0; k < 5; ++k) {
    const auto v = pressure(l0 - k * h);
    if (!v) throw FailedSolve{pressure.failure()};
    sum += weights[k] * *v;
  }
  return sum / (12.0 * h);
}

double backward_second_derivative(PressureOfStretch& pressure, double l0, double h) {
  constexpr double weights[4] = {2.0, -5.0, 4.0, -1.0};
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) {
    const auto v = pressure(l0 - k * h);
    if (!v) throw FailedSolve{pressure.failure()};
    sum += weights[k] * *v;
  }
  return sum / (h * h);
}

}  // namespace

}  // namespace detail

PressureExtrema pressure_extrema(const InflationProblem& problem, double max_pole_stretch,
                                 int scan_points, const SolverOptions& options) {
  validate(problem);
  InflationCurveOptions check;
  check.max_pole_stretch = max_pole_stretch;
  check.scan_points = scan_points;
  if (max_pole_stretch == 0.0)
    throw InvalidInput("max_pole_stretch", "max pole stretch must be a finite number > 1, got 0");
  detail::check_curve_options(problem, check);

  PressureExtrema out;
  detail::PressureOfStretch pressure(problem, options);
  // The scan: P(L0) = 0 at the flat state, then equally spaced pole stretches.
  const int n = scan_points;
  const double flat = problem.prestretch;
  std::vector<double> l(n + 1), p(n + 1);
  l[0] = flat;
  p[0] = 0.0;
  for (int i = 1; i <= n; ++i) {
    l[i] = flat + (max_pole_stretch - flat) * i / n;
    const auto v = pressure(l[i]);
    if (!v) {
      out.status = pressure.failure().status;
      out.message = fmt::format(
          "the pressure scan failed at pole stretch {:g}: {}", l[i], pressure.failure().message);
      return out;
    }
    p[i] = *v;
  }
  const double scale = detail::solver_pressure_scale_mpa(problem);
  // The extremum at pole stretch `at` (its state started from the scanned pressure `guess`);
  // false, with `out` saying why, when that state cannot be solved.
  auto record = [&](ExtremumKind kind, double at, double slope, double curvature, double guess) {
    PressureExtremum e;
    e.kind = kind;
    e.pressure_slope_mpa = scale * slope;
    e.curvature_mpa = scale * curvature;
    e.state = detail::to_physical(problem, detail::solve_inflation(problem, at, options, guess));
    if (!e.state.ok()) {
      out.status = e.state.status;
      out.message = fmt::format(
          "the extremum at pole stretch {:g} could not be solved: {}", at, e.state.message);
      return false;
    }
    out.extrema.push_back(std::move(e));
    return true;
  };
  try {
    for (int i = 1; i < n; ++i) {
      const double left = p[i] - p[i - 1], right = p[i + 1] - p[i];
      if (!(left * right < 0.0)) continue;
      // The derivative's step: fine against the bracket, and clear of the flat state.
      const double h = std::min(0.25 * (l[i] - l[i - 1]), 0.2 * (l[i - 1] - flat));
      auto d = [&](double x) { return detail::slope(pressure, x, h); };
      double lo = l[i - 1], hi = l[i + 1];
      double d_lo = d(lo), d_mid = d(l[i]), d_hi = d(hi);
      if (d_lo * d_mid <= 0.0) {
        hi = l[i];
        d_hi = d_mid;
      } else if (d_mid * d_hi <= 0.0) {
        lo = l[i];
        d_lo = d_mid;
      } else {
        continue;  // two extrema within one scan step cancelled out: the scan is too coarse
      }
      double at = d_lo == 0.0 ? lo : hi;
      if (d_lo != 0.0 && d_hi != 0.0) {
        std::uintmax_t iterations = 60;
        const auto bracket = boost::math::tools::toms748_solve(
            d, lo, hi, d_lo, d_hi, boost::math::tools::eps_tolerance<double>(40), iterations);
        at = 0.5 * (bracket.first + bracket.second);
      }
      if (!record(left > 0.0 ? ExtremumKind::Maximum : ExtremumKind::Minimum,
                  at,
                  d(at),
                  detail::second_derivative(pressure, at, h),
                  p[i]))
        return out;
    }
    // An extremum inside the last interval, [l[n-1], l[n]], changes no sign of the scanned
    // differences when the pressure at the end is still on the same side as at l[n-1] (a
    // maximum just before the end): the slope at the end shows it.  Backward differences
    // throughout this interval, so that nothing beyond the range's end is solved; their error
    // is six times the central difference's at the same step, so the step is a quarter of the
    // central one (the error then 40 times smaller; the solves' 1e-12 noise, amplified by
    // ~10 / h, stays far below it).
    const double last = p[n] - p[n - 1];
    const double h = 0.25 * std::min(0.25 * (l[n] - l[n - 1]), 0.2 * (l[n - 1] - flat));
    auto d = [&](double x) { return detail::backward_slope(pressure, x, h); };
    if (double d_hi = d(l[n]); last * d_hi < 0.0) {
      double lo = l[n - 1], hi = l[n];
      double d_lo = d(lo);
      if (d_lo * d_hi < 0.0) {  // else two extrema within the interval cancelled out
        std::uintmax_t iterations = 60;
        const auto bracket = boost::math::tools::toms748_solve(
            d, lo, hi, d_lo, d_hi, boost::math::tools::eps_tolerance<double>(40), iterations);
        const double at = 0.5 * (bracket.first + bracket.second);
        if (!record(last > 0.0 ? ExtremumKind::Maximum : ExtremumKind::Minimum,
                    at,
                    d(at),
                    detail::backward_second_derivative(pressure, at, h),
                    p[n]))
          return out;
      }
    }
  } catch (const detail::FailedSolve& f) {
    out.status = f.solution.status;
    out.message = "a pressure extremum could not be located: " + f.solution.message;
    return out;
  }
  out.status = Status::Converged;
  return out;
}

}  // namespace puncture
