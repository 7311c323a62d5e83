// CSV writer: a header row with units in the column names, then one row per point.
#include <fmt/format.h>

#include "output.hpp"
#include "tables.hpp"

namespace puncture::cli {

namespace {

std::string quoted(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

std::string csv(const Table& table) {
  std::string out;
  for (std::size_t c = 0; c < table.columns.size(); ++c) out += (c ? "," : "") + table.columns[c];
  out += '\n';
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      if (c) out += ',';
      const auto& cell = table.rows[r][c];
      if (const auto* text = std::get_if<std::string>(&cell))
        out += quoted(*text);
      else if (std::holds_alternative<int>(cell))
        out += fmt::format("{}", std::get<int>(cell));
      else
        out += fmt::format("{:.10g}", checked_number(table, r, c));
    }
    out += '\n';
  }
  return out;
}

}  // namespace

std::string csv_text(const CurveReport& report) { return csv(curve_table(report.curve.points)); }

std::string csv_text(const StateReport& report) { return csv(fields_table(report.state.fields)); }

std::string csv_text(const PunctureReport& report) { return csv(puncture_table(report.puncture)); }

std::string csv_text(const VerifyReport& report) {
  return csv(verification_table(report.verification));
}

}  // namespace puncture::cli
