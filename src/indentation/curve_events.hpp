#pragma once
// The events along a computed loading curve (puncture/curve_events.hpp): found between its
// points, then located by bracketed solves on states at given depths.
#include <functional>
#include <optional>
#include <vector>

#include "puncture/curve_events.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::detail {

// The force and the contact's reach of the state at a depth [mm] in a stage, or empty where no
// state is found.
struct DepthSample {
  double force_n = 0.0;
  double contact_reach_mm = 0.0;
};
using DepthSampler = std::function<std::optional<DepthSample>(double depth_mm, Stage stage)>;

// The contact's reach of a curve point [mm]: its edge's current radius plus its height above
// the tip.
inline double contact_reach_mm(const CurvePoint& q) {
  return q.contact_edge_radius_mm + q.contact_edge_height_mm;
}

// Force maxima and shrinking contact between the points (neighbouring points of one stage
// only: the stick -> slip switch's jump is not an event), each located with `at_depth`.
std::vector<CurveEvent> located_curve_events(const std::vector<CurvePoint>& points,
                                             const DepthSampler& at_depth);

// Pre-tensioned: inflated (held pressure or sealed gas) or pre-stretched, the membranes that
// get a failure verdict.
bool pretensioned(const Problem& p);

// The verdict for a pre-tensioned membrane (pressure, sealed gas or pre-stretch), from its
// curve's events and its puncture; empty for a membrane mounted stress-free or without a
// puncture.
std::optional<FailureVerdict> failure_verdict(const Problem& p, const LoadingCurve& curve);

}  // namespace puncture::detail
