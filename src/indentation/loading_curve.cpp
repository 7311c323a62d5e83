// The public loading-curve functions: validation, then one dispatch to the shooting of the
// problem's law and indenter, which the driver (puncture_search.hpp, curve_following.hpp) uses
// for every solve.
#include "puncture/loading_curve.hpp"

#include <fmt/format.h>

#include <cmath>

#include "indentation/curve_events.hpp"
#include "indentation/curve_following.hpp"
#include "indentation/curve_to_fold.hpp"
#include "indentation/depth_solve.hpp"
#include "indentation/dispatch.hpp"
#include "indentation/face_slip.hpp"
#include "indentation/path_puncture.hpp"
#include "indentation/puncture_search.hpp"
#include "indentation/reported_failure.hpp"
#include "indentation/sealed_gas.hpp"
#include "indentation/snap_landing.hpp"

namespace puncture {

namespace {

SolverOptions without_fields(SolverOptions o) {
  o.record_fields = false;
  return o;
}

// A warm start is a stretch: finite and > 0 (one outside the corner solve's range is not used).
void check_warm_start(const SolverOptions& o) {
  if (const auto& start = o.puncture_top_stretch_start;
      start && !(std::isfinite(*start) && *start > 0.0))
    throw InvalidInput("puncture_top_stretch_start",
                       fmt::format("puncture_top_stretch_start: a stretch must be finite and > 0, "
                                   "got {}",
                                   *start));
}

// Under a gas pressure with friction the face's material must slide outward at the puncture,
// as the model's friction there assumes (indentation/face_slip.hpp).
PuncturePrediction with_face_slip_checked(const Problem& p, PuncturePrediction out) {
  if (!out.ok()) return out;
  if (const auto why = detail::inward_face_slip(p, out.depth_mm)) {
    out.status = Status::OutsideModel;
    out.message = "no puncture found where the model holds: " + *why;
  }
  return out;
}

// The first point of the curve from which the face slides outward (the curve's points slide
// inward first, then outward: a bisection on them), for a flat punch under a gas pressure with
// friction.
std::optional<double> face_outward_from(const Problem& p, const std::vector<CurvePoint>& points) {
  if (!detail::face_friction_direction_matters(p)) return std::nullopt;
  const auto outward = [&](std::size_t i) {
    return points[i].depth_mm > 0.0 && !detail::inward_face_slip(p, points[i].depth_mm);
  };
  std::size_t lo = 0, hi = points.size();  // outward from hi on (hi = size: nowhere)
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (outward(mid))
      hi = mid;
    else
      lo = mid + 1;
  }
  return hi < points.size() ? std::optional<double>(points[hi].depth_mm) : std::nullopt;
}

// The curve's events, each located by states solved at depths (the public solve: the same
// states as the curve's, a sealed chamber's included), and the verdict on which failure comes
// first (which needs the events: neither without CurveOptions::locate_events).
void add_events(const Problem& p, const CurveOptions& curve, const SolverOptions& options,
                LoadingCurve& out) {
  if (!out.ok() || !curve.locate_events) return;
  // (Under the coulomb rule the partial-slip family is built once for all the samples.)
  detail::with_depth_solve(p, without_fields(options), [&](const detail::DepthSolve& solve) {
    const detail::DepthSampler at_depth = [&](double depth_mm,
                                              Stage stage) -> std::optional<detail::DepthSample> {
      const Equilibrium e = solve(depth_mm, stage);
      if (!e.ok()) return std::nullopt;
      return detail::DepthSample{e.force_n, e.contact_edge_radius_mm + e.contact_edge_height_mm};
    };
    out.events = detail::located_curve_events(out.points, at_depth);
  });
  out.failure_verdict = detail::failure_verdict(p, out);
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

namespace detail {

PuncturePrediction puncture_on_path(const Problem& p, const SolverOptions& options,
                                    bool face_slip_checked) {
  return reporting_failures<PuncturePrediction>([&] {
    return with_shooting(p, without_fields(options), [&](const auto& shooting) {
      bool at_switch = false;
      const auto switch_point = locate_switch(p, shooting);
      auto puncture = find_puncture(p, options, shooting, switch_point, at_switch);
      if (face_slip_checked) puncture = with_face_slip_checked(p, std::move(puncture));
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

// A later inflated state whose path folds before any puncture (the puncture search's
// limit_load there): the puncture under depth control, as the loading curve's, the first
// state's after the snap-through (snap_landing.hpp); empty where the path has no fold.
std::optional<PuncturePrediction> puncture_past_fold(const Problem& p,
                                                     const SolverOptions& options) {
  std::optional<CurveEvent> snap;
  std::optional<double> fold_work;  // the work to the fold [mJ], when asked
  with_shooting(p, without_fields(options), [&](const auto& shooting) {
    const auto branch = fold_of_depth_path(shooting);
    if (!branch) return;
    snap = snap_event_at_fold(p, shooting, *branch);
    if (options.energy_to_puncture)
      fold_work = work_to_fold_mj(p, shooting, options.curve_tol, *branch);
  });
  if (!snap) return std::nullopt;
  const SnapLanding landing = snap_landing(p, options, *snap);
  PuncturePrediction out;
  if (!landing.ok()) {
    out.status = landing.status;
    out.message = landing.message;
    return out;
  }
  Problem first = p;
  first.preload.inflated_state = 1;
  SolverOptions alone = options;
  alone.failure_verdict = false;  // the later state's verdict is its own curve's
  out = predict_puncture(first, alone);
  puncture_past_snap(landing, *snap, fold_work, out);
  return out;
}

}  // namespace detail

namespace {

// The loading curve's verdict (SolverOptions::failure_verdict): the curve to puncture on the
// default grid, its events located, so the prediction's verdict is the curve's to the last bit.
void add_failure_verdict(const Problem& p, const SolverOptions& options, PuncturePrediction& out) {
  if (!options.failure_verdict || !out.ok() || !detail::pretensioned(p)) return;
  SolverOptions along = options;
  along.energy_to_puncture = false;
  along.failure_verdict = false;
  const LoadingCurve curve = loading_curve(p, CurveOptions{}, along);
  if (curve.ok()) {
    out.failure_verdict = curve.failure_verdict;
    return;
  }
  // No verdict is not a silent one: the prediction says why (as for the energy to puncture).
  out.message += (out.message.empty() ? "" : "; ") +
                 fmt::format(
                     "no verdict on which failure comes first: the loading curve failed "
                     "({}): {}",
                     to_string(curve.status),
                     curve.message);
}

}  // namespace

PuncturePrediction predict_puncture(const Problem& p, const SolverOptions& options) {
  validate(p);
  check_warm_start(options);
  PuncturePrediction out =
      !p.preload.gas_volume_mm3
          ? detail::puncture_on_path(p, options, true)
          : with_face_slip_checked(p, detail::reporting_failures<PuncturePrediction>([&] {
                                     return detail::sealed_puncture(p, options);
                                   }));
  if (out.status == Status::LimitLoad && !p.preload.gas_volume_mm3 && p.preload.inflated_state != 1)
    out = detail::reporting_failures<PuncturePrediction>([&] {
      auto past = detail::puncture_past_fold(p, options);
      return past ? std::move(*past) : out;
    });
  add_failure_verdict(p, options, out);
  return out;
}

LoadingCurve loading_curve(const Problem& p, const CurveOptions& curve,
                           const SolverOptions& options) {
  validate(p);
  check_warm_start(options);
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
  if (p.preload.gas_volume_mm3)
    return detail::reporting_failures<LoadingCurve>([&] {
      auto out = detail::sealed_loading_curve(p, curve, options);
      out.puncture = with_face_slip_checked(p, std::move(out.puncture));
      out.face_slides_outward_from_mm = face_outward_from(p, out.points);
      add_events(p, curve, options, out);
      return out;
    });
  return detail::reporting_failures<LoadingCurve>([&] {
    // Where a later inflated state's path turns back before the puncture: the snap-through.
    std::optional<CurveEvent> snap;
    std::vector<double> after_snap;   // the curve's depths past it (to max_depth_mm)
    std::optional<double> fold_work;  // the work to the fold [mJ], when asked
    auto out = detail::with_shooting(p, without_fields(options), [&](const auto& shooting) {
      auto followed = detail::curve_to_puncture(p, shooting, curve, options);
      if (!followed.ok() && followed.puncture.status == Status::LimitLoad) {
        LoadingCurve to_fold;
        to_fold.puncture = followed.puncture;
        snap = detail::curve_to_fold(p, shooting, curve, options, to_fold, after_snap, fold_work);
        if (snap) {
          to_fold.status = Status::Converged;
          return to_fold;
        }
      }
      followed.puncture = with_face_slip_checked(p, std::move(followed.puncture));
      followed.face_slides_outward_from_mm = face_outward_from(p, followed.points);
      return followed;
    });
    add_events(p, curve, options, out);
    if (snap) {
      out.events.push_back(*snap);
      detail::land_after_snap(p, curve, options, after_snap, fold_work, out);
    }
    return out;
  });
}

}  // namespace puncture
