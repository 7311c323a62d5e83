#pragma once
// Tables shared by the writers: the loading curve and the membrane fields, one row per point,
// with units in the column names.
#include <string>
#include <variant>
#include <vector>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "puncture/verification.hpp"

namespace puncture::cli {

using Cell = std::variant<double, int, std::string>;

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<Cell>> rows;
};

// depth_mm, force_n, normalized_force, stage, configuration, part_three_stretch,
// part_two_length_mm, corner_slope_rad, max_i1.
Table curve_table(const std::vector<CurvePoint>& points);

// part, R_mm, r_mm, z_mm, slope_rad, lambda1, lambda2, lambda3, s1_mpa, s2_mpa, I1,
// contact_pressure_mpa, friction_traction_mpa.
Table fields_table(const MembraneFields& fields);

// One row: force_n, normalized_force, depth_mm, stage, configuration, part_three_stretch,
// max_i1, crack_reference_radius_mm, crack_radius_mm, crack_location.
Table puncture_table(const PuncturePrediction& puncture);

// One row per check: group, quantity, condition, shooting, second_method, relative_difference,
// tolerance, verdict, note.  A skipped check has empty numbers (NaN: written empty or null).
Table verification_table(const VerificationReport& report);

// The number in a cell, checked finite (SolveError naming the column otherwise).
double checked_number(const Table& table, std::size_t row, std::size_t column);

}  // namespace puncture::cli
