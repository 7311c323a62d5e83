#include "statistics_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <optional>

#include "cli_error.hpp"
#include "puncture/sweep_statistics.hpp"

namespace puncture::cli {

namespace {

// The fields of one line of the sweep's CSV: text quoted with "" for a quote inside.
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (quoted && c == '"' && k + 1 < line.size() && line[k + 1] == '"') {
      fields.back() += '"';
      ++k;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

std::optional<double> number_in(const std::string& cell) {
  if (cell.empty()) return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(cell.c_str(), &end);
  if (*end != '\0' || !std::isfinite(x)) return std::nullopt;
  return x;
}

}  // namespace

std::string sweep_statistics_report(const std::string& csv_path, const SweepSpec& spec) {
  std::ifstream in(csv_path);
  std::string line;
  if (!in || !std::getline(in, line))
    throw SolveError(fmt::format("--statistics: cannot read '{}' back", csv_path));
  const std::vector<std::string> header = fields_of(line);
  const std::size_t d = spec.parameters.size();
  std::vector<std::string> names;
  for (const SweepParameter& p : spec.parameters) names.push_back(p.name);
  // The output columns: the puncture's force and depth, the forces at depths.
  std::vector<std::size_t> columns;
  std::vector<SweepStatistics> stats;
  for (std::size_t c = 0; c < header.size(); ++c)
    if (header[c] == "puncture_force_n" || header[c] == "puncture_depth_mm" ||
        header[c].rfind("force_n_at_", 0) == 0) {
      columns.push_back(c);
      stats.emplace_back(names, header[c]);
    }
  std::vector<double> inputs(d);
  while (std::getline(in, line)) {
    const std::vector<std::string> row = fields_of(line);
    if (row.size() != header.size())
      throw SolveError(fmt::format("--statistics: '{}' has a row of {} fields, not {}",
                                   csv_path,
                                   row.size(),
                                   header.size()));
    for (std::size_t j = 0; j < d; ++j)
      inputs[j] = number_in(row[1 + j]).value_or(std::numeric_limits<double>::quiet_NaN());
    for (std::size_t k = 0; k < columns.size(); ++k)
      stats[k].add(inputs, number_in(row[columns[k]]));
  }
  std::string text = fmt::format("Statistics of {} ({} design)\n", csv_path, to_token(spec.design));
  for (const SweepStatistics& s : stats) {
    text += '\n';  // appended apart: GCC 12 warns falsely (-Wrestrict) on "\n" + string
    text += s.result().report();
  }
  return text;
}

}  // namespace puncture::cli
