#pragma once
// The displacement-controlled loading curve, from zero depth to puncture, and the puncture point.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "puncture/curve_events.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/outcome.hpp"

namespace puncture {

struct CurvePoint {
  double depth_mm = 0.0;
  double force_n = 0.0;
  double normalized_force = 0.0;  // F / (2 pi G H A)
  Stage stage = Stage::Slip;
  Configuration configuration = Configuration::Unloaded;
  double part_three_stretch = 1.0;
  double part_two_length_mm = 0.0;
  double corner_slope_rad = 0.0;
  double max_first_invariant = 3.0;
  // Deeper than the puncture point (or past the failure criterion): the real membrane has
  // punctured; the point is the model's continuation (curves with max_depth_mm).
  bool beyond_puncture = false;
  std::optional<ChamberGas> gas;  // a sealed chamber's gas at this depth, else empty
  // The contact's edge (where Part I leaves the probe): its current distance from the axis and
  // its height above the probe's tip [mm] (0 and 0 unloaded).
  double contact_edge_radius_mm = 0.0;
  double contact_edge_height_mm = 0.0;
  // Partial slip (Configuration::PartialSlip): the slip front, held inside, slipping outside to
  // the contact's edge; its reference radius R_s and current distance from the axis [mm] (0 and
  // 0 in every other configuration).
  double slip_front_reference_radius_mm = 0.0;
  double slip_front_radius_mm = 0.0;
};

// The stick -> slip switch under displacement control: at the switch depth the held state and
// the sliding state have different forces; the force jumps from one to the other.
struct StickSlipSwitch {
  bool occurs = false;
  double depth_mm = 0.0;
  double force_stuck_n = 0.0;    // force just before the switch (membrane held)
  double force_sliding_n = 0.0;  // force just after (membrane sliding), at the same depth
  // After a `coulomb` release on a curved probe the curve follows a partial slip (its points
  // Configuration::PartialSlip, force_sliding_n the held force: no jump) until the slip front
  // reaches the pole here [mm, N]: full sliding from there on.  Empty otherwise.
  std::optional<double> full_sliding_depth_mm;
  double full_sliding_force_n = 0.0;
};

struct PuncturePrediction : Outcome {
  double force_n = 0.0;
  double normalized_force = 0.0;
  double depth_mm = 0.0;
  Stage stage = Stage::Slip;
  Configuration configuration = Configuration::Unloaded;
  double part_three_stretch = 1.0;
  double crack_reference_radius_mm = 0.0;  // where the largest I1 sits (reference radius)
  double crack_radius_mm = 0.0;            // ... and its current distance from the axis
  std::string crack_location;              // in words, e.g. "Part I at the indenter's corner"
  // The membrane punctures as it starts sliding at the stick -> slip switch: the state is the
  // sliding one at the switch depth, or (stage Stick) the held one when sliding at that depth
  // would stretch it without bound past the criterion (beyond a limit load).
  bool at_switch = false;
  // The criterion met first (describe(FailureCriterion), e.g. "critical I1 = 95.2"); the crack's
  // place above is where its measure is largest.
  std::string criterion;
  // The indenter's work to puncture, the area under the force-depth curve from zero depth to the
  // puncture depth [mJ = N mm] (ASTM F1306's energy to perforation): with SolverOptions::
  // energy_to_puncture only, and empty (with a note in `message`) if the path could not be
  // followed.  The force's jump at a stick -> slip switch happens at one depth and adds nothing.
  std::optional<double> energy_to_puncture_mj;
  // The hoop stretch at the top of Part II [-] when the puncture was solved directly at the
  // corner (flat punch, sliding with Part II): where a neighbouring problem's search can start
  // (SolverOptions::puncture_top_stretch_start).  Empty otherwise.
  std::optional<double> part_two_top_stretch;
  // With SolverOptions::failure_verdict, for a pre-tensioned membrane: which failure comes first,
  // the loading curve's verdict (LoadingCurve::failure_verdict, whose own puncture leaves this
  // empty).  Empty for a membrane mounted stress-free, without a puncture found, or if the
  // curve could not be followed.
  std::optional<FailureVerdict> failure_verdict;
  // Where a later inflated state's path folds before any puncture (docs/model.md §8.1): the
  // puncture is the one under depth control, as the loading curve's, and this is the
  // snap-through on the way (a SnapThrough event: its depth, the force before (force_n) and
  // after (force_after_n), where the probe touches the landed state again); the puncture lies on
  // the first inflated state the membrane lands on, its depth measured from the later state's
  // pole.  Empty otherwise.
  std::optional<CurveEvent> snap_through;
  Equilibrium state;  // the full state at puncture
};

struct CurveOptions {
  int points = 200;           // depth points from zero to puncture (or to max_depth_mm)
  double max_depth_mm = 0.0;  // stop here instead of at puncture when > 0
  // When not empty: the curve at exactly these depths [mm] (finite, > 0, strictly increasing)
  // instead of the even grid (points and max_depth_mm are then ignored); a measured record's.
  // Besides them, as on the even grid, two points at a stick -> slip switch's depth and, where
  // depth control snaps through at a fold, the fold and the landing at the fold's depth.
  std::vector<double> depths_mm;
  std::function<void(int done, int total)> progress;  // called after each point, if set
  // Find the curve's events and locate each by solves at depths (LoadingCurve::events; tens of
  // solves per event), and give the failure verdict: off for a fit's many curves, which read
  // the points alone (then neither is given).
  bool locate_events = true;
};

struct LoadingCurve : Outcome {
  std::vector<CurvePoint> points;
  StickSlipSwitch stick_slip;
  std::optional<double> part_two_onset_depth_mm;  // where Part II appears in the slip stage
  std::optional<double> part_two_onset_force_n;
  bool part_two_onset_at_switch = false;  // Part II appears as the held membrane starts sliding
  // A flat punch under a gas pressure with friction: the first curve depth from which the face's
  // material slides outward, as the model's friction there assumes (docs/model.md §17); the
  // points before it slide inward and are not the membrane's states.  Nothing otherwise.
  std::optional<double> face_slides_outward_from_mm;
  PuncturePrediction puncture;
  // Force maxima (snap-through under force control) and a shrinking contact along the curve,
  // in order of depth (docs/model.md §8.1).
  std::vector<CurveEvent> events;
  // Where depth control snaps through at a fold of the depth (a SnapThrough event): the branch
  // past the fold, followed by arc length, the depth falling as the force rises (states of the
  // model that depth control does not reach), from the fold on (docs/model.md §8.1).
  std::vector<CurvePoint> beyond_fold;
  // A pre-tensioned membrane (pressure, sealed gas or pre-stretch): which failure comes first,
  // local puncture at the probe or a global one.  Empty for a membrane mounted stress-free.
  std::optional<FailureVerdict> failure_verdict;
};

// Stage the membrane is in at a given depth, per the problem's stick criterion.
struct StageBoundary : Outcome {
  bool switches = false;  // false: the membrane stays in its first stage
  Stage first_stage = Stage::Slip;
  double depth_mm = 0.0;  // switch depth when it switches
  double force_stuck_n = 0.0;
};
StageBoundary stick_slip_boundary(const Problem& problem, const SolverOptions& options = {});

PuncturePrediction predict_puncture(const Problem& problem, const SolverOptions& options = {});

LoadingCurve loading_curve(const Problem& problem, const CurveOptions& curve = {},
                           const SolverOptions& options = {});

}  // namespace puncture
