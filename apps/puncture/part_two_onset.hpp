#pragma once
// Where Part II (membrane wrapped on the indenter's side) first appears along a loading curve.
// The library locates the onset on the sliding branch alone; when the membrane is still held
// there (a stick stage lasting past that depth), Part II appears only when it starts to slide,
// at the stick -> slip switch.
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
