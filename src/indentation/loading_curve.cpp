// The public loading-curve functions: validation, then one dispatch to the shooting of the
// problem's law and indenter, which the driver (puncture_search.hpp, curve_following.hpp) uses
// for every solve.
#include "puncture/loading_curve.hpp"

#include <fmt/format.h>

#include <cmath>

#include "indentation/curve_following.hpp"
#include "indentation/dispatch.hpp"
#include "indentation/puncture_search.hpp"
#include "indentation/reported_failure.hpp"

namespace puncture {

namespace {

SolverOptions without_fields(SolverOptions o) {
  o.record_fields = false;
  return o;
}

}  // namespace

StageBoundary stick_slip_boundary(const Problem& p, const SolverOptions& options) {
  validate(p);
  return detail::reporting_failures<StageBoundary>([&] {
    return detail::with_shooting(p, without_fields(options), [&](const auto& shooting) {
      return detail::locate_switch(p, shooting).boundary;
    });
  });
}

PuncturePrediction predict_puncture(const Problem& p, const SolverOptions& options) {
  validate(p);
  return detail::reporting_failures<PuncturePrediction>([&] {
    return detail::with_shooting(p, without_fields(options), [&](const auto& shooting) {
      bool at_switch = false;
      const auto switch_point = detail::locate_switch(p, shooting);
      auto puncture = detail::find_puncture(p, options, shooting, switch_point, at_switch);
      if (options.energy_to_puncture && puncture.ok()) {
        const auto& boundary = switch_point.boundary;
        detail::add_energy_to_puncture(
            p,
            shooting,
            options.curve_tol,
            boundary,
            detail::sliding_change(shooting, boundary, detail::solver_scales(p).length_mm),
            at_switch,
            puncture);
      }
      return puncture;
    });
  });
}

LoadingCurve loading_curve(const Problem& p, const CurveOptions& curve,
                           const SolverOptions& options) {
  validate(p);
  if (curve.points < 2)
    throw InvalidInput("points",
                       fmt::format("the curve needs at least 2 points, got {}", curve.points));
  for (std::size_t i = 0; i < curve.depths_mm.size(); ++i) {
    const double d = curve.depths_mm[i];
    if (!std::isfinite(d) || d <= 0.0 || (i > 0 && !(d > curve.depths_mm[i - 1])))
      throw InvalidInput("depths_mm",
                         fmt::format("the curve's depths must be finite, > 0 mm and strictly "
                                     "increasing; depth {} is {} mm",
                                     i + 1,
                                     d));
  }
  return detail::reporting_failures<LoadingCurve>([&] {
    return detail::with_shooting(p, without_fields(options), [&](const auto& shooting) {
      return detail::curve_to_puncture(p, shooting, curve, options);
    });
  });
}

}  // namespace puncture
