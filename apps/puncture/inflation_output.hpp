#pragma once
// What `inflate` computed, and its summary, CSV and JSON writers.  Every number written is
// checked finite (SolveError otherwise); the radius of curvature of the flat state, which is
// infinite, is "n/a" in the summary, an empty cell in CSV and null in JSON.
#include <string>

#include "output_options.hpp"
#include "puncture/inflation.hpp"

namespace puncture::cli {

struct InflationCurveReport {
  InflationProblem problem;
  bool to_burst = true;  // the curve ends at the burst (else at --max-pole-stretch)
  InflationCurve curve;
};

struct InflationStateReport {
  InflationProblem problem;
  InflationState state;
};

struct InflationPressureReport {
  InflationProblem problem;
  bool to_burst = true;  // the search range ends at the burst (else at --max-pole-stretch)
  InflationAtPressure result;
};

std::string inflation_text(const InflationCurveReport& report, Format format);
std::string inflation_text(const InflationStateReport& report, Format format);
std::string inflation_text(const InflationPressureReport& report, Format format);

}  // namespace puncture::cli
