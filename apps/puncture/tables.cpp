#include "tables.hpp"

#include <fmt/format.h>

#include "finite.hpp"
#include "names.hpp"

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
               "max_i1"};
  for (const auto& p : points)
    t.rows.push_back({p.depth_mm,
                      p.force_n,
                      p.normalized_force,
                      to_string(p.stage),
                      configuration_token(p.configuration),
                      p.part_three_stretch,
                      p.part_two_length_mm,
                      p.corner_slope_rad,
                      p.max_first_invariant});
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
    t.rows.push_back({m.part[i],
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
               "crack_location"};
  t.rows.push_back({p.force_n,
                    p.normalized_force,
                    p.depth_mm,
                    to_string(p.stage),
                    configuration_token(p.configuration),
                    p.part_three_stretch,
                    p.state.max_first_invariant,
                    p.crack_reference_radius_mm,
                    p.crack_radius_mm,
                    p.crack_location});
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
    auto number = [&](double x) { return skipped ? Cell{std::string{}} : Cell{x}; };
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

double checked_number(const Table& table, std::size_t row, std::size_t column) {
  const auto& cell = table.rows[row][column];
  const double x = std::holds_alternative<int>(cell) ? std::get<int>(cell) : std::get<double>(cell);
  return finite(x, fmt::format("{} in row {}", table.columns[column], row + 1));
}

}  // namespace puncture::cli
