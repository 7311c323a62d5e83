// The inflation curve: states equally spaced in pole stretch from flat (the pre-stretch) to the
// burst (or a given pole stretch), with the pressure extrema and the burst.
#include <fmt/format.h>

#include "inflation/scaled_inflation.hpp"

namespace puncture {

InflationCurve inflation_curve(const InflationProblem& problem, const InflationCurveOptions& curve,
                               const SolverOptions& options) {
  validate(problem);
  detail::check_curve_options(problem, curve);
  InflationCurve out;
  out.burst = inflation_burst(problem, options);
  if (curve.max_pole_stretch > 0.0) {
    out.end_pole_stretch = curve.max_pole_stretch;
  } else if (out.burst.ok()) {
    out.end_pole_stretch = out.burst.state.pole_stretch;
  } else {
    out.status = out.burst.state.ok() ? Status::NoConvergence : out.burst.state.status;
    out.message = "the curve ends at the burst, which was not found: " + out.burst.message;
    return out;
  }
  SolverOptions inner = options;
  inner.record_fields = false;
  const int n = curve.points;
  const double flat = problem.prestretch;
  double guess = 0.0;
  for (int k = 0; k < n; ++k) {
    const double l0 =
        k == n - 1 ? out.end_pole_stretch : flat + (out.end_pole_stretch - flat) * k / (n - 1);
    auto s = detail::solve_inflation(problem, l0, inner, guess);
    if (!s.ok()) {
      out.status = s.status;
      out.message = fmt::format("the curve stopped at pole stretch {:g}: {}", l0, s.message);
      return out;
    }
    guess = s.pressure;
    out.states.push_back(detail::to_physical(problem, s));
    if (curve.progress) curve.progress(k + 1, n);
  }
  auto extrema = pressure_extrema(problem, out.end_pole_stretch, curve.scan_points, options);
  if (!extrema.ok()) {
    out.status = extrema.status;
    out.message = extrema.message;
    return out;
  }
  out.extrema = std::move(extrema.extrema);
  out.status = Status::Converged;
  return out;
}

}  // namespace puncture
