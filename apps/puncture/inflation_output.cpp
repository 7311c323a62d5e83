// Writers of `inflate`: readable summary, CSV (one table, units in the column names) and JSON
// (every fact).
#include "inflation_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <optional>
#include <set>
#include <variant>
#include <vector>

#include "finite.hpp"
#include "json_helpers.hpp"
#include "tables.hpp"

namespace puncture::cli {

namespace {

// ----- a table of numbers and labels -----------------------------------------------------------

// The columns of `t` named in `keep`, in their order.
Table only(const Table& t, const std::vector<std::string>& keep) {
  std::vector<std::size_t> index;
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (std::find(keep.begin(), keep.end(), t.columns[c]) != keep.end()) index.push_back(c);
  Table out;
  for (const auto c : index) out.columns.push_back(t.columns[c]);
  for (const auto& row : t.rows) {
    auto& r = out.rows.emplace_back();
    for (const auto c : index) r.push_back(row[c]);
  }
  return out;
}

std::optional<double> bounded(double x, std::string_view what) {
  return finite_or_unbounded(x, what);
}

// ----- the states and fields -------------------------------------------------------------------

const std::vector<std::string> kStateColumns = {"pole_stretch",
                                                "pressure_mpa",
                                                "normalized_pressure",
                                                "pole_height_mm",
                                                "volume_mm3",
                                                "stored_energy_mj",
                                                "pole_curvature_radius_mm",
                                                "pole_tension_n_per_mm",
                                                "clamp_radial_stretch",
                                                "max_i1",
                                                "max_i1_R_mm",
                                                "max_i1_r_mm"};

// The summary's tables show these (CSV and JSON have every column).
const std::vector<std::string> kSummaryColumns = {"branch",
                                                  "pole_stretch",
                                                  "pressure_mpa",
                                                  "normalized_pressure",
                                                  "pole_height_mm",
                                                  "volume_mm3",
                                                  "stored_energy_mj",
                                                  "max_i1",
                                                  "max_i1_R_mm"};

std::vector<Cell> state_cells(const InflationState& s) {
  return {s.pole_stretch,
          s.pressure_mpa,
          s.normalized_pressure,
          s.pole_height_mm,
          s.volume_mm3,
          s.stored_energy_mj,
          bounded(s.pole_curvature_radius_mm, "pole_curvature_radius_mm"),
          s.pole_tension_n_per_mm,
          s.clamp_radial_stretch,
          s.max_first_invariant,
          s.max_first_invariant_reference_radius_mm,
          s.max_first_invariant_radius_mm};
}

Table fields_rows(const MembraneFields& f) {
  Table t{{"R_mm",
           "r_mm",
           "z_mm",
           "slope_rad",
           "lambda1",
           "lambda2",
           "lambda3",
           "s1_mpa",
           "s2_mpa",
           "I1"},
          {}};
  for (std::size_t i = 0; i < f.size(); ++i)
    t.rows.push_back({f.reference_radius_mm[i],
                      f.radius_mm[i],
                      f.deflection_mm[i],
                      f.slope_rad[i],
                      f.radial_stretch[i],
                      f.hoop_stretch[i],
                      f.thickness_stretch[i],
                      f.radial_stress_mpa[i],
                      f.hoop_stress_mpa[i],
                      f.first_invariant[i]});
  return t;
}

json state_json(const InflationState& s, bool with_fields) {
  Table one{kStateColumns, {state_cells(s)}};
  json out = rows_json(one).at(0);
  out["clamp_slope_rad"] = finite(s.clamp_slope_rad, "clamp slope");
  out["pole_stress_mpa"] = finite(s.pole_stress_mpa, "pole stress");
  out["clamp_residual"] = finite(s.clamp_residual, "clamp residual");
  out["shooting_evaluations"] = s.shooting_evaluations;
  if (with_fields) out["fields"] = rows_json(fields_rows(s.fields));
  return out;
}

json extremum_json(const PressureExtremum& e) {
  json out = {{"kind", to_string(e.kind)}};
  out.update(state_json(e.state, false));
  out["pressure_slope_mpa"] = finite(e.pressure_slope_mpa, "pressure slope");
  out["pressure_curvature_mpa"] = finite(e.curvature_mpa, "pressure curvature");
  return out;
}

json inputs_json(const InflationProblem& p) {
  return {{"clamp_radius_mm", finite(p.clamp_radius_mm, "clamp radius")},
          {"thickness_mm", finite(p.thickness_mm, "thickness")},
          {"material", material_json(p.material)},
          {"critical_i1", finite(p.critical_i1, "critical I1")},
          {"prestretch", finite(p.prestretch, "pre-stretch")},
          {"pressure_scale_mpa", finite(pressure_scale_mpa(p), "pressure scale")}};
}

// ----- summary pieces --------------------------------------------------------------------------

void summary_line(std::string& out, std::string_view label, std::string_view value) {
  out += fmt::format("  {:<26}{}\n", label, value);
}

void inputs(std::string& out, const InflationProblem& p) {
  out += "Inputs\n";
  summary_line(out, "clamp radius A", num(p.clamp_radius_mm, "clamp radius") + " mm");
  summary_line(out, "thickness H", num(p.thickness_mm, "thickness") + " mm");
  summary_line(out, "material", describe(p.material));
  summary_line(out, "critical I1 (burst)", num(p.critical_i1, "critical I1"));
  if (p.prestretch != 1.0)
    summary_line(
        out,
        "pre-stretch L0",
        num(p.prestretch, "pre-stretch") + " (stress-free disc of radius A / L0 clamped at A)");
  summary_line(
      out,
      "pressure scale G H / A",
      num(pressure_scale_mpa(p), "pressure scale") + " MPa (normalised pressure = p / this)");
}

// A pressure in the project's unit (MPa) and in kPa, the unit balloon and bulge tests are read in
// (and the Python inflation plot's).
std::string pressure_text(double pressure_mpa, std::string_view what) {
  return fmt::format("{} MPa ({} kPa)", num(pressure_mpa, what), num(pressure_mpa * 1e3, what));
}

std::string where_text(const InflationState& s) {
  if (s.max_first_invariant_reference_radius_mm == 0.0) return "the pole (R = 0)";
  return fmt::format("R = {} mm, r = {} mm",
                     num(s.max_first_invariant_reference_radius_mm, "largest I1 position"),
                     num(s.max_first_invariant_radius_mm, "largest I1 radius"));
}

void state_lines(std::string& out, const InflationState& s) {
  summary_line(out,
               "pressure",
               fmt::format("{} (p A / G H = {})",
                           pressure_text(s.pressure_mpa, "pressure"),
                           num(s.normalized_pressure, "normalised pressure")));
  summary_line(out, "pole stretch", num(s.pole_stretch, "pole stretch"));
  summary_line(out, "pole height", num(s.pole_height_mm, "pole height") + " mm");
  summary_line(out, "volume", num(s.volume_mm3, "volume") + " mm^3");
  summary_line(out, "stored energy", num(s.stored_energy_mj, "stored energy") + " mJ");
  const auto rho = bounded(s.pole_curvature_radius_mm, "pole radius of curvature");
  summary_line(out,
               "pole radius of curvature",
               rho ? num(*rho, "pole radius of curvature") + " mm" : "n/a (flat)");
  summary_line(out, "pole tension", num(s.pole_tension_n_per_mm, "pole tension") + " N/mm (true)");
  summary_line(out,
               "clamp",
               fmt::format("lambda1 = {}, slope {} deg",
                           num(s.clamp_radial_stretch, "clamp stretch"),
                           num(s.clamp_slope_rad * 180.0 / std::numbers::pi, "clamp slope")));
  summary_line(out,
               "largest I1",
               fmt::format("{} at {}", num(s.max_first_invariant, "largest I1"), where_text(s)));
}

void extremum_lines(std::string& out, const PressureExtremum& e) {
  const auto& s = e.state;
  const bool max = e.kind == ExtremumKind::Maximum;
  summary_line(out,
               max ? "pressure maximum" : "pressure minimum",
               fmt::format("{} at pole stretch {} (height {} mm, volume {} mm^3)",
                           pressure_text(s.pressure_mpa, "extremum pressure"),
                           num(s.pole_stretch, "extremum pole stretch"),
                           num(s.pole_height_mm, "extremum height"),
                           num(s.volume_mm3, "extremum volume")));
  out += max ? "    a limit point: under pressure control the membrane snaps through here\n"
             : "    the membrane stiffens again beyond\n";
}

void extrema_lines(std::string& out, const std::vector<PressureExtremum>& extrema) {
  if (extrema.empty()) summary_line(out, "pressure extrema", "none: the pressure rises throughout");
  for (const auto& e : extrema) extremum_lines(out, e);
}

// ----- the curve ---------------------------------------------------------------------------------

// The curve's states and, at their pole stretches, the extrema and the burst (labelled).
Table curve_rows(const InflationCurve& c, bool with_points) {
  Table t;
  t.columns = kStateColumns;
  if (with_points) t.columns.insert(t.columns.begin(), "point");
  struct Labelled {
    const InflationState* state;
    std::string label;
  };
  std::vector<Labelled> all;
  for (const auto& s : c.states) all.push_back({&s, "curve"});
  if (with_points) {
    for (const auto& e : c.extrema)
      all.push_back(
          {&e.state, e.kind == ExtremumKind::Maximum ? "pressure_maximum" : "pressure_minimum"});
    if (c.burst.ok() && c.burst.state.pole_stretch <= c.end_pole_stretch)
      all.push_back({&c.burst.state, "burst"});
    std::stable_sort(all.begin(), all.end(), [](const Labelled& a, const Labelled& b) {
      return a.state->pole_stretch < b.state->pole_stretch;
    });
  }
  for (const auto& l : all) {
    auto row = state_cells(*l.state);
    if (with_points) row.insert(row.begin(), l.label);
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string summary(const InflationCurveReport& r) {
  const auto& c = r.curve;
  std::string out;
  inputs(out, r.problem);
  out += fmt::format("Inflation curve ({} points, pole stretch 1 to {}, {})\n",
                     c.states.size(),
                     num(c.end_pole_stretch, "end pole stretch"),
                     r.to_burst ? "to the burst" : "set by --max-pole-stretch");
  extrema_lines(out, c.extrema);
  out += fmt::format("Burst (largest I1 = {})\n", num(r.problem.critical_i1, "critical I1"));
  if (!c.burst.ok()) {
    summary_line(out, "burst", "not found: " + c.burst.message);
  } else {
    state_lines(out, c.burst.state);
    if (c.burst.state.pole_stretch > c.end_pole_stretch)
      out += "  (beyond the end of the curve)\n";
    else if (c.burst.state.pole_stretch < c.end_pole_stretch * (1.0 - 1e-12))
      out += "  (the curve continues past the burst)\n";
  }
  out += "Curve (sampled; --format csv for every point)\n";
  const auto rows = only(curve_rows(c, false), kSummaryColumns);
  text_table(out, rows, spread_rows(rows.rows.size()));
  return out;
}

json curve_json(const InflationCurveReport& r) {
  const auto& c = r.curve;
  json extrema = json::array();
  for (const auto& e : c.extrema) extrema.push_back(extremum_json(e));
  json burst = {{"found", c.burst.ok()}};
  if (c.burst.ok())
    burst.update(state_json(c.burst.state, false));
  else
    burst["message"] = c.burst.message;
  return {{"inputs", inputs_json(r.problem)},
          {"curve",
           {{"end_pole_stretch", finite(c.end_pole_stretch, "end pole stretch")},
            {"ends_at", r.to_burst ? "burst" : "max_pole_stretch"},
            {"points", rows_json(curve_rows(c, false))},
            {"extrema", extrema},
            {"burst", burst}}}};
}

// ----- one state ---------------------------------------------------------------------------------

std::string summary(const InflationStateReport& r) {
  std::string out;
  inputs(out, r.problem);
  out +=
      fmt::format("Inflated state at pole stretch {}\n", num(r.state.pole_stretch, "pole stretch"));
  state_lines(out, r.state);
  if (r.state.max_first_invariant >= r.problem.critical_i1)
    out += "  (the largest I1 is at or beyond the critical I1: the membrane has burst)\n";
  const auto fields = fields_rows(r.state.fields);
  out += fmt::format(
      "Fields along the meridian from the pole ({} of {} points; --format csv for "
      "all)\n",
      spread_rows(fields.rows.size()).size(),
      fields.rows.size());
  text_table(out, fields, spread_rows(fields.rows.size()));
  return out;
}

// ----- at a pressure -----------------------------------------------------------------------------

Table pressure_rows(const InflationAtPressure& a) {
  Table t;
  t.columns = kStateColumns;
  t.columns.insert(t.columns.begin(), "branch");
  for (std::size_t k = 0; k < a.states.size(); ++k) {
    auto row = state_cells(a.states[k]);
    row.insert(row.begin(), std::to_string(k + 1));
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string summary(const InflationPressureReport& r) {
  const auto& a = r.result;
  std::string out;
  inputs(out, r.problem);
  out += fmt::format("States at pressure {} (pole stretch searched from 1 to {}, {})\n",
                     pressure_text(a.pressure_mpa, "pressure"),
                     num(a.max_pole_stretch, "search end"),
                     r.to_burst ? "the burst" : "set by --max-pole-stretch");
  summary_line(
      out,
      "states",
      a.states.size() == 1
          ? std::string("1")
          : fmt::format("{}; the first is reached by inflating slowly from flat", a.states.size()));
  extrema_lines(out, a.extrema);
  out += "States (--format json for their fields)\n";
  const auto rows = only(pressure_rows(a), kSummaryColumns);
  text_table(out, rows, spread_rows(rows.rows.size()));
  return out;
}

json pressure_json(const InflationPressureReport& r) {
  const auto& a = r.result;
  json states = json::array();
  for (const auto& s : a.states) states.push_back(state_json(s, true));
  json extrema = json::array();
  for (const auto& e : a.extrema) extrema.push_back(extremum_json(e));
  return {{"inputs", inputs_json(r.problem)},
          {"request", {{"pressure_mpa", finite(a.pressure_mpa, "pressure")}}},
          {"max_pole_stretch", finite(a.max_pole_stretch, "search end")},
          {"ends_at", r.to_burst ? "burst" : "max_pole_stretch"},
          {"message", a.message},
          {"states", states},
          {"extrema", extrema}};
}

}  // namespace

std::string inflation_text(const InflationCurveReport& r, Format format) {
  switch (format) {
    case Format::Csv:
      return csv(curve_rows(r.curve, true));
    case Format::Json:
      return dump(curve_json(r));
    case Format::Summary:
      break;
  }
  return summary(r);
}

std::string inflation_text(const InflationStateReport& r, Format format) {
  switch (format) {
    case Format::Csv:
      return csv(fields_rows(r.state.fields));
    case Format::Json:
      return dump({{"inputs", inputs_json(r.problem)}, {"state", state_json(r.state, true)}});
    case Format::Summary:
      break;
  }
  return summary(r);
}

std::string inflation_text(const InflationPressureReport& r, Format format) {
  switch (format) {
    case Format::Csv:
      return csv(pressure_rows(r.result));
    case Format::Json:
      return dump(pressure_json(r));
    case Format::Summary:
      break;
  }
  return summary(r);
}

}  // namespace puncture::cli
