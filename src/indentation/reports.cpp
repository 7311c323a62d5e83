#include "puncture/reports.hpp"

#include <fmt/format.h>

namespace puncture {

std::string brief_report(const Equilibrium& e) {
  if (!e.ok()) return fmt::format("{}: {}", to_string(e.status), e.message);
  return fmt::format(
      "{}: {} stage, {}, force {:.6g} N, depth {:.6g} mm, Part III stretch {:.6g}, largest I1 "
      "{:.6g}",
      to_string(e.status),
      to_string(e.stage),
      to_string(e.configuration),
      e.force_n,
      e.depth_mm,
      e.part_three_stretch,
      e.max_first_invariant);
}

std::string brief_report(const PuncturePrediction& p) {
  if (!p.ok()) return "not found: " + p.message;
  return fmt::format("force {:.6g} N, depth {:.6g} mm, Part III stretch {:.6g}, crack at {}",
                     p.force_n,
                     p.depth_mm,
                     p.part_three_stretch,
                     p.crack_location);
}

std::string brief_report(const LoadingCurve& c) {
  if (!c.ok()) return fmt::format("{}: {}", to_string(c.status), c.message);
  return fmt::format("{}: {} points, depth 0 to {:.6g} mm, {}",
                     to_string(c.status),
                     c.points.size(),
                     c.points.empty() ? 0.0 : c.points.back().depth_mm,
                     c.puncture.ok() ? fmt::format("puncture at {:.6g} N", c.puncture.force_n)
                                     : std::string("no puncture"));
}

}  // namespace puncture
