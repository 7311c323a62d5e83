#pragma once
// A loading curve's point from a state solved on its own (at a depth, outside the curve's depth
// Newton): the fields both carry, the point placed at `depth_mm` on the curve.
#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::detail {

inline CurvePoint curve_point_from_equilibrium(const Equilibrium& e, double depth_mm) {
  CurvePoint pt;
  pt.depth_mm = depth_mm;
  pt.force_n = e.force_n;
  pt.normalized_force = e.normalized_force;
  pt.stage = e.stage;
  pt.configuration = e.configuration;
  pt.part_three_stretch = e.part_three_stretch;
  pt.part_two_length_mm = e.part_two_length_mm;
  pt.corner_slope_rad = e.corner_slope_rad;
  pt.max_first_invariant = e.max_first_invariant;
  pt.contact_edge_radius_mm = e.contact_edge_radius_mm;
  pt.contact_edge_height_mm = e.contact_edge_height_mm;
  return pt;
}

}  // namespace puncture::detail
