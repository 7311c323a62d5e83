// How friction between membrane and indenter changes the puncture (1 mm indenter).
#include <fmt/format.h>

#include "puncture/loading_curve.hpp"

int main() {
  puncture::Problem problem;
  problem.indenter = puncture::FlatPunch{1.0};
  for (double mu : {0.0, 0.18, 0.5, 1.0, 1.95}) {
    problem.friction = mu;
    const auto p = puncture::predict_puncture(problem);
    if (!p.ok()) {
      fmt::print("mu' = {}: {}\n", mu, p.message);
      return 1;
    }
    fmt::print("mu' = {:4.2f}  F_p = {:.4f} N  depth {:6.2f} mm  Part III stretch {:.3f}\n",
               mu,
               p.force_n,
               p.depth_mm,
               p.part_three_stretch);
  }
}
