#include "tables.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "finite.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/material.hpp"

namespace puncture::cli {

Table curve_table(const std::vector<CurvePoint>& points) {
  Table t;
  t.columns = {"depth_mm",
               "force_n",
               "normalized_force",
               "stage",
               "configuration",
               "part_three_stretch",
               "part_two_length_mm",
               "corner_slope_rad",
               "max_i1",
               "beyond_puncture"};
  for (const auto& p : points)
    t.rows.push_back({p.depth_mm,
                      p.force_n,
                      p.normalized_force,
                      to_string(p.stage),
                      to_token(p.configuration),
                      p.part_three_stretch,
                      p.part_two_length_mm,
                      p.corner_slope_rad,
                      p.max_first_invariant,
                      p.beyond_puncture ? 1 : 0});
  // Over a sealed chamber: the gas at each depth (the other curves' columns are unchanged).
  if (std::any_of(points.begin(), points.end(), [](const CurvePoint& p) { return p.gas; })) {
    t.columns.insert(t.columns.end(), {"gas_pressure_mpa", "gas_volume_mm3"});
    for (std::size_t i = 0; i < points.size(); ++i) {
      const auto& gas = points[i].gas;
      t.rows[i].push_back(gas ? std::optional<double>(gas->pressure_mpa) : std::nullopt);
      t.rows[i].push_back(gas ? std::optional<double>(gas->volume_mm3) : std::nullopt);
    }
  }
  // After a coulomb release: the slip front of the partial-slip points (empty on the others).
  const auto partial = [](const CurvePoint& p) {
    return p.configuration == Configuration::PartialSlip;
  };
  if (std::any_of(points.begin(), points.end(), partial)) {
    t.columns.insert(t.columns.end(), {"slip_front_reference_radius_mm", "slip_front_radius_mm"});
    for (std::size_t i = 0; i < points.size(); ++i) {
      const bool on = partial(points[i]);
      t.rows[i].push_back(on ? std::optional<double>(points[i].slip_front_reference_radius_mm)
                             : std::nullopt);
      t.rows[i].push_back(on ? std::optional<double>(points[i].slip_front_radius_mm)
                             : std::nullopt);
    }
  }
  return t;
}

Table fields_table(const MembraneFields& m) {
  Table t;
  t.columns = {"part",
               "R_mm",
               "r_mm",
               "z_mm",
               "slope_rad",
               "lambda1",
               "lambda2",
               "lambda3",
               "s1_mpa",
               "s2_mpa",
               "I1",
               "contact_pressure_mpa",
               "friction_traction_mpa"};
  for (std::size_t i = 0; i < m.size(); ++i)
    t.rows.push_back({static_cast<int>(m.part[i]),
                      m.reference_radius_mm[i],
                      m.radius_mm[i],
                      m.deflection_mm[i],
                      m.slope_rad[i],
                      m.radial_stretch[i],
                      m.hoop_stretch[i],
                      m.thickness_stretch[i],
                      m.radial_stress_mpa[i],
                      m.hoop_stress_mpa[i],
                      m.first_invariant[i],
                      m.contact_pressure_mpa[i],
                      m.friction_traction_mpa[i]});
  return t;
}

Table state_fields_table(const Equilibrium& e) {
  Table t = fields_table(e.fields);
  const std::vector<std::string> state = {"depth_mm", "force_n", "stage", "configuration"};
  t.columns.insert(t.columns.begin(), state.begin(), state.end());
  for (auto& row : t.rows) {
    const std::vector<Cell> values = {
        e.depth_mm, e.force_n, to_string(e.stage), to_token(e.configuration)};
    row.insert(row.begin(), values.begin(), values.end());
  }
  return t;
}

Table puncture_table(const PuncturePrediction& p) {
  Table t;
  t.columns = {"force_n",
               "normalized_force",
               "depth_mm",
               "stage",
               "configuration",
               "part_three_stretch",
               "max_i1",
               "crack_reference_radius_mm",
               "crack_radius_mm",
               "crack_location",
               "energy_to_puncture_mj"};
  t.rows.push_back({p.force_n,
                    p.normalized_force,
                    p.depth_mm,
                    to_string(p.stage),
                    to_token(p.configuration),
                    p.part_three_stretch,
                    p.state.max_first_invariant,
                    p.crack_reference_radius_mm,
                    p.crack_radius_mm,
                    p.crack_location,
                    p.energy_to_puncture_mj});
  if (const auto& gas = p.state.gas) {
    t.columns.insert(t.columns.end(), {"gas_pressure_mpa", "gas_volume_mm3"});
    t.rows.front().insert(t.rows.front().end(), {gas->pressure_mpa, gas->volume_mm3});
  }
  if (const auto& snap = p.snap_through) {
    // The fold passed on the way under depth control (its depth, the force before and after,
    // where the probe touches the landed state again; empty if it never left it).
    t.columns.insert(
        t.columns.end(),
        {"snap_depth_mm", "snap_force_before_n", "snap_force_after_n", "snap_touches_again_at_mm"});
    t.rows.front().insert(t.rows.front().end(),
                          {snap->depth_mm, snap->force_n, snap->force_after_n, snap->end_depth_mm});
  }
  return t;
}

Table verification_table(const VerificationReport& report) {
  Table t;
  t.columns = {"group",
               "quantity",
               "condition",
               "shooting",
               "second_method",
               "relative_difference",
               "tolerance",
               "verdict",
               "note"};
  for (const VerificationCheck& c : report.checks) {
    const bool skipped = !has_numbers(c);
    auto number = [&](double x) { return skipped ? std::nullopt : std::optional<double>(x); };
    t.rows.push_back({c.group,
                      c.quantity,
                      c.condition,
                      number(c.shooting),
                      number(c.reference),
                      number(c.difference),
                      number(c.tolerance),
                      to_string(c.verdict),
                      c.note});
  }
  return t;
}

bool is_missing(const Cell& cell) {
  const auto* x = std::get_if<std::optional<double>>(&cell);
  return x && !x->has_value();
}

double checked_number(const Table& table, std::size_t row, std::size_t column) {
  const auto& cell = table.rows[row][column];
  const double x = std::holds_alternative<int>(cell)
                       ? std::get<int>(cell)
                       : std::get<std::optional<double>>(cell).value();
  return finite(x, fmt::format("{} in row {}", table.columns[column], row + 1));
}

namespace {

// A cell as text: numbers in `number_format`, a missing number as `missing`.
std::string cell_text(const Table& table, std::size_t row, std::size_t column,
                      const char* number_format, const char* missing) {
  const auto& cell = table.rows[row][column];
  if (const auto* text = std::get_if<std::string>(&cell)) return *text;
  if (const auto* count = std::get_if<int>(&cell)) return fmt::format("{}", *count);
  if (is_missing(cell)) return missing;
  return fmt::format(fmt::runtime(number_format), checked_number(table, row, column));
}

std::string quoted(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

}  // namespace

std::string csv(const Table& table) {
  std::string out;
  for (std::size_t c = 0; c < table.columns.size(); ++c) out += (c ? "," : "") + table.columns[c];
  out += '\n';
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      if (c) out += ',';
      out += quoted(cell_text(table, r, c, "{:.10g}", ""));
    }
    out += '\n';
  }
  return out;
}

void text_table(std::string& out, const Table& table, const std::vector<std::size_t>& rows) {
  std::vector<std::vector<std::string>> cells;
  std::vector<std::size_t> width;
  for (const auto& c : table.columns) width.push_back(c.size());
  for (const auto r : rows) {
    auto& row = cells.emplace_back();
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      row.push_back(cell_text(table, r, c, "{:.5g}", "n/a"));
      width[c] = std::max(width[c], row.back().size());
    }
  }
  auto print_row = [&](const std::vector<std::string>& row) {
    std::string text = " ";
    for (std::size_t c = 0; c < row.size(); ++c) text += fmt::format(" {:>{}}", row[c], width[c]);
    out += text + "\n";
  };
  print_row(table.columns);
  for (const auto& row : cells) print_row(row);
}

std::vector<std::size_t> all_rows(const Table& table) {
  std::vector<std::size_t> rows(table.rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = i;
  return rows;
}

std::vector<std::size_t> spread_rows(std::size_t n, std::size_t shown) {
  std::set<std::size_t> rows;
  if (n == 0) return {};
  if (n <= shown + 8) shown = n;
  for (std::size_t k = 0; k < shown; ++k)
    rows.insert(shown == 1 ? 0 : (k * (n - 1) + (shown - 1) / 2) / (shown - 1));
  rows.insert(n - 1);
  return {rows.begin(), rows.end()};
}

}  // namespace puncture::cli
