#pragma once
// Pieces of JSON that several writers share: a table's rows, the inputs (membrane, material,
// stick criterion) and optional numbers.  Every number is checked finite (SolveError naming it
// otherwise).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "puncture/material.hpp"
#include "puncture/problem.hpp"
#include "tables.hpp"

namespace puncture::cli {

using json = nlohmann::ordered_json;

// The complete text: indented by 2, with a final newline.
std::string dump(const json& j);

// One object per row, keyed by the column names; a missing number is null.
json rows_json(const Table& table);

// The number, or null when there is none.
json value_or_null(const std::optional<double>& x, std::string_view what);

// law, shear_modulus_mpa, and j_lim (Gent; left out when `with_j_lim` is false, for the J_lim
// calibration) or alpha (Mooney-Rivlin).
json material_json(const Material& material, bool with_j_lim = true);

// rule, and threshold and threshold_unit for the rules that have one.
json stick_json(const StickCriterion& stick);

// The indentation problem: clamp_radius_mm, indenter_radius_mm, thickness_mm, material,
// friction, critical_i1, stick, part_two_equation.  `calibrated` ("friction" or "jlim") is left
// out: it is what a calibration determines.
json problem_json(const Problem& problem, std::string_view calibrated = "");

}  // namespace puncture::cli
