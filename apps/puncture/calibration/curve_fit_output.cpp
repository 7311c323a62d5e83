// Writers of `puncture fit curve`: readable summary, CSV (every point of every test with the
// fitted force and the residual) and JSON.
#include "calibration/curve_fit_output.hpp"

#include <fmt/format.h>

#include "calibration/common_output.hpp"
#include "finite.hpp"
#include "json_helpers.hpp"
#include "tables.hpp"

namespace puncture::cli {

namespace {

using calibration::line;
using calibration::num_or;
using calibration::sampled_rows;

Table points_table(const CurveFitReport& r) {
  Table t{{"test", "depth_mm", "force_n", "model_force_n", "residual_n"}, {}};
  for (const auto& test : r.fit.tests)
    for (std::size_t i = 0; i < test.depth_mm.size(); ++i)
      t.rows.push_back({test.name,
                        test.depth_mm[i],
                        test.force_n[i],
                        test.model_force_n[i],
                        test.residual_n[i]});
  return t;
}

// A parameter's label: its name, or for a test's own (the contact offset) "offset N".
std::vector<std::string> labels(const CurveFit& f) {
  std::vector<std::string> out;
  int own = 0;
  for (const auto& p : f.parameters)
    out.push_back(p.test.empty() ? p.name : fmt::format("offset {}", ++own));
  return out;
}

std::string parameter_text(const FittedCurveParameter& p) {
  const std::string unit = p.unit.empty() ? "" : " " + p.unit;
  const std::string of_test = p.test.empty() ? "" : fmt::format(" (test {})", p.test);
  if (p.profile_interval && p.ci_lower && p.ci_upper)
    return fmt::format("{}{}  95 % interval [{}, {}] from the profile{}",
                       num(p.value, p.name),
                       unit,
                       num(*p.ci_lower, p.name + " interval"),
                       num(*p.ci_upper, p.name + " interval"),
                       p.on_bound ? "  (on its bound)" : "");
  if (!p.standard_error) return num(p.value, p.name) + unit + " (no standard error)" + of_test;
  return fmt::format("{} +- {}{}  95 % interval [{}, {}]{}{}",
                     num(p.value, p.name),
                     num(*p.standard_error, p.name + " standard error"),
                     unit,
                     num_or(p.ci_lower, p.name + " interval"),
                     num_or(p.ci_upper, p.name + " interval"),
                     p.on_bound ? "  (on its bound)" : "",
                     of_test);
}

std::string summary(const CurveFitReport& r) {
  const auto& f = r.fit;
  std::string out = "Inputs\n";
  for (std::size_t t = 0; t < r.records.size(); ++t) {
    const auto& rec = r.records[t];
    const auto& test = r.problem.tests[t];
    line(out,
         fmt::format("test {}", t + 1),
         fmt::format("{}: {} points, depth to {} mm from the contact at {} mm ({}){}",
                     rec.source,
                     rec.depth_mm.size(),
                     num(rec.depth_mm.back(), "largest depth"),
                     num(rec.contact_depth_mm, "contact depth"),
                     rec.contact_found ? "found" : "given",
                     test.puncture ? fmt::format("; perforation at {} mm, {} N",
                                                 num(test.puncture->depth_mm, "puncture depth"),
                                                 num(test.puncture->force_n, "puncture force"))
                                   : std::string()));
    line(out,
         "",
         fmt::format("{}, clamp radius {} mm, thickness {} mm, friction {}",
                     describe(test.problem.indenter),
                     num(test.problem.geometry.clamp_radius_mm, "clamp radius"),
                     num(test.problem.geometry.thickness_mm, "thickness"),
                     num(test.problem.friction, "friction")));
  }
  line(out, "material", describe(r.problem.tests.front().problem.material) + " (start)");
  out +=
      "Least-squares fit of the force at the measured depths (Ceres Levenberg-Marquardt;\n"
      "standard errors from the covariance (J^T J)^-1 of the residuals over their sd, the\n"
      "curves' sd being the residual sd; intervals: estimate +- t(0.975, n - p) se)\n";
  const auto label = labels(f);
  for (std::size_t i = 0; i < f.parameters.size(); ++i) {
    const auto& p = f.parameters[i];
    line(out, label[i], parameter_text(p));
    if (!p.note.empty()) line(out, "", p.note);
  }
  if (!f.correlation.empty() && f.parameters.size() > 1) {
    std::string header = "correlation";
    out += fmt::format("  {:<22}", header);
    for (const auto& l : label) out += fmt::format(" {:>14}", l);
    out += "\n";
    for (std::size_t i = 0; i < f.parameters.size(); ++i) {
      out += fmt::format("  {:<22}", label[i]);
      for (std::size_t j = 0; j < f.parameters.size(); ++j)
        out += fmt::format(" {:>14.4f}", finite(f.correlation[i][j], "correlation"));
      out += "\n";
    }
  }
  line(out,
       "residual sd",
       fmt::format("{} N (R^2 = {}; {} points, {} parameter{}, {} iterations, {} curves solved)",
                   num(f.residual_sd_n, "residual sd"),
                   num(f.r_squared, "R^2"),
                   f.points,
                   f.parameters.size(),
                   f.parameters.size() == 1 ? "" : "s",
                   f.iterations,
                   f.curve_evaluations));
  for (std::size_t k = 0; k < f.tests.size(); ++k) {
    const auto& t = f.tests[k];
    std::string text = fmt::format("RMS residual {} N", num(t.rms_residual_n, "RMS residual"));
    if (t.measured_puncture && t.model_puncture)
      text += fmt::format("; puncture measured {} N at {} mm, fitted {} N at {} mm",
                          num(t.measured_puncture->force_n, "puncture force"),
                          num(t.measured_puncture->depth_mm, "puncture depth"),
                          num(t.model_puncture->force_n, "fitted puncture force"),
                          num(t.model_puncture->depth_mm, "fitted puncture depth"));
    line(out, fmt::format("test {}", k + 1), text);
  }
  for (const auto& w : f.warnings) line(out, "warning", w);
  out += "Data and fit (sampled; --format csv for every point)\n";
  const auto t = points_table(r);
  text_table(out, t, sampled_rows(t.rows.size(), 12));
  return out;
}

json json_text_value(const CurveFitReport& r) {
  const auto& f = r.fit;
  json parameters = json::array();
  for (const auto& p : f.parameters)
    parameters.push_back({{"name", p.name},
                          {"unit", p.unit},
                          {"test", p.test.empty() ? json(nullptr) : json(p.test)},
                          {"interval", p.profile_interval ? "profile" : "t"},
                          {"value", finite(p.value, p.name)},
                          {"standard_error", value_or_null(p.standard_error, p.name)},
                          {"ci95_lower", value_or_null(p.ci_lower, p.name)},
                          {"ci95_upper", value_or_null(p.ci_upper, p.name)},
                          {"on_bound", p.on_bound},
                          {"identifiable", p.identifiable},
                          {"note", p.note}});
  json correlation = json::array();
  for (const auto& row : f.correlation) {
    json j = json::array();
    for (const double c : row) j.push_back(finite(c, "correlation"));
    correlation.push_back(j);
  }
  json tests = json::array();
  for (std::size_t t = 0; t < f.tests.size(); ++t) {
    const auto& ft = f.tests[t];
    const auto& rec = r.records[t];
    const auto point = [](const std::optional<MeasuredPuncture>& p, const char* what) -> json {
      if (!p) return nullptr;
      return {{"depth_mm", finite(p->depth_mm, what)}, {"force_n", finite(p->force_n, what)}};
    };
    json rows = json::array();
    tests.push_back({{"source", ft.name},
                     {"problem", problem_json(f.fitted_problems[t])},
                     {"contact_depth_mm", finite(rec.contact_depth_mm, "contact depth")},
                     {"contact_found", rec.contact_found},
                     {"rms_residual_n", finite(ft.rms_residual_n, "RMS residual")},
                     {"measured_puncture", point(ft.measured_puncture, "measured puncture")},
                     {"model_puncture", point(ft.model_puncture, "model puncture")},
                     {"depth_mm", ft.depth_mm},
                     {"force_n", ft.force_n},
                     {"model_force_n", ft.model_force_n},
                     {"residual_n", ft.residual_n}});
  }
  return {{"fit",
           {{"status", to_string(f.status)},
            {"converged", f.ok()},
            {"free", parameters},
            {"correlation", correlation},
            {"residual_sd_n", finite(f.residual_sd_n, "residual sd")},
            {"r_squared", finite(f.r_squared, "R^2")},
            {"points", f.points},
            {"iterations", f.iterations},
            {"curves_solved", f.curve_evaluations},
            {"loss", to_string(r.options.loss)},
            {"warnings", f.warnings}}},
          {"tests", tests}};
}

}  // namespace

std::string curve_fit_text(const CurveFitReport& report, Format format) {
  switch (format) {
    case Format::Csv:
      return csv(points_table(report));
    case Format::Json: {
      // Every number is checked finite: the vectors too.
      for (const auto& t : report.fit.tests)
        for (const auto* v : {&t.depth_mm, &t.force_n, &t.model_force_n, &t.residual_n})
          for (const double x : *v) finite(x, "a fitted point");
      return dump(json_text_value(report));
    }
    case Format::Summary:
      break;
  }
  return summary(report);
}

}  // namespace puncture::cli
