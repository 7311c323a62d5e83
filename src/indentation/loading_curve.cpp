// The public loading-curve functions: validation, then one dispatch to the shooting of the
// problem's law and indenter, which the driver (puncture_search.hpp, curve_following.hpp) uses
// for every solve.
#include "puncture/loading_curve.hpp"

#include <fmt/format.h>

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
  return detail::reporting_failures<StageBoundary>([&] {
    StageBoundary b;
    if (const auto errors = validation_errors(p); !errors.empty()) {
      b.status = Status::InvalidInput;
      b.message = errors.front().message;
      return b;
    }
    return detail::with_shooting(p, without_fields(options), [&](const auto& shooting) {
      return detail::locate_switch(p, shooting).boundary;
    });
  });
}

PuncturePrediction predict_puncture(const Problem& p, const SolverOptions& options) {
  return detail::reporting_failures<PuncturePrediction>([&] {
    PuncturePrediction out;
    if (const auto errors = validation_errors(p); !errors.empty()) {
      out.message = errors.front().message;
      return out;
    }
    return detail::with_shooting(p, without_fields(options), [&](const auto& shooting) {
      bool at_switch = false;
      return detail::find_puncture(
          p, options, shooting, detail::locate_switch(p, shooting), at_switch);
    });
  });
}

LoadingCurve loading_curve(const Problem& p, const CurveOptions& curve,
                           const SolverOptions& options) {
  return detail::reporting_failures<LoadingCurve>([&] {
    LoadingCurve out;
    if (const auto errors = validation_errors(p); !errors.empty()) {
      out.status = Status::InvalidInput;
      out.message = errors.front().message;
      return out;
    }
    if (curve.points < 2) {
      out.status = Status::InvalidInput;
      out.message = fmt::format("the curve needs at least 2 points, got {}", curve.points);
      return out;
    }
    return detail::with_shooting(p, without_fields(options), [&](const auto& shooting) {
      return detail::curve_to_puncture(p, shooting, curve, options);
    });
  });
}

}  // namespace puncture
