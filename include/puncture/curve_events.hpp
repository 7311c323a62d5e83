#pragma once
// What happens along a loading curve besides its points: a force maximum (where force control
// snaps through), the contact shrinking as the probe goes deeper, and, for a pre-tensioned
// membrane, which failure comes first (docs/model.md §8.1).  A fold of the depth (where depth
// control snaps through) is a SnapThrough; the branch beyond it is LoadingCurve::beyond_fold.
#include <optional>
#include <string>

namespace puncture {

enum class CurveEventKind {
  // dF/d(depth) = 0 with the force falling after: under force control the probe snaps through
  // to the deeper state of the same force (if the curve reaches it again).
  ForceMaximum,
  // The contact (the probe's outline covered by the membrane) shrinks as the probe goes deeper:
  // its edge moves back towards the tip.
  ContactShrinks,
  // The depth turns back (a fold of the path, dDepth/dF = 0): under depth control the membrane
  // snaps through at that depth to another state (force_after_n); under force control the path
  // passes the fold (the force keeps rising).
  SnapThrough,
};

std::string to_string(CurveEventKind kind);
// "force_maximum", "contact_shrinks": as written in JSON.
std::string to_token(CurveEventKind kind);

struct CurveEvent {
  CurveEventKind kind = CurveEventKind::ForceMaximum;
  // Where it starts, located by a bracketed solve between the curve's points (dF/d(depth) = 0
  // for a force maximum, d(reach)/d(depth) = 0 where the contact starts shrinking) [mm, N].
  double depth_mm = 0.0;
  double force_n = 0.0;
  // ForceMaximum: the deeper depth where the curve carries this force again (force control's
  // snap-through lands there) [mm]; empty if the curve ends before.  ContactShrinks: where the
  // contact grows again [mm]; empty if it shrinks to the end of the curve.  SnapThrough: where
  // the probe touches the landing state again, if it left it [mm].
  std::optional<double> end_depth_mm;
  // SnapThrough: the force of the state the membrane lands on at depth_mm [N] (0: the probe
  // left the membrane).
  std::optional<double> force_after_n;
  // The contact's reach at depth_mm [mm]: the contact edge's current radius plus its height
  // above the tip (grows along every probe's outline).
  double contact_reach_mm = 0.0;
  // How far the location is known [mm]: the half-width of the bracket the solve ended on, or
  // the spacing of the finite differences it used, whichever is larger.
  double depth_uncertainty_mm = 0.0;
  std::string description;  // where and why, in words
};

// Which failure ends the loading of a pre-tensioned (inflated or pre-stretched) membrane first
// (Deris & Nadler, IJNLM 2015): the probe punctures it locally, or the membrane fails globally,
// away from the probe or through an instability of the whole membrane.
enum class FailureMode {
  // The failure criterion is reached first at the probe: under it, on its side or at the
  // contact edge.
  LocalPuncture,
  // The criterion is reached first in the free membrane away from the contact (the dome
  // bursts there).
  GlobalBurst,
  // The force reaches a maximum before puncture: held at a force (or a gas pressure), the
  // membrane snaps through (or bursts) there, before the probe punctures it.
  GlobalLimitPoint,
};

std::string to_string(FailureMode mode);
// "local_puncture", "global_burst", "global_limit_point": as written in JSON.
std::string to_token(FailureMode mode);

struct FailureVerdict {
  FailureMode mode = FailureMode::LocalPuncture;
  double depth_mm = 0.0;  // where the first failure happens [mm]
  double force_n = 0.0;   // ... at this force [N]
  std::string where;      // the place on the membrane, e.g. "Part I, off the indenter"
  std::string reason;     // why this failure and not the other, with numbers
};

}  // namespace puncture
