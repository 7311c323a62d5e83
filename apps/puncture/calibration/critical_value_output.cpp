// Writers of `puncture calibrate critical-i1 --measure NAME`: summary, CSV (one row) and JSON.
#include "calibration/critical_value_output.hpp"

#include <fmt/format.h>

#include "calibration/common_output.hpp"
#include "finite.hpp"
#include "json_helpers.hpp"
#include "tables.hpp"

namespace puncture::cli {

namespace {

using calibration::line;
using calibration::num_or;

std::string unit_suffix(const FailureCriterion& c) {
  return criterion_unit(c).empty() ? std::string() : fmt::format(" {}", criterion_unit(c));
}

std::string summary(const CriticalValueReport& r) {
  const auto& e = r.estimate;
  const std::string unit = unit_suffix(e.criterion);
  std::string out = "Inputs\n";
  line(out, "inflation tests", fmt::format("{} (from {})", r.tests.size(), r.source));
  line(out,
       "membrane",
       r.pole_only
           ? fmt::format("{}, not solved (--pole-only): the pole's value", describe(r.material))
           : fmt::format("{}, inflated to the mark's pole stretch", describe(r.material)));
  line(out, "measure", fmt::format("{}{}", measure_name(e.criterion), unit));
  out += fmt::format(
      "Burst stretch and {} per test (the mark at the pole: stretch = burst radius /\n"
      "initial radius; pole = the equibiaxial pole's value; value = the membrane's largest,\n"
      "at reference radius R / A (0: the pole); radii in mm)\n",
      measure_name(e.criterion));
  Table t{{"test", "initial_radius_mm", "burst_radius_mm", "stretch", "pole", "value", "at_R/A"},
          {}};
  for (std::size_t i = 0; i < r.tests.size(); ++i)
    t.rows.push_back({std::to_string(i + 1),
                      r.tests[i].initial_radius_mm,
                      r.tests[i].burst_radius_mm,
                      e.stretches[i],
                      e.pole_values[i],
                      e.values[i],
                      e.radius_fractions[i]});
  text_table(out, t, all_rows(t));
  out += fmt::format("Critical {}\n", measure_name(e.criterion));
  line(out, "critical value (mean)", num(e.mean, "critical value") + unit);
  line(out,
       "standard deviation",
       e.standard_deviation
           ? num(*e.standard_deviation, "standard deviation") + unit + " (sample, n - 1)"
           : std::string("n/a (one test)"));
  line(out, "standard error of mean", num_or(e.standard_error, "standard error", "n/a (one test)"));
  line(
      out,
      "for the model",
      fmt::format("--criterion {}:{}", criterion_name(e.criterion), num(e.mean, "critical value")));
  return out;
}

std::string csv_text(const CriticalValueReport& r) {
  const auto& e = r.estimate;
  Table t{{"tests", "criterion", "critical", "critical_sd", "critical_standard_error", "unit"}, {}};
  t.rows.push_back({static_cast<double>(r.tests.size()),
                    criterion_name(e.criterion),
                    e.mean,
                    e.standard_deviation,
                    e.standard_error,
                    criterion_unit(e.criterion)});
  return csv(t);
}

std::string json_text(const CriticalValueReport& r) {
  const auto& e = r.estimate;
  json tests = json::array();
  for (std::size_t i = 0; i < r.tests.size(); ++i)
    tests.push_back({{"initial_radius_mm", finite(r.tests[i].initial_radius_mm, "initial radius")},
                     {"burst_radius_mm", finite(r.tests[i].burst_radius_mm, "burst radius")},
                     {"stretch", finite(e.stretches[i], "stretch")},
                     {"pole_value", finite(e.pole_values[i], "pole value")},
                     {"value", finite(e.values[i], "value")},
                     {"radius_fraction", finite(e.radius_fractions[i], "R / A")}});
  return dump({{"inputs",
                {{"source", r.source},
                 {"tests", tests},
                 {"membrane", material_json(r.material)},
                 {"pole_only", r.pole_only}}},
               {"critical_value",
                {{"criterion", criterion_name(e.criterion)},
                 {"measure", measure_name(e.criterion)},
                 {"unit", criterion_unit(e.criterion)},
                 {"mean", finite(e.mean, "critical value")},
                 {"sd", value_or_null(e.standard_deviation, "standard deviation")},
                 {"standard_error", value_or_null(e.standard_error, "standard error")},
                 {"tests", r.tests.size()}}}});
}

}  // namespace

std::string calibration_text(const CriticalValueReport& r, Format format) {
  switch (format) {
    case Format::Csv:
      return csv_text(r);
    case Format::Json:
      return json_text(r);
    case Format::Summary:
      break;
  }
  return summary(r);
}

}  // namespace puncture::cli
