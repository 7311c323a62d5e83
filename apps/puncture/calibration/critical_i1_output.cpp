// Writers of `puncture calibrate critical-i1`: readable summary, CSV (one row) and JSON.
#include <fmt/format.h>

#include "calibration/common_output.hpp"
#include "finite.hpp"
#include "json_helpers.hpp"
#include "tables.hpp"

namespace puncture::cli::calibration {

namespace {

Table tests_rows(const CriticalI1Report& r) {
  const auto& e = r.estimate;
  Table t{{"test", "initial_radius_mm", "burst_radius_mm", "stretch", "pole_I1", "I1", "at_R/A"},
          {}};
  for (std::size_t i = 0; i < r.tests.size(); ++i)
    t.rows.push_back({std::to_string(i + 1),
                      r.tests[i].initial_radius_mm,
                      r.tests[i].burst_radius_mm,
                      e.stretches[i],
                      e.pole_first_invariants[i],
                      e.first_invariants[i],
                      e.largest_i1_radius_fractions[i]});
  return t;
}

}  // namespace

std::string summary(const CriticalI1Report& r) {
  const auto& e = r.estimate;
  std::string out = "Inputs\n";
  line(out, "inflation tests", fmt::format("{} (from {})", r.tests.size(), r.source));
  line(out,
       "membrane",
       r.law ? describe(*r.law) + ", inflated to the mark's pole stretch"
             : std::string("not solved (--pole-only): the pole's I1, as the paper"));
  out +=
      "Burst stretch and I1 per test (the mark at the pole: stretch = burst radius /\n"
      "initial radius, pole_I1 = 2 stretch^2 + stretch^-4; I1 = the membrane's largest,\n"
      "at reference radius R / A (0: the pole); radii in mm)\n";
  const auto t = tests_rows(r);
  text_table(out, t, all_rows(t));
  bool off_pole = false;
  for (const double at : e.largest_i1_radius_fractions) off_pole = off_pole || at > 0.0;
  if (off_pole)
    out +=
        "  The largest I1 is not at the pole: the burst starts where it is, and the pole's\n"
        "  I1 (the paper's estimate) would underestimate the critical I1.\n";
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
    tests.push_back(
        {{"initial_radius_mm", finite(r.tests[i].initial_radius_mm, "initial radius")},
         {"burst_radius_mm", finite(r.tests[i].burst_radius_mm, "burst radius")},
         {"stretch", finite(e.stretches[i], "stretch")},
         {"pole_i1", finite(e.pole_first_invariants[i], "pole I1")},
         {"i1", finite(e.first_invariants[i], "I1")},
         {"largest_i1_radius_fraction", finite(e.largest_i1_radius_fractions[i], "R / A")}});
  json membrane = nullptr;
  if (r.law) {
    membrane = material_json(Material{1.0, *r.law});
    membrane.erase("shear_modulus_mpa");  // the result does not depend on it
  }
  return dump({{"inputs", {{"source", r.source}, {"tests", tests}, {"membrane_law", membrane}}},
               {"critical_i1",
                {{"mean", finite(e.mean, "critical I1")},
                 {"sd", value_or_null(e.standard_deviation, "standard deviation")},
                 {"standard_error", value_or_null(e.standard_error, "standard error")},
                 {"tests", r.tests.size()}}}});
}

}  // namespace puncture::cli::calibration
