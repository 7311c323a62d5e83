#include "part_two_onset.hpp"

namespace puncture::cli {

std::optional<PartTwoOnset> part_two_onset(const LoadingCurve& c) {
  if (!c.part_two_onset_depth_mm || !c.part_two_onset_force_n) return std::nullopt;
  const bool held_there = c.stick_slip.occurs && *c.part_two_onset_depth_mm < c.stick_slip.depth_mm;
  if (!held_there) return PartTwoOnset{*c.part_two_onset_depth_mm, *c.part_two_onset_force_n};
  for (const auto& p : c.points)
    if (p.stage == Stage::Slip && p.configuration == Configuration::SlipWithPartTwo)
      return PartTwoOnset{p.depth_mm, p.force_n, p.depth_mm == c.stick_slip.depth_mm};
  return std::nullopt;
}

}  // namespace puncture::cli
