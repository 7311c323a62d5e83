#pragma once
// Where a later inflated state's loading curve snaps through at a fold of the depth
// (curve_to_fold.hpp): the state the membrane lands on at the fold's depth, and the curve from it
// to the puncture (docs/model.md §8.1, "Following a fold").
#include <vector>

#include "puncture/loading_curve.hpp"
#include "puncture/problem.hpp"

namespace puncture::detail {

// `out`: the curve to the fold, its last event the SnapThrough there.  The landing state is the
// first inflated state at the same probe position (depth measured from the later state's pole):
// clear of the probe (force 0) while its pole lies below the probe's tip, else indented by the
// rest.  The event gets the landing's force and words; the first state's curve to its puncture
// follows, its depths shifted by the two poles' height difference, its events and puncture too.
// Where that curve fails, `out` ends at the landing with its status and why.  `after`: the
// curve's depths past the fold (to max_depth_mm; curve_to_fold), empty for the curve to
// puncture: the points at those depths then, clear of the probe at force 0.
void land_after_snap(const Problem& p, const CurveOptions& curve, const SolverOptions& options,
                     const std::vector<double>& after, LoadingCurve& out);

}  // namespace puncture::detail
