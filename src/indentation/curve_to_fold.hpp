#pragma once
// The loading curve of a later inflated state whose path in depth turns back before any
// puncture (docs/model.md §8.1, "Following a fold"): the points on the depth grid up to the
// fold, the fold itself as the last point, the branch beyond it by arc length
// (depth_arclength.hpp) and the snap-through event there; the state the membrane lands on, and
// the curve from it, are snap_landing.cpp's.
#include <fmt/format.h>

#include <optional>

#include "indentation/curve_events.hpp"
#include "indentation/curve_following.hpp"
#include "indentation/depth_arclength.hpp"
#include "indentation/depth_path_puncture.hpp"

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

// The curve to the fold (its `points` evenly spaced from 0 with the fold the last) and the
// branch beyond, and the SnapThrough event at the fold, its landing not yet set (snap_landing);
// empty (and `out` untouched) where the path has no fold or the grid cannot be followed to it.  For
// the curve to puncture (no max_depth_mm, no given depths) of a later inflated state whose puncture
// search ended at a fold.
template <class Shooting>
std::optional<CurveEvent> curve_to_fold(const Problem& p, const Shooting& shooting,
                                        const CurveOptions& curve, const SolverOptions& options,
                                        LoadingCurve& out) {
  if (!curve.depths_mm.empty() || curve.max_depth_mm > 0.0 || curve.points < 3) return std::nullopt;
  const auto branch = fold_of_depth_path(shooting);
  if (!branch) return std::nullopt;
  const SolverScales units = solver_scales(p);
  const double fold_mm = branch->fold.state.depth * units.length_mm;
  // The even grid of `points` to the fold, but for its last point, the fold itself (depth
  // control is singular there).
  const int n = curve.points;
  CurveOptions grid = curve;
  grid.points = n - 1;
  grid.max_depth_mm = fold_mm * (n - 2) / (n - 1);
  LoadingCurve to_fold;
  StageBoundary slip;  // under a held pressure the membrane slides from the first touch
  slip.status = Status::Converged;
  slip.first_stage = Stage::Slip;
  if (!follow_curve(p,
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
  out.points = std::move(to_fold.points);
  out.points.push_back(curve_point_of(p, contact, branch->fold.state, Stage::Slip, fold_mm));
  out.beyond_fold.clear();
  for (std::size_t i = branch->fold_index; i < branch->states.size(); ++i)
    out.beyond_fold.push_back(curve_point_of(
        p, contact, branch->states[i], Stage::Slip, branch->states[i].depth * units.length_mm));
  CurveEvent e;
  e.kind = CurveEventKind::SnapThrough;
  e.depth_mm = fold_mm;
  e.force_n = branch->fold.state.f * units.force_n;
  e.contact_reach_mm = contact_reach_mm(out.points.back());
  e.depth_uncertainty_mm = branch->fold.depth_uncertainty * units.length_mm;
  return e;
}

}  // namespace puncture::detail
