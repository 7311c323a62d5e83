#include "rows_csv.hpp"

#include <fmt/format.h>

#include <cmath>

namespace puncture::cli {

namespace {

std::string quoted_cell(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// A number in its shortest exact form; a non-finite one is never written as a number.
std::string number(double x) { return std::isfinite(x) ? fmt::format("{}", x) : std::string(); }

// One line per row, whatever the message holds (a resumed file is read line by line).
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

}  // namespace

// Cells are appended one at a time (GCC 12 warns falsely, -Wrestrict, on "," + string).
void add_cell(std::string& line, const std::string& cell) {
  line += ',';
  line += cell;
}

std::string sweep_csv_header(const SweepSpec& spec) {
  std::string line = "point";
  for (const SweepParameter& p : spec.parameters) add_cell(line, quoted_cell(p.name));
  line += ",status,failure_kind";
  if (spec.outputs.puncture)
    line +=
        ",puncture_force_n,puncture_depth_mm,part_three_stretch,max_i1,"
        "crack_reference_radius_mm,crack_radius_mm,crack_location";
  for (double depth : spec.outputs.force_at_depth_mm)
    add_cell(line, fmt::format("force_n_at_{}_mm", depth));
  line += ",message\n";
  return line;
}

std::string sweep_csv_line(const SweepRow& row) {
  std::string line = std::to_string(row.point.index);
  for (const std::string& text : row.point.texts) add_cell(line, quoted_cell(text));
  add_cell(line, quoted_cell(to_string(row.status)));
  add_cell(line, to_token(row.failure_kind()));
  if (row.puncture) {
    const SweepPuncture& p = *row.puncture;
    if (p.ok()) {
      for (const double x : {p.force_n,
                             p.depth_mm,
                             p.part_three_stretch,
                             p.max_first_invariant,
                             p.crack_reference_radius_mm,
                             p.crack_radius_mm})
        add_cell(line, number(x));
      add_cell(line, quoted_cell(p.crack_location));
    } else {
      line += ",,,,,,,";
    }
  }
  for (const SweepForceAtDepth& f : row.at_depth) add_cell(line, f.ok() ? number(f.force_n) : "");
  add_cell(line, quoted_cell(one_line(row.message)));
  line += '\n';
  return line;
}

}  // namespace puncture::cli
