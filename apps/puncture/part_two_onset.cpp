#include "part_two_onset.hpp"

namespace puncture::cli {

std::optional<PartTwoOnset> part_two_onset(const LoadingCurve& c) {
  if (!c.part_two_onset_depth_mm || !c.part_two_onset_force_n) return std::nullopt;
  return PartTwoOnset{
      *c.part_two_onset_depth_mm, *c.part_two_onset_force_n, c.part_two_onset_at_switch};
}

}  // namespace puncture::cli
