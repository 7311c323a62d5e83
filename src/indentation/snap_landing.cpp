// The landing of a snap-through at a fold of the depth and the curve from it
// (snap_landing.hpp; docs/model.md §8.1, "Following a fold").
#include "indentation/snap_landing.hpp"

#include <fmt/format.h>

#include <string>

#include "indentation/curve_events.hpp"
#include "indentation/curve_point_of.hpp"
#include "indentation/inflated_dome.hpp"
#include "indentation/solver_scales.hpp"
#include "puncture/equilibrium.hpp"

namespace puncture::detail {

namespace {

std::string landing_num(double x) { return fmt::format("{:.6g}", x); }

}  // namespace

void land_after_snap(const Problem& p, const CurveOptions& curve, const SolverOptions& options,
                     const std::vector<double>& after, LoadingCurve& out) {
  const std::size_t at = out.events.size() - 1;  // the SnapThrough
  const double fold_mm = out.events[at].depth_mm, force_before = out.events[at].force_n;
  Problem first = p;
  first.preload.inflated_state = 1;
  SolverOptions quiet = options;
  quiet.record_fields = false;
  const auto later_dome = inflated_dome(p, quiet), first_dome = inflated_dome(first, quiet);
  const double length_mm = solver_scales(p).length_mm;
  // How far the first state's pole lies below the later state's: the probe touches it that
  // much deeper than the later state's pole [mm].
  const double offset = (later_dome->height - first_dome->height) * length_mm;
  const double landing_depth = fold_mm - offset;  // on the first state [mm]
  CurvePoint landing;
  if (landing_depth > 0.0) {
    const Equilibrium e = solve_at_depth(first, landing_depth, Stage::Slip, quiet);
    if (!e.ok()) {
      out.status = e.status;
      out.message = fmt::format(
          "the membrane snaps through at the fold of the depth, {} mm ({} N), where no state of "
          "the first inflated state is found at its depth {} mm: {}",
          landing_num(fold_mm),
          landing_num(force_before),
          landing_num(landing_depth),
          e.message);
      return;
    }
    landing = curve_point_of(e, fold_mm);
  }
  CurveOptions rest_options;
  rest_options.points = curve.points;
  rest_options.locate_events = curve.locate_events;
  // To max_depth_mm: the grid's depths past the fold where the probe touches the first state
  // (those short of it are the free dome's, at force 0).
  for (const double d : after)
    if (d > offset) rest_options.depths_mm.push_back(d - offset);
  // Nothing of the first state's curve when every depth past the fold leaves the probe clear.
  const bool touches = after.empty() || !rest_options.depths_mm.empty();
  const Equilibrium free_dome = solve_at_depth(first, 0.0, Stage::Slip, quiet);
  const LoadingCurve rest = touches ? loading_curve(first, rest_options, options) : LoadingCurve{};
  CurveEvent& snap = out.events[at];
  snap.force_after_n = landing_depth > 0.0 ? landing.force_n : 0.0;
  if (landing_depth <= 0.0) snap.end_depth_mm = offset;
  snap.description = fmt::format(
      "the depth turns back at {} mm (within {} mm) at {} N: a fold of the path of the later "
      "inflated state, whose branch beyond it (followed by arc length) carries more force at "
      "smaller depths; under depth control the membrane snaps through there to the first "
      "inflated state at the same probe position, {}; under force control the path passes the "
      "fold (the force keeps rising)",
      landing_num(fold_mm),
      landing_num(snap.depth_uncertainty_mm),
      landing_num(force_before),
      landing_depth <= 0.0
          ? fmt::format("whose pole lies {} mm below the probe's tip: the probe leaves the "
                        "membrane (the force drops to 0) and touches it again at depth {} mm",
                        landing_num(-landing_depth),
                        landing_num(offset))
          : fmt::format("indented {} mm: the force drops to {} N",
                        landing_num(landing_depth),
                        landing_num(landing.force_n)));
  if (touches && !rest.ok()) {
    out.status = rest.status;
    out.message = fmt::format("{}; the first inflated state's curve from there fails: {}",
                              snap.description,
                              rest.message);
    return;
  }
  if (landing_depth <= 0.0) {
    if (!free_dome.ok()) {
      out.status = free_dome.status;
      out.message = fmt::format(
          "{}; the first inflated state's dome: {}", snap.description, free_dome.message);
      return;
    }
    landing = curve_point_of(free_dome, fold_mm);  // clear of the probe
  }
  landing.depth_mm = fold_mm;
  out.points.push_back(landing);
  for (const double d : after)
    if (d <= offset) {  // the probe above the first state's pole
      CurvePoint clear = landing;
      clear.depth_mm = d;
      out.points.push_back(clear);
    }
  for (CurvePoint pt : rest.points) {
    pt.depth_mm += offset;
    if (pt.depth_mm > fold_mm) out.points.push_back(pt);
  }
  out.failure_verdict = failure_verdict(p, out);
  out.status = Status::Converged;
  out.message.clear();
  if (!touches) return;  // the puncture search's answer stays
  for (CurveEvent e : rest.events) {
    e.depth_mm += offset;
    if (e.end_depth_mm) *e.end_depth_mm += offset;
    out.events.push_back(e);
  }
  if (rest.part_two_onset_depth_mm) {
    out.part_two_onset_depth_mm = *rest.part_two_onset_depth_mm + offset;
    out.part_two_onset_force_n = rest.part_two_onset_force_n;
  }
  out.puncture = rest.puncture;
  if (out.puncture.ok()) {
    out.puncture.depth_mm += offset;
    out.puncture.state.depth_mm += offset;
    // The work along the later state's branch to the fold is not added to the first state's.
    out.puncture.energy_to_puncture_mj.reset();
    out.puncture.message = fmt::format(
        "on the first inflated state, after the snap-through at {} mm (depths from the later "
        "state's pole; the first state's pole {} mm lower); the energy to puncture is not "
        "integrated across the snap-through{}{}",
        landing_num(fold_mm),
        landing_num(offset),
        out.puncture.message.empty() ? "" : "; ",
        out.puncture.message);
  }
  out.failure_verdict = failure_verdict(p, out);
  out.status = Status::Converged;
  out.message.clear();
}

}  // namespace puncture::detail
