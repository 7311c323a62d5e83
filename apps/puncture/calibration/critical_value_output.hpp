#pragma once
// `puncture calibrate critical-i1 --measure NAME`: the critical value of another criterion from
// the same inflation tests, and its writers.
#include <string>
#include <vector>

#include "output_options.hpp"
#include "puncture/critical_value.hpp"

namespace puncture::cli {

struct CriticalValueReport {
  std::string source;  // "--burst-radii" or the CSV file
  std::vector<BurstTest> tests;
  Material material;  // the membrane (G sets the MPa of energy and stress)
  bool pole_only = false;
  CriticalValueEstimate estimate;
};

std::string calibration_text(const CriticalValueReport& report, Format format);

}  // namespace puncture::cli
