#pragma once
// A testing machine's force-displacement record of an indentation test, read as it comes: the
// two columns by name or position, in the machine's units, with or without a header, separated
// by commas, semicolons or tabs, with decimal points or commas.  The depth's zero (the contact
// point) is given or found, and the record is cut where the membrane perforates.
//
// Rules (docs/model.md "Fitting force-depth curves"):
//  - Separator (auto): a tab if the first data line has one, else a semicolon if it has one,
//    else a comma.  Decimal comma (auto): with a tab or semicolon separator, a comma inside a
//    number is its decimal mark.
//  - Header (auto): the first non-blank, non-'#' line is a header when one of its fields is not
//    a number.  Columns by name need a header.  Cells of other columns are never read.
//  - Contact point (when not given): the baseline is the first `baseline_points` forces (mean
//    m, sd s); the force has risen when it exceeds m + max(contact_sigmas s, contact_noise_n)
//    at `sustained_points` consecutive points; the contact is the last point before that run
//    and its depth is the zero.  A membrane's force grows as depth^3 at first, so this zero is
//    late by about (threshold / F)^(1/3) of the depth F is reached at: give the contact point
//    when it is known.
//  - Perforation: the first point whose force falls below (1 - drop_fraction) times the largest
//    force before it, once that largest force has reached a tenth of the record's largest (the
//    baseline's noise is no perforation); the record ends at that largest force, which is the
//    puncture point.
//  - Kept: the points after the contact up to the cut (depth > 0).  Their depth must not
//    decrease.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "puncture/csv.hpp"

namespace puncture {

enum class DepthUnit { Millimetre, Metre, Inch };
enum class ForceUnit { Newton, Kilonewton, PoundForce, GramForce };

// "mm", "m", "in" and "N", "kN", "lbf", "gf"; empty when unknown.
std::optional<DepthUnit> depth_unit_from_token(std::string_view token);
std::optional<ForceUnit> force_unit_from_token(std::string_view token);
double millimetres_per(DepthUnit unit);
double newtons_per(ForceUnit unit);

// A column by its header name, or by its 1-based position (index > 0 wins).
struct ColumnChoice {
  std::string name;
  int index = 0;
};

enum class Tristate { Auto, Yes, No };

struct RecordFormat {
  ColumnChoice depth{"depth_mm", 0};
  ColumnChoice force{"force_n", 0};
  DepthUnit depth_unit = DepthUnit::Millimetre;
  ForceUnit force_unit = ForceUnit::Newton;
  Tristate header = Tristate::Auto;
  char separator = 0;                       // ',', ';', '\t', or 0 for auto
  Tristate decimal_comma = Tristate::Auto;  // Yes needs a ';' or tab separator
  // The depth of the contact point in the record's depth unit; empty: found from the data.
  std::optional<double> contact_depth;
  int baseline_points = 10;
  double contact_sigmas = 5.0;
  double contact_noise_n = 0.0;  // floor of the threshold above the baseline [N]
  int sustained_points = 5;
  bool cut_at_perforation = true;
  double drop_fraction = 0.5;
};

struct ForceDepthRecord {
  std::string source;
  std::vector<double> depth_mm;  // from the contact point, > 0
  std::vector<double> force_n;
  std::vector<int> line_numbers;  // the input line of each kept point
  double contact_depth_mm = 0.0;  // the zero, in the record's depth [mm]
  bool contact_found = false;     // found from the data (else given)
  char separator = ',';
  bool decimal_comma = false;
  bool header = false;
  std::optional<double> perforation_depth_mm;  // the puncture point, when the record has one
  std::optional<double> perforation_force_n;
  int perforation_line = 0;
  int rows = 0;  // data rows read
};

// Throws CsvError naming the source, line and column (a missing column, a non-numeric cell in a
// chosen column, a decreasing depth, too few points left) or std::invalid_argument for an
// invalid format.
ForceDepthRecord parse_force_depth_record(std::string_view text, std::string_view source,
                                          const RecordFormat& format);
ForceDepthRecord read_force_depth_record(const std::string& path, const RecordFormat& format);

}  // namespace puncture
