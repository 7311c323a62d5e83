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

std::string parameter_text(const FittedParameter& p) {
  std::string text = num_or(p.value, p.name, "none");
  if (p.standard_error) text += " +- " + num(*p.standard_error, p.name + " standard error");
  if (!p.unit.empty()) text += " " + p.unit;
  if (!p.standard_error) text += " (no standard error)";
  return text;
}

std::string model_flags(const UniaxialFit& fit) {
  if (!fit.material) return "";
  std::string flags = fmt::format("--material {} --shear-modulus {}",
                                  law_name(fit.material->law),
                                  num(fit.material->shear_modulus_mpa, "G"));
  if (const auto* gent = std::get_if<Gent>(&fit.material->law))
    flags += " --jlim " + num(gent->j_lim, "J_lim");
  if (const auto* mr = std::get_if<MooneyRivlin>(&fit.material->law))
    flags += " --mr-alpha " + num(mr->alpha, "alpha");
  return flags;
}

}  // namespace

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

std::string json_text(const UniaxialFitReport& r) {
  const auto& f = r.fit;
  json parameters = json::array();
  for (const auto& p : f.parameters)
    parameters.push_back({{"name", p.name},
                          {"unit", p.unit},
                          {"value", value_or_null(p.value, p.name)},
                          {"standard_error", value_or_null(p.standard_error, p.name)},
                          {"identifiable", p.identifiable},
                          {"note", p.note}});
  const json material = f.material ? material_json(*f.material) : json(nullptr);
  json specimen = nullptr;
  if (r.specimen)
    specimen = {{"width_mm", finite(r.specimen->width_mm, "specimen width")},
                {"thickness_mm", finite(r.specimen->thickness_mm, "specimen thickness")},
                {"gauge_length_mm", finite(r.specimen->gauge_length_mm, "gauge length")}};
  return dump(
      {{"inputs", {{"source", r.source}, {"points", r.data.size()}, {"specimen", specimen}}},
       {"fit",
        {{"law", to_string(f.law)},
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
         {"material", material}}},
       {"points", rows_json(points_rows(r))}});
}

std::string csv_text(const UniaxialFitReport& r) { return csv(points_rows(r)); }

}  // namespace puncture::cli::calibration
