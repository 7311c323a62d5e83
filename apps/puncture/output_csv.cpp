// CSV writer: a header row with units in the column names, then one row per point.
#include "output.hpp"
#include "tables.hpp"

namespace puncture::cli {

std::string csv_text(const CurveReport& report) { return csv(curve_table(report.curve.points)); }

std::string csv_text(const StateReport& report) { return csv(state_fields_table(report.state)); }

std::string csv_text(const PunctureReport& report) { return csv(puncture_table(report.puncture)); }

std::string csv_text(const VerifyReport& report) {
  return csv(verification_table(report.verification));
}

}  // namespace puncture::cli
