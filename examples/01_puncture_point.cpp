// The paper's default membrane (2 mm indenter, lubricated): where does it puncture?
#include <fmt/format.h>

#include "puncture/loading_curve.hpp"

int main() {
  const puncture::Problem problem;  // defaults: the paper's silicone membrane
  const auto p = puncture::predict_puncture(problem);
  if (!p.ok()) {
    fmt::print("no puncture: {}\n", p.message);
    return 1;
  }
  fmt::print("puncture at F = {:.4f} N, depth {:.2f} mm, Part III stretch {:.3f}\n",
             p.force_n,
             p.depth_mm,
             p.part_three_stretch);
  fmt::print("crack starts in {}\n", p.crack_location);
}
