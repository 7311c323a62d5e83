#pragma once
// Where Part II (membrane wrapped on the indenter's side) first appears along a loading curve:
// on the sliding branch, or at the stick -> slip switch when the membrane is held past that depth.
#include <optional>

#include "puncture/loading_curve.hpp"

namespace puncture::cli {

struct PartTwoOnset {
  double depth_mm = 0.0;
  double force_n = 0.0;
  bool at_switch = false;  // appears on sliding at the stick -> slip switch
};

std::optional<PartTwoOnset> part_two_onset(const LoadingCurve& curve);

}  // namespace puncture::cli
