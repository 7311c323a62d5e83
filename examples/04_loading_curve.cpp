// The loading curve of a dry membrane (1 mm indenter, friction 1.95) from zero depth to puncture.
#include <fmt/format.h>

#include "puncture/loading_curve.hpp"

int main() {
  puncture::Problem problem;
  problem.indenter = puncture::FlatPunch{1.0};  // indenter radius [mm]
  problem.friction = 1.95;                      // dry rubber on steel

  puncture::CurveOptions options;
  options.points = 60;  // equally spaced depths from 0 to the puncture depth
  const auto curve = puncture::loading_curve(problem, options);
  if (!curve.ok()) {  // an expected failure is a status, never an exception
    fmt::print("{}: {}\n", puncture::to_string(curve.status), curve.message);
    return 1;
  }
  for (std::size_t i = 0; i < curve.points.size(); i += 10) {
    const auto& p = curve.points[i];
    fmt::print("depth {:6.2f} mm  F = {:.4f} N  I1 = {:5.2f}  {}\n",
               p.depth_mm,
               p.force_n,
               p.max_first_invariant,
               puncture::to_string(p.configuration));
  }
  if (curve.part_two_onset_depth_mm)  // the membrane starts to wrap the indenter's side
    fmt::print("Part II from depth {:.2f} mm, F = {:.4f} N\n",
               *curve.part_two_onset_depth_mm,
               *curve.part_two_onset_force_n);
  const auto& p = curve.puncture;  // where the largest I1 reaches the critical I1
  fmt::print("puncture at F = {:.4f} N, depth {:.2f} mm, crack in {}\n",
             p.force_n,
             p.depth_mm,
             p.crack_location);
}
