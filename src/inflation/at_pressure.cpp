// Every inflated state at a given pressure: the pressure is monotone between its extrema, so
// each monotone piece of the curve holds at most one state, found by TOMS 748 on the pole
// stretch.
#include <fmt/format.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "inflation/scaled_inflation.hpp"

namespace puncture {

InflationAtPressure inflate_at_pressure(const InflationProblem& problem, double pressure_mpa,
                                        const InflationCurveOptions& range,
                                        const SolverOptions& options) {
  validate(problem);
  detail::check_curve_options(problem, range);
  if (!std::isfinite(pressure_mpa) || pressure_mpa < 0.0)
    throw InvalidInput(
        "pressure_mpa",
        fmt::format("pressure must be a finite number >= 0 MPa, got {}", pressure_mpa));
  InflationAtPressure out;
  out.pressure_mpa = pressure_mpa;
  const double flat = problem.prestretch;
  if (pressure_mpa == 0.0) {
    out.states.push_back(
        detail::to_physical(problem, detail::solve_inflation(problem, flat, options)));
    out.status = Status::Converged;
    return out;
  }
  // The range: to the burst unless a pole stretch is given.
  if (range.max_pole_stretch > 0.0) {
    out.max_pole_stretch = range.max_pole_stretch;
  } else {
    const auto burst = inflation_burst(problem, options);
    if (!burst.ok()) {
      out.status = burst.state.ok() ? Status::NoConvergence : burst.state.status;
      out.message = "the search range ends at the burst, which was not found: " + burst.message;
      return out;
    }
    out.max_pole_stretch = burst.state.pole_stretch;
  }
  auto extrema = pressure_extrema(problem, out.max_pole_stretch, range.scan_points, options);
  if (!extrema.ok()) {
    out.status = extrema.status;
    out.message = extrema.message;
    return out;
  }
  out.extrema = extrema.extrema;

  // In the solver's pressure unit (G H / (A / L0)).
  const double scale = detail::solver_pressure_scale_mpa(problem);
  const double target = pressure_mpa / scale;
  SolverOptions inner = options;
  inner.record_fields = false;
  double guess = 0.0;
  std::optional<detail::ScaledInflation> failure;
  auto pressure_at = [&](double l0) -> double {
    auto s = detail::solve_inflation(problem, l0, inner, guess);
    if (!s.ok()) {
      failure = s;
      return 0.0;
    }
    guess = s.pressure;
    return s.pressure;
  };
  // The monotone pieces: [L0, first extremum], ..., [last extremum, end].
  std::vector<double> ends{flat};
  std::vector<double> values{0.0};
  for (const auto& e : out.extrema) {
    ends.push_back(e.state.pole_stretch);
    values.push_back(e.state.normalized_pressure / flat);  // P A / (G H) in the solver's unit
  }
  ends.push_back(out.max_pole_stretch);
  values.push_back(pressure_at(out.max_pole_stretch));
  double highest = 0.0, highest_at = flat;
  for (std::size_t k = 1; k < ends.size(); ++k) {
    if (failure) break;
    if (values[k] > highest) {
      highest = values[k];
      highest_at = ends[k];
    }
    const double g_lo = values[k - 1] - target, g_hi = values[k] - target;
    if (g_lo * g_hi > 0.0) continue;
    double at = g_hi == 0.0 ? ends[k] : ends[k - 1];
    if (g_lo != 0.0 && g_hi != 0.0) {
      std::uintmax_t iterations = 100;
      const auto bracket =
          boost::math::tools::toms748_solve([&](double l0) { return pressure_at(l0) - target; },
                                            ends[k - 1],
                                            ends[k],
                                            g_lo,
                                            g_hi,
                                            boost::math::tools::eps_tolerance<double>(45),
                                            iterations);
      at = 0.5 * (bracket.first + bracket.second);
    }
    if (failure) break;
    // A pressure equal to an extremum's ends two pieces: keep it once.
    if (!out.states.empty() && std::abs(out.states.back().pole_stretch - at) <= 1e-9 * at) continue;
    auto s = detail::to_physical(problem, detail::solve_inflation(problem, at, options, guess));
    if (!s.ok()) {
      out.status = s.status;
      out.message = fmt::format("the state at pole stretch {:g} failed: {}", at, s.message);
      return out;
    }
    out.states.push_back(std::move(s));
  }
  if (failure) {
    out.status = failure->status;
    out.message = "the solver failed while searching the pressure: " + failure->message;
    return out;
  }
  out.status = out.states.empty() ? Status::NotReached : Status::Converged;
  if (out.states.empty())
    out.message = fmt::format(
        "no state with pole stretch up to {:.6g} carries {:g} MPa: the highest pressure in that "
        "range is {:.6g} MPa, at pole stretch {:.6g}{}",
        out.max_pole_stretch,
        pressure_mpa,
        highest * scale,
        highest_at,
        range.max_pole_stretch > 0.0 ? "" : " (the range ends at the burst)");
  else if (out.states.size() > 1)
    out.message = fmt::format(
        "{} states carry this pressure; the first is reached by inflating slowly from flat",
        out.states.size());
  return out;
}

}  // namespace puncture
