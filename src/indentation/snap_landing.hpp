#pragma once
// Where a later inflated state's loading curve snaps through at a fold of the depth
// (curve_to_fold.hpp): the state the membrane lands on at the fold's depth, and the curve and
// the puncture from it (docs/model.md §8.1, "Following a fold").
#include <optional>
#include <vector>

#include "puncture/loading_curve.hpp"
#include "puncture/problem.hpp"

namespace puncture::detail {

// The landing: the first inflated state at the fold's probe position (depths measured from the
// later state's pole).
struct SnapLanding : Outcome {
  // How far the first state's pole lies below the later state's: the probe touches it that much
  // deeper than the later state's pole [mm].
  double offset_mm = 0.0;
  // The fold's depth on the first state [mm]: <= 0, its pole below the probe's tip (clear of the
  // probe, force 0); > 0, indented by that much.
  double landing_depth_mm = 0.0;
  CurvePoint point;  // the landed state, at the fold's depth
};

// The landing of the SnapThrough event `snap` (its depth and force before set), which gets the
// landing's force, where the probe touches again (if it leaves) and its words.
SnapLanding snap_landing(const Problem& p, const SolverOptions& options, CurveEvent& snap);

// The first state's puncture `first` as the later state's after the snap-through (`landing`,
// `snap`): its depth shifted by the poles' offset, the snap-through recorded.  Its energy to
// puncture (from the first state's dome) becomes the area under the path depth control follows:
// `fold_work` (the work to the fold [mJ], work_to_fold_mj), then nothing while the probe is clear
// of the landed membrane (force 0), then the first state's (the force's drop at the
// snap-through is dissipated, not the probe's work).  Where the membrane lands indented, or
// `fold_work` is missing, left empty with a note.
void puncture_past_snap(const SnapLanding& landing, const CurveEvent& snap,
                        const std::optional<double>& fold_work, PuncturePrediction& first);

// `out`: the curve to the fold, its last event the SnapThrough there.  The landing state is the
// first inflated state at the same probe position (snap_landing).  The event gets the landing's
// force and words; the first state's curve to its puncture follows, its depths shifted by the
// two poles' height difference, its events and puncture too (the puncture as puncture_past_snap
// gives it).  Where that curve fails, `out` ends at the landing with its status and why.
// `after`: the curve's depths past the fold (to max_depth_mm; curve_to_fold), empty for the curve
// to puncture: the points at those depths then, clear of the probe at force 0.
// `fold_work`: as puncture_past_snap's.
void land_after_snap(const Problem& p, const CurveOptions& curve, const SolverOptions& options,
                     const std::vector<double>& after, const std::optional<double>& fold_work,
                     LoadingCurve& out);

}  // namespace puncture::detail
