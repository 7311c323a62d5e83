// Fuzz target of the strict CSV reader (measurements for the calibrations and fits).  Any input
// either parses into a table that keeps the reader's promises or is refused with a CsvError
// naming a line; anything else (another exception, a crash, a sanitizer finding) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "puncture/csv.hpp"

namespace {

// The table's promises (puncture/csv.hpp); abort() so that libFuzzer and the replay report it.
void check(const puncture::CsvTable& table) {
  if (table.columns.empty() || table.rows.empty()) std::abort();
  if (table.rows.size() != table.line_numbers.size()) std::abort();
  int previous_line = 0;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    if (table.rows[i].size() != table.columns.size()) std::abort();
    for (const double value : table.rows[i])
      if (!std::isfinite(value)) std::abort();
    if (table.line_numbers[i] <= previous_line) std::abort();
    previous_line = table.line_numbers[i];
  }
  for (const auto& name : table.columns)
    if (name.empty() || table.find(name) == std::nullopt) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    check(puncture::parse_numeric_csv(text, "fuzz.csv"));
  } catch (const puncture::CsvError& e) {
    if (e.line() < 0 || e.column() < 0) std::abort();
  }
  return 0;
}
