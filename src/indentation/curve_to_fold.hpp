#pragma once
// The loading curve of a later inflated state whose path in depth turns back before any
// puncture (docs/model.md §8.1, "Following a fold"): the points on the depth grid up to the
// fold, the fold itself as the last point, the branch beyond it by arc length
// (depth_arclength.hpp) and the snap-through event there; the state the membrane lands on, and
// the curve from it, are snap_landing.cpp's.
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "indentation/curve_events.hpp"
#include "indentation/curve_following.hpp"
#include "indentation/depth_arclength.hpp"
#include "indentation/depth_path_puncture.hpp"
#include "indentation/work_to_fold.hpp"

namespace puncture::detail {

// The path in depth from a later inflated state's dome to where it turns back, followed through
// the fold: empty where the path does not end at a fold.
template <class Shooting>
std::optional<FoldBranch> fold_of_depth_path(const Shooting& shooting) {
  if (!shooting.settings().dome_later_state) return std::nullopt;
  const auto never = [](const ScaledSolution&) { return -1.0; };
  const DepthPathResult path = puncture_along_depth(shooting, never);
  if (path.end != DepthPathEnd::StatesEnd || !path.fold || !path.deepest || path.peak)
    return std::nullopt;
  return follow_through_fold(shooting, path.state, *path.deepest);
}

// The SnapThrough event at the fold of `branch`, its landing not yet set (snap_landing).
template <class Shooting>
CurveEvent snap_event_at_fold(const Problem& p, const Shooting& shooting,
                              const FoldBranch& branch) {
  const SolverScales units = solver_scales(p);
  const double fold_mm = branch.fold.state.depth * units.length_mm;
  CurveEvent e;
  e.kind = CurveEventKind::SnapThrough;
  e.depth_mm = fold_mm;
  e.force_n = branch.fold.state.f * units.force_n;
  e.contact_reach_mm = contact_reach_mm(
      curve_point_of(p, shooting.contact(), branch.fold.state, Stage::Slip, fold_mm));
  e.depth_uncertainty_mm = branch.fold.depth_uncertainty * units.length_mm;
  return e;
}

// The curve to the fold and the branch beyond, and the SnapThrough event at the fold, its
// landing not yet set (snap_landing); empty (and `out` untouched) where the path has no fold
// or the grid cannot be followed to it.  To puncture (no max_depth_mm) the `points` are evenly
// spaced to the fold, the fold the last; to max_depth_mm beyond the fold, the even grid's depths
// short of the fold, then the fold, and the grid's deeper depths are put in `after` (the
// landing's, snap_landing); given depths likewise (one at the fold's depth among `after`).  For a
// later inflated state whose puncture search ended at a fold.  With
// SolverOptions::energy_to_puncture, `fold_work` gets the work to the fold [mJ] (work_to_fold_mj).
template <class Shooting>
std::optional<CurveEvent> curve_to_fold(const Problem& p, const Shooting& shooting,
                                        const CurveOptions& curve, const SolverOptions& options,
                                        LoadingCurve& out, std::vector<double>& after,
                                        std::optional<double>& fold_work) {
  const bool given = !curve.depths_mm.empty();
  if (!given && curve.points < 3) return std::nullopt;
  const auto branch = fold_of_depth_path(shooting);
  if (!branch) return std::nullopt;
  const SolverScales units = solver_scales(p);
  const double fold_mm = branch->fold.state.depth * units.length_mm;
  const int n = curve.points;
  CurveOptions grid = curve;
  after.clear();
  bool only_zero_short = false;
  if (given) {
    grid.depths_mm.clear();
    for (const double d : curve.depths_mm) (d < fold_mm ? grid.depths_mm : after).push_back(d);
    if (after.empty()) return std::nullopt;  // failed short of the fold
  } else if (curve.max_depth_mm > 0.0) {
    if (!(curve.max_depth_mm > fold_mm)) return std::nullopt;  // failed short of the fold
    auto depth_at = [&](int k) {
      return k == n - 1 ? curve.max_depth_mm : curve.max_depth_mm * k / (n - 1);
    };
    int short_of_fold = 0;
    while (short_of_fold < n && depth_at(short_of_fold) < fold_mm) ++short_of_fold;
    for (int k = short_of_fold; k < n; ++k)
      if (depth_at(k) > fold_mm) after.push_back(depth_at(k));
    // (Only zero depth short of it: the grid to half the fold, of which that point is kept.)
    only_zero_short = short_of_fold == 1;
    grid.points = std::max(short_of_fold, 2);
    grid.max_depth_mm = short_of_fold > 1 ? depth_at(short_of_fold - 1) : 0.5 * fold_mm;
  } else {
    // The even grid of `points` to the fold, but for its last point, the fold itself (depth
    // control is singular there).
    grid.points = n - 1;
    grid.max_depth_mm = fold_mm * (n - 2) / (n - 1);
  }
  LoadingCurve to_fold;
  StageBoundary slip;  // under a held pressure the membrane slides from the first touch
  slip.status = Status::Converged;
  slip.first_stage = Stage::Slip;
  const bool none_short = given && grid.depths_mm.empty();
  if (!none_short && !follow_curve(p,
                                   shooting,
                                   options.curve_tol,
                                   slip,
                                   grid.max_depth_mm,
                                   false,
                                   std::nullopt,
                                   grid,
                                   to_fold))
    return std::nullopt;
  const auto& contact = shooting.contact();
  if (only_zero_short) to_fold.points.resize(1);
  out.points = std::move(to_fold.points);
  out.points.push_back(curve_point_of(p, contact, branch->fold.state, Stage::Slip, fold_mm));
  out.beyond_fold.clear();
  for (std::size_t i = branch->fold_index; i < branch->states.size(); ++i)
    out.beyond_fold.push_back(curve_point_of(
        p, contact, branch->states[i], Stage::Slip, branch->states[i].depth * units.length_mm));
  fold_work.reset();
  if (options.energy_to_puncture)
    fold_work = work_to_fold_mj(p, shooting, options.curve_tol, *branch);
  return snap_event_at_fold(p, shooting, *branch);
}

}  // namespace puncture::detail
