// Writers of the calibration results: readable summary, CSV (one table, units in the column
// names) and JSON (every fact).
#include "calibration_output.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "finite.hpp"
#include "json_helpers.hpp"
#include "stick_spec.hpp"
#include "tables.hpp"

namespace puncture::cli {

namespace {

// ----- shared helpers -------------------------------------------------------------------------

std::string num(double x, std::string_view what) { return fmt::format("{:.5g}", finite(x, what)); }

std::string num_or(const std::optional<double>& x, std::string_view what,
                   std::string_view missing = "n/a") {
  return x ? num(*x, what) : std::string(missing);
}

void line(std::string& out, std::string_view label, std::string_view value) {
  out += fmt::format("  {:<28}{}\n", label, value);
}

// About `shown` evenly spaced rows, always the first and the last.
std::vector<std::size_t> sampled_rows(std::size_t n, std::size_t shown) {
  if (n <= shown + 4) {
    std::vector<std::size_t> rows(n);
    for (std::size_t i = 0; i < n; ++i) rows[i] = i;
    return rows;
  }
  std::vector<std::size_t> rows;
  for (std::size_t k = 0; k < shown; ++k) rows.push_back(k * (n - 1) / (shown - 1));
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  return rows;
}

std::string material_without(const Material& m, bool j_lim_calibrated) {
  if (j_lim_calibrated)
    return fmt::format("gent (J_lim: calibrated here), G = {:g} MPa", m.shear_modulus_mpa);
  return describe(m);
}

// The physical inputs; `calibrated` ("friction" or "jlim") is left out.
void problem_lines(std::string& out, const Problem& p, std::string_view calibrated) {
  const auto& g = p.geometry;
  line(out, "clamp radius A", num(g.clamp_radius_mm, "clamp radius") + " mm");
  line(out, "indenter radius a", num(g.indenter_radius_mm, "indenter radius") + " mm");
  line(out, "thickness H", num(g.thickness_mm, "thickness") + " mm");
  line(out, "material", material_without(p.material, calibrated == "jlim"));
  if (calibrated != "friction") line(out, "friction mu'", num(p.friction, "friction"));
  line(out, "stick criterion", describe_stick(p.stick));
  line(out, "Part II equation", to_string(p.part_two_equation));
}

std::optional<double> value_of(const Inversion& i) {
  return i.found ? std::optional<double>(i.value) : std::nullopt;
}

json inversion_json(const Inversion& i, std::string_view what) {
  json solutions = json::array();
  for (const double s : i.solutions) solutions.push_back(finite(s, what));
  return {{"found", i.found},
          {"value", value_or_null(value_of(i), what)},
          {"solutions", solutions},
          {"message", i.message},
          {"evaluations", i.evaluations}};
}

// "1.9923", or "not found: <why>"; a warning on a found value is kept.
std::string inversion_text(const Inversion& i, std::string_view what) {
  if (!i.found) return "not found: " + i.message;
  auto text = num(i.value, what);
  if (!i.message.empty()) text += " (" + i.message + ")";
  return text;
}

// ----- critical I1 ----------------------------------------------------------------------------

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

// ----- friction -------------------------------------------------------------------------------

void friction_lines(std::string& out, const FrictionEstimate& e, const FrictionReport& r) {
  line(out, "friction mu'", inversion_text(e.friction, "friction"));
  if (r.hole.ratio_sd > 0.0) {
    line(out,
         "mu' for ratio + sd",
         inversion_text(e.friction_for_ratio_plus_sd, "friction for ratio + sd"));
    line(out,
         "mu' for ratio - sd",
         inversion_text(e.friction_for_ratio_minus_sd, "friction for ratio - sd"));
  }
  line(out,
       "reachable stretch",
       fmt::format("{} (mu' = {}) to {} (mu' = 0)",
                   num_or(e.stretch_at_max_friction, "stretch at the largest friction"),
                   num(e.max_friction, "largest friction"),
                   num_or(e.stretch_at_zero_friction, "stretch without friction")));
  if (!e.friction.found) return;
  if (e.method == HoleMethod::AtMeasuredForce) {
    if (e.max_first_invariant)
      line(out,
           "largest I1 at the force",
           fmt::format("{} (critical I1 {}: {})",
                       num(*e.max_first_invariant, "largest I1"),
                       num(r.problem.critical_i1, "critical I1"),
                       *e.max_first_invariant > r.problem.critical_i1
                           ? "above, so with this mu' the model punctures below the force"
                           : "below, so with this mu' the model punctures above the force"));
  } else if (e.puncture_force_n) {
    line(out,
         "predicted puncture",
         fmt::format(
             "{} N at depth {} mm{}",
             num(*e.puncture_force_n, "predicted puncture force"),
             num_or(e.puncture_depth_mm, "predicted puncture depth"),
             r.hole.puncture_force_n
                 ? fmt::format(" (measured {} N)", num(*r.hole.puncture_force_n, "measured force"))
                 : std::string()));
  }
}

std::string summary(const FrictionReport& r) {
  std::string out = "Inputs\n";
  problem_lines(out, r.problem, "friction");
  line(out, "critical I1", num(r.problem.critical_i1, "critical I1"));
  line(out,
       "hole ratio",
       fmt::format("{}{} (indenter diameter / hole diameter = Part III stretch at puncture)",
                   num(r.hole.ratio, "hole ratio"),
                   r.hole.ratio_sd > 0.0 ? " +- " + num(r.hole.ratio_sd, "hole ratio sd") : ""));
  line(out,
       "measured puncture force",
       r.hole.puncture_force_n ? num(*r.hole.puncture_force_n, "measured force") + " N"
                               : std::string("not given"));
  if (r.at_measured_force) {
    out +=
        "Friction at the measured force (the paper's method, §4.2: the Part III stretch of\n"
        "the sliding equilibrium at the measured force equals the ratio)\n";
    friction_lines(out, *r.at_measured_force, r);
  }
  out +=
      "Friction at the predicted puncture (force-free: the Part III stretch at the predicted\n"
      "puncture equals the ratio; with the crack at the corner it depends only on the\n"
      "material, mu' and the critical I1)\n";
  friction_lines(out, r.at_predicted_puncture, r);
  out += r.at_measured_force
             ? "The paper used the first: \"we apply the same puncture force as in the experiment "
               "and\nadjust the coefficient of friction\".\n"
             : "The paper's method needs the measured force: --puncture-force N.\n";
  return out;
}

std::vector<Cell> friction_row(const FrictionEstimate& e, const FrictionReport& r) {
  return {to_string(e.method),
          r.hole.ratio,
          value_of(e.friction),
          value_of(e.friction_for_ratio_plus_sd),
          value_of(e.friction_for_ratio_minus_sd),
          e.stretch_at_zero_friction,
          e.stretch_at_max_friction,
          e.max_first_invariant,
          e.puncture_force_n,
          e.puncture_depth_mm};
}

std::string csv_text(const FrictionReport& r) {
  Table t{{"method",
           "hole_ratio",
           "friction",
           "friction_ratio_plus_sd",
           "friction_ratio_minus_sd",
           "stretch_at_zero_friction",
           "stretch_at_max_friction",
           "max_i1",
           "puncture_force_n",
           "puncture_depth_mm"},
          {}};
  if (r.at_measured_force) t.rows.push_back(friction_row(*r.at_measured_force, r));
  t.rows.push_back(friction_row(r.at_predicted_puncture, r));
  return csv(t);
}

json friction_json(const FrictionEstimate& e) {
  json scan = json::array();
  for (const auto& s : e.scan)
    scan.push_back({{"friction", finite(s.parameter, "scan friction")},
                    {"part_three_stretch", value_or_null(s.model, "scan stretch")}});
  json out = {{"method", to_string(e.method)},
              {"friction", inversion_json(e.friction, "friction")},
              {"friction_ratio_plus_sd",
               inversion_json(e.friction_for_ratio_plus_sd, "friction for ratio + sd")},
              {"friction_ratio_minus_sd",
               inversion_json(e.friction_for_ratio_minus_sd, "friction for ratio - sd")},
              {"stretch_at_zero_friction",
               value_or_null(e.stretch_at_zero_friction, "stretch without friction")},
              {"stretch_at_max_friction",
               value_or_null(e.stretch_at_max_friction, "stretch at the largest friction")},
              {"max_friction", finite(e.max_friction, "largest friction")},
              {"max_i1", value_or_null(e.max_first_invariant, "largest I1")}};
  if (e.method == HoleMethod::AtMeasuredForce)
    out["force_n"] = finite(e.force_n, "force");
  else {
    out["puncture_force_n"] = value_or_null(e.puncture_force_n, "predicted puncture force");
    out["puncture_depth_mm"] = value_or_null(e.puncture_depth_mm, "predicted puncture depth");
  }
  out["scan"] = scan;
  return out;
}

std::string json_text(const FrictionReport& r) {
  return dump({{"inputs",
                {{"problem", problem_json(r.problem, "friction")},
                 {"hole_ratio", finite(r.hole.ratio, "hole ratio")},
                 {"hole_ratio_sd", finite(r.hole.ratio_sd, "hole ratio sd")},
                 {"puncture_force_n", value_or_null(r.hole.puncture_force_n, "measured force")}}},
               {"paper_method", to_string(HoleMethod::AtMeasuredForce)},
               {"at_measured_force",
                r.at_measured_force ? friction_json(*r.at_measured_force) : json(nullptr)},
               {"at_predicted_puncture", friction_json(r.at_predicted_puncture)}});
}

// ----- J_lim ----------------------------------------------------------------------------------

std::string summary(const JLimReport& r) {
  const auto& e = r.estimate;
  std::string out = "Inputs\n";
  problem_lines(out, r.problem, "jlim");
  line(out,
       "critical I1",
       num(r.problem.critical_i1, "critical I1") +
           (r.critical_i1_sd ? " +- " + num(*r.critical_i1_sd, "critical I1 sd") : ""));
  line(out,
       "measured puncture force",
       num(r.force_n, "measured force") +
           (r.force_sd_n ? " +- " + num(*r.force_sd_n, "force sd") : "") + " N");
  out +=
      "J_lim from the puncture force (the paper's method, §4.1: the predicted puncture\n"
      "force, where the largest I1 reaches the critical I1, equals the measured force)\n";
  line(out, "J_lim", inversion_text(e.j_lim, "J_lim"));
  const auto other = [&](std::string_view label, const std::optional<JLimEstimate>& x) {
    if (x) line(out, label, inversion_text(x->j_lim, label));
  };
  other("J_lim for force + sd", r.force_plus_sd);
  other("J_lim for force - sd", r.force_minus_sd);
  other("J_lim for critical I1 + sd", r.i1_plus_sd);
  other("J_lim for critical I1 - sd", r.i1_minus_sd);
  const auto& p = e.puncture;
  if (p.found)
    line(out,
         "predicted puncture",
         fmt::format("{} N at depth {} mm, Part III stretch {}, crack: {}",
                     num(p.force_n, "predicted puncture force"),
                     num(p.depth_mm, "predicted puncture depth"),
                     num(p.part_three_stretch, "Part III stretch"),
                     p.crack_location));
  if (e.max_first_invariant_at_force)
    line(out,
         "largest I1 at the force",
         num(*e.max_first_invariant_at_force, "largest I1 at the force") +
             " (the paper's check: sliding equilibrium at the measured force)");
  line(out,
       "reachable forces",
       fmt::format("{} N (J_lim = {}) to {} N (J_lim = {}); neo-Hookean limit {} N",
                   num(e.smallest_force_n, "smallest force"),
                   num(e.max_j_lim, "largest J_lim"),
                   num(e.largest_force_n, "largest force"),
                   fmt::format("{:.8g}", finite(e.min_j_lim, "smallest J_lim")),
                   num(e.neo_hookean_force_n, "neo-Hookean force")));
  return out;
}

std::string csv_text(const JLimReport& r) {
  const auto& e = r.estimate;
  const auto j = [](const std::optional<JLimEstimate>& x) -> std::optional<double> {
    return x ? value_of(x->j_lim) : std::nullopt;
  };
  const auto& p = e.puncture;
  const auto if_found = [&](double x) { return p.found ? std::optional<double>(x) : std::nullopt; };
  Table t{{"j_lim",
           "j_lim_force_plus_sd",
           "j_lim_force_minus_sd",
           "j_lim_critical_i1_plus_sd",
           "j_lim_critical_i1_minus_sd",
           "puncture_force_n",
           "puncture_depth_mm",
           "part_three_stretch",
           "max_i1_at_force"},
          {}};
  // (a row of numbers only; built from an array, which spares GCC 12 a false
  // -Wmaybe-uninitialized on the cells' text member)
  const std::optional<double> row[] = {value_of(e.j_lim),
                                       j(r.force_plus_sd),
                                       j(r.force_minus_sd),
                                       j(r.i1_plus_sd),
                                       j(r.i1_minus_sd),
                                       if_found(p.force_n),
                                       if_found(p.depth_mm),
                                       if_found(p.part_three_stretch),
                                       e.max_first_invariant_at_force};
  t.rows.emplace_back(std::begin(row), std::end(row));
  return csv(t);
}

json jlim_json(const JLimEstimate& e) {
  json scan = json::array();
  for (const auto& s : e.scan)
    scan.push_back({{"j_lim", finite(s.parameter, "scan J_lim")},
                    {"puncture_force_n", value_or_null(s.model, "scan force")}});
  json puncture = nullptr;
  if (e.puncture.found)
    puncture = {{"force_n", finite(e.puncture.force_n, "predicted puncture force")},
                {"depth_mm", finite(e.puncture.depth_mm, "predicted puncture depth")},
                {"part_three_stretch", finite(e.puncture.part_three_stretch, "Part III stretch")},
                {"crack_location", e.puncture.crack_location}};
  return {{"force_n", finite(e.force_n, "measured force")},
          {"j_lim", inversion_json(e.j_lim, "J_lim")},
          {"puncture", puncture},
          {"max_i1_at_force", value_or_null(e.max_first_invariant_at_force, "largest I1")},
          {"smallest_force_n", finite(e.smallest_force_n, "smallest force")},
          {"largest_force_n", finite(e.largest_force_n, "largest force")},
          {"neo_hookean_force_n", finite(e.neo_hookean_force_n, "neo-Hookean force")},
          {"min_j_lim", finite(e.min_j_lim, "smallest J_lim")},
          {"max_j_lim", finite(e.max_j_lim, "largest J_lim")},
          {"scan", scan}};
}

std::string json_text(const JLimReport& r) {
  const auto optional_json = [](const std::optional<JLimEstimate>& x) {
    return x ? inversion_json(x->j_lim, "J_lim") : json(nullptr);
  };
  return dump({{"inputs",
                {{"problem", problem_json(r.problem, "jlim")},
                 {"puncture_force_n", finite(r.force_n, "measured force")},
                 {"puncture_force_sd_n", value_or_null(r.force_sd_n, "force sd")},
                 {"critical_i1_sd", value_or_null(r.critical_i1_sd, "critical I1 sd")}}},
               {"estimate", jlim_json(r.estimate)},
               {"j_lim_force_plus_sd", optional_json(r.force_plus_sd)},
               {"j_lim_force_minus_sd", optional_json(r.force_minus_sd)},
               {"j_lim_critical_i1_plus_sd", optional_json(r.i1_plus_sd)},
               {"j_lim_critical_i1_minus_sd", optional_json(r.i1_minus_sd)}});
}

// ----- uniaxial fit ---------------------------------------------------------------------------

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
      "Least-squares fit of the nominal stress (Levenberg-Marquardt; standard errors\n"
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
         {"converged", f.converged},
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

// ----- puncture band --------------------------------------------------------------------------

std::string unit_of(BandParameter p) { return p == BandParameter::ShearModulus ? " MPa" : ""; }

std::string percent_of(double x, double nominal) {
  return fmt::format("{:+.3g} %", finite(100.0 * (x / nominal - 1.0), "relative change"));
}

std::string interval_text(const BandReport& r, BandParameter p, const ParameterRange& range,
                          double nominal) {
  const auto i = static_cast<std::size_t>(p);
  std::string text = fmt::format("{} to {}{} (nominal {}",
                                 num(range.lower, "interval lower end"),
                                 num(range.upper, "interval upper end"),
                                 unit_of(p),
                                 num(nominal, "nominal value"));
  if (r.sd[i])
    text += fmt::format(
        " +- {}{}",
        r.sd_multiple == 1.0 ? std::string() : num(r.sd_multiple, "sd multiple") + " x ",
        num(*r.sd[i], "standard deviation"));
  return text + ")";
}

std::string evaluation_where(const BandEvaluation& e) {
  std::string out = fmt::format("critical I1 {}, mu' {}",
                                num(e.parameters.critical_i1, "critical I1"),
                                num(e.parameters.friction, "friction"));
  if (e.parameters.j_lim) out += ", J_lim " + num(*e.parameters.j_lim, "J_lim");
  return out + ", G " + num(e.parameters.shear_modulus_mpa, "G") + " MPa";
}

std::string summary(const BandReport& r) {
  const auto& b = r.band;
  std::string out = "Inputs\n";
  problem_lines(out, r.problem, "");
  line(out, "critical I1", num(r.problem.critical_i1, "critical I1"));
  out += "Intervals (each parameter not listed keeps the value above)\n";
  for (const auto& s : b.sensitivities)
    line(out, to_string(s.parameter), interval_text(r, s.parameter, s.range, s.nominal));
  out += "Puncture at the nominal parameters\n";
  const auto& n = b.nominal;
  line(out, "puncture force", num(n.force_n, "nominal puncture force") + " N");
  line(out, "puncture depth", num(n.depth_mm, "nominal puncture depth") + " mm");
  line(out, "Part III stretch", num(n.part_three_stretch, "Part III stretch"));
  line(out, "crack starts", n.crack_location);
  out += fmt::format("Band over the {} corners of the intervals\n", b.corners.size());
  if (b.force_min_n && b.force_max_n) {
    line(out,
         "puncture force",
         fmt::format("{} to {} N ({} / {})",
                     num(*b.force_min_n, "least force"),
                     num(*b.force_max_n, "largest force"),
                     percent_of(*b.force_min_n, n.force_n),
                     percent_of(*b.force_max_n, n.force_n)));
    line(out,
         "puncture depth",
         fmt::format("{} to {} mm ({} / {})",
                     num(*b.depth_min_mm, "least depth"),
                     num(*b.depth_max_mm, "largest depth"),
                     percent_of(*b.depth_min_mm, n.depth_mm),
                     percent_of(*b.depth_max_mm, n.depth_mm)));
  }
  if (b.force_min_corner)
    line(out, "least force at", evaluation_where(b.corners[*b.force_min_corner]));
  if (b.force_max_corner)
    line(out, "largest force at", evaluation_where(b.corners[*b.force_max_corner]));
  if (b.force_half_range_rss_n)
    line(out,
         "first-order force sd",
         num(*b.force_half_range_rss_n, "force spread") +
             " N (root sum of squares of the one-at-a-time half-ranges)");
  if (b.dominant) {
    std::string share;
    for (const auto& s : b.sensitivities)
      if (s.parameter == *b.dominant && s.force_variance_share)
        share = fmt::format(" ({:.3g} % of the first-order variance of the force)",
                            finite(100.0 * *s.force_variance_share, "variance share"));
    line(out, "dominant parameter", to_string(*b.dominant) + share);
  }
  out +=
      "One parameter at a time (the others nominal; forces in N, depths in mm; share: of the\n"
      "first-order variance of the force; monotone: along --samples points of the interval)\n";
  Table t{{"parameter",
           "lower",
           "upper",
           "force_lower",
           "force_upper",
           "force_change",
           "share",
           "depth_lower",
           "depth_upper",
           "monotone"},
          {}};
  const auto if_found = [](const BandEvaluation& e, double x) {
    return e.found ? std::optional<double>(x) : std::nullopt;
  };
  for (const auto& s : b.sensitivities)
    t.rows.push_back({to_token(s.parameter),
                      s.range.lower,
                      s.range.upper,
                      if_found(s.at_lower, s.at_lower.force_n),
                      if_found(s.at_upper, s.at_upper.force_n),
                      s.force_change_n,
                      s.force_variance_share,
                      if_found(s.at_lower, s.at_lower.depth_mm),
                      if_found(s.at_upper, s.at_upper.depth_mm),
                      std::string(s.force_monotone && s.depth_monotone ? "yes"
                                  : s.force_monotone                   ? "force only"
                                  : s.depth_monotone                   ? "depth only"
                                                                       : "no")});
  text_table(out, t, all_rows(t));
  if (b.warnings.empty()) {
    out += b.consistent_with_documented_directions
               ? "Every prediction converged; each parameter moves the force monotonically and "
                 "the\ndocumented way (puncture calibrate band --help).\n"
               : "Every prediction converged.\n";
  } else {
    out += "Warnings\n";
    for (const auto& w : b.warnings) out += "  " + w + "\n";
  }
  return out;
}

// Every evaluation the band made, one row each, and the ends of the band as copies of the
// corner rows that give them.
std::vector<Cell> evaluation_row(const std::string& kind, const BandEvaluation& e) {
  const auto if_found = [&](double x) { return e.found ? std::optional<double>(x) : std::nullopt; };
  return {kind,
          e.parameters.critical_i1,
          e.parameters.friction,
          e.parameters.j_lim,
          e.parameters.shear_modulus_mpa,
          std::string(e.found ? "yes" : "no"),
          if_found(e.force_n),
          if_found(e.depth_mm),
          if_found(e.part_three_stretch),
          e.found ? std::string() : e.message};
}

std::string csv_text(const BandReport& r) {
  const auto& b = r.band;
  Table t{{"case",
           "critical_i1",
           "friction",
           "j_lim",
           "shear_modulus_mpa",
           "found",
           "puncture_force_n",
           "puncture_depth_mm",
           "part_three_stretch",
           "message"},
          {}};
  t.rows.push_back(evaluation_row("nominal", b.nominal));
  const auto end = [&](const char* kind, const std::optional<std::size_t>& corner) {
    if (corner) t.rows.push_back(evaluation_row(kind, b.corners[*corner]));
  };
  end("force_min", b.force_min_corner);
  end("force_max", b.force_max_corner);
  end("depth_min", b.depth_min_corner);
  end("depth_max", b.depth_max_corner);
  for (const auto& s : b.sensitivities)
    for (const auto& e : s.samples)
      t.rows.push_back(evaluation_row("vary_" + to_token(s.parameter), e));
  for (const auto& c : b.corners) t.rows.push_back(evaluation_row("corner", c));
  return csv(t);
}

json evaluation_json(const BandEvaluation& e) {
  json parameters = {{"critical_i1", finite(e.parameters.critical_i1, "critical I1")},
                     {"friction", finite(e.parameters.friction, "friction")},
                     {"j_lim", value_or_null(e.parameters.j_lim, "J_lim")},
                     {"shear_modulus_mpa", finite(e.parameters.shear_modulus_mpa, "G")}};
  if (!e.found) return {{"parameters", parameters}, {"found", false}, {"message", e.message}};
  return {{"parameters", parameters},
          {"found", true},
          {"force_n", finite(e.force_n, "puncture force")},
          {"depth_mm", finite(e.depth_mm, "puncture depth")},
          {"part_three_stretch", finite(e.part_three_stretch, "Part III stretch")},
          {"crack_location", e.crack_location}};
}

json direction_json(const std::optional<int>& d) {
  if (!d) return nullptr;
  return *d;
}

std::string json_text(const BandReport& r) {
  const auto& b = r.band;
  json intervals = json::object();
  for (const auto& s : b.sensitivities) {
    const auto i = static_cast<std::size_t>(s.parameter);
    intervals[to_token(s.parameter)] = {{"nominal", finite(s.nominal, "nominal value")},
                                        {"lower", finite(s.range.lower, "interval lower end")},
                                        {"upper", finite(s.range.upper, "interval upper end")},
                                        {"sd", value_or_null(r.sd[i], "standard deviation")}};
  }
  json sensitivities = json::array();
  for (const auto& s : b.sensitivities) {
    json samples = json::array();
    for (const auto& e : s.samples) samples.push_back(evaluation_json(e));
    sensitivities.push_back(
        {{"parameter", to_token(s.parameter)},
         {"force_change_n", value_or_null(s.force_change_n, "force change")},
         {"depth_change_mm", value_or_null(s.depth_change_mm, "depth change")},
         {"force_direction", direction_json(s.force_direction)},
         {"depth_direction", direction_json(s.depth_direction)},
         {"documented_force_direction", documented_force_direction(s.parameter)},
         {"documented_depth_direction", documented_depth_direction(s.parameter)},
         {"force_monotone", s.force_monotone},
         {"depth_monotone", s.depth_monotone},
         {"force_variance_share", value_or_null(s.force_variance_share, "variance share")},
         {"samples", samples}});
  }
  json corners = json::array();
  for (const auto& c : b.corners) corners.push_back(evaluation_json(c));
  const auto index = [](const std::optional<std::size_t>& i) -> json {
    if (!i) return nullptr;
    return *i;
  };
  return dump(
      {{"inputs",
        {{"problem", problem_json(r.problem, "")},
         {"intervals", intervals},
         {"sd_multiple", finite(r.sd_multiple, "sd multiple")}}},
       {"nominal", evaluation_json(b.nominal)},
       {"band",
        {{"force_min_n", value_or_null(b.force_min_n, "least force")},
         {"force_max_n", value_or_null(b.force_max_n, "largest force")},
         {"depth_min_mm", value_or_null(b.depth_min_mm, "least depth")},
         {"depth_max_mm", value_or_null(b.depth_max_mm, "largest depth")},
         {"force_min_corner", index(b.force_min_corner)},
         {"force_max_corner", index(b.force_max_corner)},
         {"depth_min_corner", index(b.depth_min_corner)},
         {"depth_max_corner", index(b.depth_max_corner)},
         {"force_half_range_rss_n", value_or_null(b.force_half_range_rss_n, "force spread")},
         {"dominant", b.dominant ? json(to_token(*b.dominant)) : json(nullptr)},
         {"complete", b.complete},
         {"consistent_with_documented_directions", b.consistent_with_documented_directions},
         {"warnings", b.warnings}}},
       {"sensitivities", sensitivities},
       {"corners", corners}});
}

template <class Report>
std::string render_any(const Report& r, Format format) {
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

}  // namespace

std::string calibration_text(const CriticalI1Report& r, Format f) { return render_any(r, f); }
std::string calibration_text(const FrictionReport& r, Format f) { return render_any(r, f); }
std::string calibration_text(const JLimReport& r, Format f) { return render_any(r, f); }
std::string calibration_text(const UniaxialFitReport& r, Format f) { return render_any(r, f); }
std::string calibration_text(const BandReport& r, Format f) { return render_any(r, f); }

}  // namespace puncture::cli
