#pragma once
// The writers: each returns the complete text of one result in one format, or throws
// SolveError when a number to be written is not finite (so nothing partial is written).
#include <string>

#include "output_options.hpp"
#include "reports.hpp"

namespace puncture::cli {

std::string summary_text(const CurveReport& report);
std::string summary_text(const StateReport& report);
std::string summary_text(const PunctureReport& report);
std::string summary_text(const VerifyReport& report);

std::string csv_text(const CurveReport& report);     // the curve, one row per depth point
std::string csv_text(const StateReport& report);     // the fields, one row per membrane point
std::string csv_text(const PunctureReport& report);  // one row
std::string csv_text(const VerifyReport& report);    // one row per check

std::string json_text(const CurveReport& report);
std::string json_text(const StateReport& report);
std::string json_text(const PunctureReport& report);
std::string json_text(const VerifyReport& report);

template <class Report>
std::string render(const Report& report, Format format) {
  switch (format) {
    case Format::Csv:
      return csv_text(report);
    case Format::Json:
      return json_text(report);
    case Format::Summary:
      break;
  }
  return summary_text(report);
}

}  // namespace puncture::cli
