// CSV writer: a header row with units in the column names, then one row per point.
#include <algorithm>

#include "output.hpp"
#include "puncture/failure.hpp"
#include "tables.hpp"

namespace puncture::cli {

std::string csv_text(const CurveReport& report) { return csv(curve_table(report.curve.points)); }

// With --criterion, each local criterion's measure on every row (column <name>, or <name>_mpa),
// the criterion's ratio to its critical value a column further (the energy release, one balance
// over the whole membrane, is in the summary and JSON).
std::string csv_text(const StateReport& report) {
  Table t = state_fields_table(report.state);
  const auto& f = report.state.fields;
  for (const FailureCriterion& c : report.problem.criteria) {
    if (!has_local_measure(c)) continue;
    const std::string unit = criterion_unit(c).empty() ? "" : "_mpa";
    std::string column = criterion_name(c);
    std::replace(column.begin(), column.end(), '-', '_');
    t.columns.push_back(column + unit);
    t.columns.push_back(column + "_ratio");
    for (std::size_t i = 0; i < t.rows.size() && i < f.size(); ++i) {
      const double v =
          measure_at(c, report.problem.material, f.radial_stretch[i], f.hoop_stretch[i]);
      t.rows[i].push_back(v);
      t.rows[i].push_back(v / critical_value(c));
    }
  }
  return csv(t);
}

std::string csv_text(const PunctureReport& report) { return csv(puncture_table(report.puncture)); }

std::string csv_text(const VerifyReport& report) {
  return csv(verification_table(report.verification));
}

}  // namespace puncture::cli
