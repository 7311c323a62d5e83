#pragma once
// What `puncture fit curve` computed, and its summary, CSV (one row per point) and JSON writers.
#include <string>
#include <vector>

#include "output_options.hpp"
#include "puncture/curve_fit.hpp"
#include "puncture/force_depth_record.hpp"

namespace puncture::cli {

struct CurveFitReport {
  std::vector<ForceDepthRecord> records;  // one per test, as read
  CurveFitProblem problem;
  CurveFitOptions options;
  CurveFit fit;
};

std::string curve_fit_text(const CurveFitReport& report, Format format);

}  // namespace puncture::cli
