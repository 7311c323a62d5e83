#pragma once
// Tables shared by the writers: the loading curve and the membrane fields, one row per point,
// with units in the column names; and how every command writes a table (CSV, aligned text).
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "puncture/verification.hpp"

namespace puncture::cli {

// A cell: a number (empty when there is none, e.g. an unbounded or not-found quantity: an empty
// CSV cell, null in JSON, "n/a" in a summary), a count, or text.
using Cell = std::variant<std::optional<double>, int, std::string>;

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<Cell>> rows;
};

// depth_mm, force_n, normalized_force, stage, configuration, part_three_stretch,
// part_two_length_mm, corner_slope_rad, max_i1, beyond_puncture; over a sealed chamber also
// gas_pressure_mpa and gas_volume_mm3 (the gas's gauge pressure and the enclosed volume V).
Table curve_table(const std::vector<CurvePoint>& points);

// part, R_mm, r_mm, z_mm, slope_rad, lambda1, lambda2, lambda3, s1_mpa, s2_mpa, I1,
// contact_pressure_mpa, friction_traction_mpa.
Table fields_table(const MembraneFields& fields);
// The same with the state's depth_mm, force_n, stage and configuration first on every row, for
// a CSV file that stands on its own.
Table state_fields_table(const Equilibrium& e);

// One row: force_n, normalized_force, depth_mm, stage, configuration, part_three_stretch,
// max_i1, crack_reference_radius_mm, crack_radius_mm, crack_location, energy_to_puncture_mj
// (empty when not computed); over a sealed chamber also gas_pressure_mpa, gas_volume_mm3.
Table puncture_table(const PuncturePrediction& puncture);

// One row per check: group, quantity, condition, shooting, second_method, relative_difference,
// tolerance, verdict, note.  A skipped check has no numbers (written empty).
Table verification_table(const VerificationReport& report);

// A number cell that holds no number.
bool is_missing(const Cell& cell);

// The number in a cell (a count, or a number that is there), checked finite (SolveError naming
// the column and the row otherwise).
double checked_number(const Table& table, std::size_t row, std::size_t column);

// CSV: the column names, then one line per row; numbers as {:.10g}, a missing number empty,
// text quoted where it holds a comma, a quote or a newline.
std::string csv(const Table& table);

// Aligned text of the given rows (indices into table.rows) under the column names, for the
// summaries: numbers as {:.5g}, a missing number "n/a".
void text_table(std::string& out, const Table& table, const std::vector<std::size_t>& rows);

// Every row's index.
std::vector<std::size_t> all_rows(const Table& table);

// About `shown` evenly spaced rows of n, the first and the last among them; all n when
// n <= shown + 8.
std::vector<std::size_t> spread_rows(std::size_t n, std::size_t shown = 16);

}  // namespace puncture::cli
