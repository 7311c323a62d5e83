// The landing of a snap-through at a fold of the depth and the curve from it
// (snap_landing.hpp; docs/model.md §8.1, "Following a fold").
#include "indentation/snap_landing.hpp"

#include <fmt/format.h>

#include <string>

#include "indentation/curve_events.hpp"
#include "indentation/curve_point_from_equilibrium.hpp"
#include "indentation/inflated_dome.hpp"
#include "indentation/solver_scales.hpp"
#include "puncture/equilibrium.hpp"

namespace puncture::detail {

namespace {

std::string landing_num(double x) { return fmt::format("{:.6g}", x); }

SolverOptions landing_quiet(SolverOptions o) {
  o.record_fields = false;
  return o;
}

Problem first_inflated_state(const Problem& p) {
  Problem first = p;
  first.preload.inflated_state = 1;
  return first;
}

}  // namespace

SnapLanding snap_landing(const Problem& p, const SolverOptions& options, CurveEvent& snap) {
  const double fold_mm = snap.depth_mm, force_before = snap.force_n;
  const Problem first = first_inflated_state(p);
  const SolverOptions quiet = landing_quiet(options);
  const auto later_dome = inflated_dome(p, quiet), first_dome = inflated_dome(first, quiet);
  SnapLanding out;
  out.offset_mm = (later_dome->height - first_dome->height) * solver_scales(p).length_mm;
  out.landing_depth_mm = fold_mm - out.offset_mm;
  if (out.landing_depth_mm > 0.0) {
    const Equilibrium e = solve_at_depth(first, out.landing_depth_mm, Stage::Slip, quiet);
    if (!e.ok()) {
      out.status = e.status;
      out.message = fmt::format(
          "the membrane snaps through at the fold of the depth, {} mm ({} N), where no state of "
          "the first inflated state is found at its depth {} mm: {}",
          landing_num(fold_mm),
          landing_num(force_before),
          landing_num(out.landing_depth_mm),
          e.message);
      return out;
    }
    out.point = curve_point_from_equilibrium(e, fold_mm);
  }
  const bool clear = out.landing_depth_mm <= 0.0;
  snap.force_after_n = clear ? 0.0 : out.point.force_n;
  if (clear) snap.end_depth_mm = out.offset_mm;
  snap.description = fmt::format(
      "the depth turns back at {} mm (within {} mm) at {} N: a fold of the path of the later "
      "inflated state, whose branch beyond it (followed by arc length) carries more force at "
      "smaller depths; under depth control the membrane snaps through there to the first "
      "inflated state at the same probe position, {}; under force control the path passes the "
      "fold (the force keeps rising)",
      landing_num(fold_mm),
      landing_num(snap.depth_uncertainty_mm),
      landing_num(force_before),
      clear ? fmt::format("whose pole lies {} mm below the probe's tip: the probe leaves the "
                          "membrane (the force drops to 0) and touches it again at depth {} mm",
                          landing_num(-out.landing_depth_mm),
                          landing_num(out.offset_mm))
            : fmt::format("indented {} mm: the force drops to {} N",
                          landing_num(out.landing_depth_mm),
                          landing_num(out.point.force_n)));
  if (clear) {
    const Equilibrium free_dome = solve_at_depth(first, 0.0, Stage::Slip, quiet);
    if (!free_dome.ok()) {
      out.status = free_dome.status;
      out.message = fmt::format(
          "{}; the first inflated state's dome: {}", snap.description, free_dome.message);
      return out;
    }
    out.point = curve_point_from_equilibrium(free_dome, fold_mm);  // clear of the probe
  }
  out.point.depth_mm = fold_mm;
  out.status = Status::Converged;
  return out;
}

void puncture_past_snap(const SnapLanding& landing, const CurveEvent& snap,
                        const std::optional<double>& fold_work, PuncturePrediction& first) {
  if (!first.ok()) {
    first.message = fmt::format(
        "under depth control the membrane snaps through at {} mm onto the first inflated state, "
        "where no puncture is found: {}",
        landing_num(snap.depth_mm),
        first.message);
    return;
  }
  first.depth_mm += landing.offset_mm;
  first.state.depth_mm += landing.offset_mm;
  first.snap_through = snap;
  std::string energy;
  if (first.energy_to_puncture_mj) {
    if (fold_work && landing.landing_depth_mm <= 0.0) {
      energy = fmt::format(
          "; the energy to puncture is the work to the fold, {} mJ, plus the first state's from "
          "the probe's next touch (the force is 0 in between; the drop at the snap-through is "
          "dissipated, not the probe's work)",
          landing_num(*fold_work));
      *first.energy_to_puncture_mj += *fold_work;
    } else {
      energy = fold_work ? "; the energy to puncture is not integrated across a snap-through "
                           "onto an indented state"
                         : "; no energy to puncture: the path to the fold is not followed at "
                           "the quadrature's depths";
      first.energy_to_puncture_mj.reset();
    }
  }
  first.message = fmt::format(
      "under depth control, on the first inflated state after the snap-through at {} mm (depths "
      "from the later state's pole; the first state's pole {} mm lower){}{}{}",
      landing_num(snap.depth_mm),
      landing_num(landing.offset_mm),
      energy,
      first.message.empty() ? "" : "; ",
      first.message);
}

void land_after_snap(const Problem& p, const CurveOptions& curve, const SolverOptions& options,
                     const std::vector<double>& after, const std::optional<double>& fold_work,
                     LoadingCurve& out) {
  const std::size_t at = out.events.size() - 1;  // the SnapThrough
  const SnapLanding landing = snap_landing(p, options, out.events[at]);
  if (!landing.ok()) {
    out.status = landing.status;
    out.message = landing.message;
    return;
  }
  const double fold_mm = out.events[at].depth_mm, offset = landing.offset_mm;
  const Problem first = first_inflated_state(p);
  CurveOptions rest_options;
  rest_options.points = curve.points;
  rest_options.locate_events = curve.locate_events;
  // To max_depth_mm: the grid's depths past the fold where the probe touches the first state
  // (those short of it are the free dome's, at force 0).
  for (const double d : after)
    if (d > offset) rest_options.depths_mm.push_back(d - offset);
  // Nothing of the first state's curve when every depth past the fold leaves the probe clear.
  const bool touches = after.empty() || !rest_options.depths_mm.empty();
  const LoadingCurve rest = touches ? loading_curve(first, rest_options, options) : LoadingCurve{};
  if (touches && !rest.ok()) {
    out.status = rest.status;
    out.message = fmt::format("{}; the first inflated state's curve from there fails: {}",
                              out.events[at].description,
                              rest.message);
    return;
  }
  out.points.push_back(landing.point);
  for (const double d : after)
    if (d <= offset) {  // the probe above the first state's pole
      CurvePoint clear = landing.point;
      clear.depth_mm = d;
      out.points.push_back(clear);
    }
  for (CurvePoint pt : rest.points) {
    pt.depth_mm += offset;
    if (pt.depth_mm > fold_mm) out.points.push_back(pt);
  }
  out.status = Status::Converged;
  out.message.clear();
  for (CurveEvent e : rest.events) {
    e.depth_mm += offset;
    if (e.end_depth_mm) *e.end_depth_mm += offset;
    out.events.push_back(e);
  }
  if (rest.part_two_onset_depth_mm) {
    out.part_two_onset_depth_mm = *rest.part_two_onset_depth_mm + offset;
    out.part_two_onset_force_n = rest.part_two_onset_force_n;
  }
  // The puncture under depth control: the first state's, also where the curve's depths end
  // before the probe touches it again (as a curve to max_depth_mm gives its puncture beyond).
  if (touches) {
    out.puncture = rest.puncture;
  } else {
    SolverOptions alone = options;
    alone.failure_verdict = false;
    out.puncture = predict_puncture(first, alone);
  }
  puncture_past_snap(landing, out.events[at], fold_work, out.puncture);
  out.failure_verdict = failure_verdict(p, out);
}

}  // namespace puncture::detail
