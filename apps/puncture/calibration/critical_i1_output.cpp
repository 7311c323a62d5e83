// Writers of `puncture calibrate critical-i1`: readable summary, CSV (one row) and JSON.
#include <fmt/format.h>

#include "calibration/common_output.hpp"
#include "finite.hpp"
#include "json_helpers.hpp"
#include "tables.hpp"

namespace puncture::cli::calibration {

namespace {

Table tests_rows(const CriticalI1Report& r) {
  Table t{{"test", "initial_radius_mm", "burst_radius_mm", "stretch", "I1"}, {}};
  for (std::size_t i = 0; i < r.tests.size(); ++i)
    t.rows.push_back({std::to_string(i + 1),
                      r.tests[i].initial_radius_mm,
                      r.tests[i].burst_radius_mm,
                      r.estimate.stretches[i],
                      r.estimate.first_invariants[i]});
  return t;
}

}  // namespace

std::string summary(const CriticalI1Report& r) {
  const auto& e = r.estimate;
  std::string out = "Inputs\n";
  line(out, "inflation tests", fmt::format("{} (from {})", r.tests.size(), r.source));
  out +=
      "Burst stretch and I1 per test (equibiaxial at the pole: lambda = burst radius /\n"
      "initial radius, I1 = 2 lambda^2 + lambda^-4; radii in mm)\n";
  const auto t = tests_rows(r);
  text_table(out, t, all_rows(t));
  out += "Critical I1\n";
  line(out, "critical I1 (mean)", num(e.mean, "critical I1"));
  line(out,
       "standard deviation",
       e.standard_deviation ? num(*e.standard_deviation, "standard deviation") + " (sample, n - 1)"
                            : std::string("n/a (one test)"));
  line(out, "standard error of mean", num_or(e.standard_error, "standard error", "n/a (one test)"));
  line(out, "for the model", "--critical-i1 " + num(e.mean, "critical I1"));
  return out;
}

std::string csv_text(const CriticalI1Report& r) {
  const auto& e = r.estimate;
  Table t{{"tests", "critical_i1", "critical_i1_sd", "critical_i1_standard_error"}, {}};
  t.rows.push_back(
      {static_cast<double>(r.tests.size()), e.mean, e.standard_deviation, e.standard_error});
  return csv(t);
}

std::string json_text(const CriticalI1Report& r) {
  const auto& e = r.estimate;
  json tests = json::array();
  for (std::size_t i = 0; i < r.tests.size(); ++i)
    tests.push_back({{"initial_radius_mm", finite(r.tests[i].initial_radius_mm, "initial radius")},
                     {"burst_radius_mm", finite(r.tests[i].burst_radius_mm, "burst radius")},
                     {"stretch", finite(e.stretches[i], "stretch")},
                     {"i1", finite(e.first_invariants[i], "I1")}});
  return dump({{"inputs", {{"source", r.source}, {"tests", tests}}},
               {"critical_i1",
                {{"mean", finite(e.mean, "critical I1")},
                 {"sd", value_or_null(e.standard_deviation, "standard deviation")},
                 {"standard_error", value_or_null(e.standard_error, "standard error")},
                 {"tests", r.tests.size()}}}});
}

}  // namespace puncture::cli::calibration
