// Built against an installed puncture (find_package(puncture), puncture::core): the puncture point
// of the paper's default membrane.
#include <cstdio>

#include "puncture/loading_curve.hpp"

int main() {
  const puncture::Problem problem;  // defaults: the paper's silicone membrane
  const auto p = puncture::predict_puncture(problem);
  if (!p.ok()) {
    std::printf("no puncture: %s\n", p.message.c_str());
    return 1;
  }
  std::printf("puncture at F = %.4f N, depth %.2f mm\n", p.force_n, p.depth_mm);
  return 0;
}
