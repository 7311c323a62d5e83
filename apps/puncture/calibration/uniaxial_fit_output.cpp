// Writers of `puncture fit uniaxial`: readable summary, CSV (the data and the fit, one row per
// point) and JSON.
#include <fmt/format.h>

#include <algorithm>
#include <variant>

#include "calibration/common_output.hpp"
#include "finite.hpp"
#include "json_helpers.hpp"
#include "puncture/material.hpp"
#include "tables.hpp"

namespace puncture::cli::calibration {

namespace {

Table points_rows(const UniaxialFitReport& r) {
  Table t{{"stretch", "nominal_stress_mpa", "fitted_stress_mpa", "residual_mpa"}, {}};
  for (std::size_t i = 0; i < r.data.size(); ++i)
    t.rows.push_back({r.data[i].stretch,
                      r.data[i].nominal_stress_mpa,
                      r.fit.fitted_stress_mpa[i],
                      r.fit.fitted_stress_mpa[i] - r.data[i].nominal_stress_mpa});
  return t;
}

std::string joined(const std::vector<double>& values, std::string_view what) {
  std::string out;
  for (const double v : values) {
    // Appended piece by piece: `"," + num(...)` trips a false -Wrestrict of GCC 12 (in a unity
    // batch).
    if (!out.empty()) out += ',';
    out += num(v, what);
  }
  return out;
}

}  // namespace

std::string parameter_text(const FittedParameter& p) {
  std::string text = num_or(p.value, p.name, "none");
  if (p.standard_error) text += " +- " + num(*p.standard_error, p.name + " standard error");
  if (!p.unit.empty()) text += " " + p.unit;
  if (!p.standard_error) text += " (no standard error)";
  return text;
}

std::string model_flags(const UniaxialFit& fit) {
  if (!fit.material) return "";
  const auto& m = *fit.material;
  const double g = m.shear_modulus_mpa;
  if (const auto* yeoh = std::get_if<Yeoh>(&m.law))  // G = 2 C10, Ci0 = ci G
    return "--material yeoh --yeoh " + joined({0.5 * g, yeoh->c2 * g, yeoh->c3 * g}, "Yeoh C");
  if (const auto* ogden = std::get_if<Ogden>(&m.law)) {
    std::vector<double> mu;
    for (const double x : ogden->mu) mu.push_back(x * g);
    return "--material ogden --ogden-mu " + joined(mu, "Ogden mu") + " --ogden-alpha " +
           joined(ogden->alpha, "Ogden alpha");
  }
  std::string flags = fmt::format("--material {} --shear-modulus {}", law_name(m.law), num(g, "G"));
  if (const auto* gent = std::get_if<Gent>(&m.law)) flags += " --jlim " + num(gent->j_lim, "J_lim");
  if (const auto* mr = std::get_if<MooneyRivlin>(&m.law))
    flags += " --mr-alpha " + num(mr->alpha, "alpha");
  if (const auto* ab = std::get_if<ArrudaBoyce>(&m.law))
    flags += " --chain-segments " + num(ab->n, "N");
  if (const auto* gg = std::get_if<GentGent>(&m.law))
    flags += " --jlim " + num(gg->j_lim, "J_lim") + " --i2-share " + num(gg->beta, "beta");
  return flags;
}

void statistics_lines(std::string& out, const UniaxialFit& f) {
  if (f.parameters.size() > 1) {
    if (f.correlation.empty()) {
      line(out, "correlation", "none (the Jacobian is singular)");
    } else {
      for (std::size_t i = 0; i < f.parameters.size(); ++i)
        for (std::size_t j = i + 1; j < f.parameters.size(); ++j)
          line(out,
               i == 0 && j == 1 ? "correlation" : "",
               fmt::format("{} ~ {}: {}",
                           f.parameters[i].name,
                           f.parameters[j].name,
                           fmt::format("{:+.3f}", f.correlation[i][j])));
    }
  }
  if (f.information)
    line(out,
         "AIC, AICc, BIC",
         fmt::format("{}, {}, {} (n = {}, k = {} with the variance, RSS = {} MPa^2)",
                     num(f.information->aic, "AIC"),
                     num_or(f.information->aicc, "AICc", "n/a (n <= k + 1)"),
                     num(f.information->bic, "BIC"),
                     f.information->points,
                     f.information->parameters,
                     num(f.information->rss_mpa2, "RSS")));
  else
    line(out, "AIC, AICc, BIC", "none: the fit is exact (RSS = 0)");
}

json correlation_json(const UniaxialFit& f) {
  json rows = json::array();
  for (const auto& row : f.correlation) {
    json r = json::array();
    for (const double x : row) r.push_back(finite(x, "correlation"));
    rows.push_back(r);
  }
  return rows;
}

json information_json(const UniaxialFit& f) {
  if (!f.information) return nullptr;
  const auto& c = *f.information;
  return {{"points", c.points},
          {"parameters", c.parameters},
          {"rss_mpa2", finite(c.rss_mpa2, "RSS")},
          {"aic", finite(c.aic, "AIC")},
          {"aicc", value_or_null(c.aicc, "AICc")},
          {"bic", finite(c.bic, "BIC")}};
}

std::string summary(const UniaxialFitReport& r) {
  const auto& f = r.fit;
  double lo = r.data.front().stretch, hi = lo;
  for (const auto& p : r.data) lo = std::min(lo, p.stretch), hi = std::max(hi, p.stretch);
  std::string out = "Inputs\n";
  line(out,
       "data",
       fmt::format("{}: {} points, stretch {} to {}",
                   r.source,
                   r.data.size(),
                   num(lo, "smallest stretch"),
                   num(hi, "largest stretch")));
  if (r.specimen)
    line(out,
         "specimen",
         fmt::format("width {} mm, thickness {} mm, gauge length {} mm",
                     num(r.specimen->width_mm, "specimen width"),
                     num(r.specimen->thickness_mm, "specimen thickness"),
                     num(r.specimen->gauge_length_mm, "gauge length")));
  line(out, "law", to_string(f.law));
  line(out, "test", fmt::format("{} (nominal stress)", to_string(f.test)));
  out +=
      "Least-squares fit of the nominal stress (bounded Levenberg-Marquardt; standard errors\n"
      "sigma sqrt(diag (J^T J)^-1), sigma^2 = sum of squared residuals / (n - p))\n";
  bool all_identifiable = true;
  for (const auto& p : f.parameters) {
    line(out, p.name, parameter_text(p));
    if (!p.note.empty()) line(out, "", p.note);
    all_identifiable = all_identifiable && p.identifiable;
  }
  line(out,
       "RMS residual",
       fmt::format("{} MPa (residual sd {} MPa; {} points, {} parameter{}, {} iterations)",
                   num(f.rms_residual_mpa, "RMS residual"),
                   num(f.residual_sd_mpa, "residual sd"),
                   f.points,
                   f.parameters.size(),
                   f.parameters.size() == 1 ? "" : "s",
                   f.iterations));
  statistics_lines(out, f);
  line(out,
       "reach of the data",
       fmt::format("largest I1 - 3 = {}{}",
                   num(f.max_i1_minus_3, "largest I1 - 3"),
                   f.stiffening_at_largest_stretch
                       ? fmt::format(" (fitted Gent stress there {} x neo-Hookean)",
                                     num(*f.stiffening_at_largest_stretch, "stiffening"))
                       : std::string()));
  const bool g_ok = f.parameters.front().identifiable;
  if (f.material && all_identifiable)
    line(out, "for the model", model_flags(f));
  else if (f.law == FitLaw::Gent && g_ok)
    line(out,
         "for the model",
         fmt::format("--shear-modulus {}; J_lim is not determined by these data: calibrate it "
                     "from a puncture test (puncture calibrate jlim)",
                     num(f.parameters.front().value.value_or(0.0), "G")));
  else if (f.material)
    line(out, "for the model", model_flags(f) + " (not every parameter is determined: see above)");
  else
    line(out,
         "for the model",
         fmt::format("none: the fitted parameters are not a valid {} material (see above)",
                     to_string(f.law)));
  out += "Data and fit (stresses in MPa; sampled, --format csv for every point)\n";
  const auto t = points_rows(r);
  text_table(out, t, sampled_rows(t.rows.size(), 12));
  return out;
}

json fit_json(const UniaxialFit& f) {
  json parameters = json::array();
  for (const auto& p : f.parameters)
    parameters.push_back({{"name", p.name},
                          {"unit", p.unit},
                          {"value", value_or_null(p.value, p.name)},
                          {"standard_error", value_or_null(p.standard_error, p.name)},
                          {"identifiable", p.identifiable},
                          {"note", p.note}});
  const json material = f.material ? material_json(*f.material) : json(nullptr);
  return {{"law", to_string(f.law)},
          {"test", to_string(f.test)},
          {"converged", f.ok()},
          {"iterations", f.iterations},
          {"parameters", parameters},
          {"inverse_j_lim", value_or_null(f.inverse_j_lim, "1/J_lim")},
          {"inverse_j_lim_standard_error", value_or_null(f.inverse_j_lim_se, "1/J_lim se")},
          {"j_lim_lower_bound", value_or_null(f.j_lim_lower_bound, "J_lim lower bound")},
          {"max_i1_minus_3", finite(f.max_i1_minus_3, "largest I1 - 3")},
          {"stiffening_at_largest_stretch",
           value_or_null(f.stiffening_at_largest_stretch, "stiffening")},
          {"rms_residual_mpa", finite(f.rms_residual_mpa, "RMS residual")},
          {"residual_sd_mpa", finite(f.residual_sd_mpa, "residual sd")},
          {"correlation", correlation_json(f)},
          {"information_criteria", information_json(f)},
          {"material", material}};
}

json specimen_json(const std::optional<SpecimenGeometry>& specimen) {
  if (!specimen) return nullptr;
  return {{"width_mm", finite(specimen->width_mm, "specimen width")},
          {"thickness_mm", finite(specimen->thickness_mm, "specimen thickness")},
          {"gauge_length_mm", finite(specimen->gauge_length_mm, "gauge length")}};
}

std::string json_text(const UniaxialFitReport& r) {
  return dump(
      {{"inputs",
        {{"source", r.source}, {"points", r.data.size()}, {"specimen", specimen_json(r.specimen)}}},
       {"fit", fit_json(r.fit)},
       {"points", rows_json(points_rows(r))}});
}

std::string csv_text(const UniaxialFitReport& r) { return csv(points_rows(r)); }

}  // namespace puncture::cli::calibration
