#include "json_helpers.hpp"

#include "finite.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/failure.hpp"
#include "puncture/material.hpp"
#include "stick_spec.hpp"

namespace puncture::cli {

std::string dump(const json& j) { return j.dump(2) + "\n"; }

json rows_json(const Table& table) {
  json rows = json::array();
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    json row = json::object();
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      const auto& cell = table.rows[r][c];
      if (const auto* text = std::get_if<std::string>(&cell))
        row[table.columns[c]] = *text;
      else if (const auto* count = std::get_if<int>(&cell))
        row[table.columns[c]] = *count;
      else if (is_missing(cell))
        row[table.columns[c]] = nullptr;
      else
        row[table.columns[c]] = checked_number(table, r, c);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

json value_or_null(const std::optional<double>& x, std::string_view what) {
  if (!x) return nullptr;
  return finite(*x, what);
}

json material_json(const Material& m, bool with_j_lim) {
  json material = {{"law", law_name(m.law)},
                   {"shear_modulus_mpa", finite(m.shear_modulus_mpa, "shear modulus")}};
  if (const auto* gent = std::get_if<Gent>(&m.law); gent && with_j_lim)
    material["j_lim"] = finite(gent->j_lim, "J_lim");
  if (const auto* mr = std::get_if<MooneyRivlin>(&m.law))
    material["alpha"] = finite(mr->alpha, "Mooney-Rivlin alpha");
  if (const auto* yeoh = std::get_if<Yeoh>(&m.law)) {  // C10 = G / 2, Ci0 = ci G
    material["c10_mpa"] = finite(0.5 * m.shear_modulus_mpa, "Yeoh C10");
    material["c20_mpa"] = finite(yeoh->c2 * m.shear_modulus_mpa, "Yeoh C20");
    material["c30_mpa"] = finite(yeoh->c3 * m.shear_modulus_mpa, "Yeoh C30");
  }
  if (const auto* ogden = std::get_if<Ogden>(&m.law)) {  // mu_p = (mu_p / G) G
    json mu = json::array();
    for (const double x : ogden->mu) mu.push_back(finite(x * m.shear_modulus_mpa, "Ogden mu"));
    material["mu_mpa"] = mu;
    material["alpha"] = ogden->alpha;
  }
  if (const auto* ab = std::get_if<ArrudaBoyce>(&m.law))
    material["chain_segments"] = finite(ab->n, "Arruda-Boyce N");
  if (const auto* gg = std::get_if<GentGent>(&m.law)) {
    material["j_lim"] = finite(gg->j_lim, "J_lim");
    material["beta"] = finite(gg->beta, "Gent-Gent beta");
  }
  return material;
}

json stick_json(const StickCriterion& s) {
  json stick = {{"rule", to_string(s.rule)}};
  if (const auto unit = threshold_unit(s.rule); !unit.empty()) {
    stick["threshold"] = finite(s.threshold, "stick threshold");
    stick["threshold_unit"] = unit;
  }
  return stick;
}

json problem_json(const Problem& p, std::string_view calibrated) {
  json out = {{"clamp_radius_mm", finite(p.geometry.clamp_radius_mm, "clamp radius")},
              {"indenter_radius_mm", finite(radius_mm(p.indenter), "indenter radius")},
              {"thickness_mm", finite(p.geometry.thickness_mm, "thickness")},
              {"prestretch", finite(p.preload.prestretch, "pre-stretch")},
              {"material", material_json(p.material, calibrated != "jlim")}};
  if (calibrated != "friction") out["friction"] = finite(p.friction, "friction");
  if (p.criteria.empty())
    out["critical_i1"] = finite(p.critical_i1, "critical I1");
  else {
    json criteria = json::array();
    for (const FailureCriterion& c : p.criteria)
      criteria.push_back({{"name", criterion_name(c)},
                          {"critical", finite(critical_value(c), "critical value")},
                          {"unit", criterion_unit(c)}});
    out["criteria"] = criteria;
  }
  out["stick"] = stick_json(p.stick);
  out["part_two_equation"] = to_string(p.part_two_equation);
  if (p.preload.pressure_mpa > 0.0)
    out["pressure_mpa"] = finite(p.preload.pressure_mpa, "pressure");
  if (const auto v0 = p.preload.gas_volume_mm3) {
    out["gas_volume_mm3"] = finite(*v0, "gas volume");
    out["atmospheric_pressure_mpa"] =
        finite(p.preload.atmospheric_pressure_mpa, "atmospheric pressure");
  }
  // The flat punch's JSON is unchanged; another shape is named.
  if (std::holds_alternative<SphereTipped>(p.indenter)) out["indenter"] = "sphere-tipped";
  if (const auto* punch = std::get_if<FlatPunch>(&p.indenter);
      punch && punch->fillet_radius_mm > 0.0)
    out["fillet_radius_mm"] = finite(punch->fillet_radius_mm, "fillet radius");
  if (const auto* ball = std::get_if<Ball>(&p.indenter)) {
    out["indenter"] = "ball";
    out["ball_radius_mm"] = finite(ball->ball_radius_mm, "ball radius");
  }
  if (const auto* cone = std::get_if<Cone>(&p.indenter)) {
    out["indenter"] = "cone";
    out["cone_half_angle_deg"] = finite(cone->half_angle_deg, "cone half-angle");
    out["tip_radius_mm"] = finite(cone->tip_radius_mm, "tip radius");
  }
  // A curved probe's meridian, for the plots to draw it to scale (the sharp punch is a rectangle).
  if (!sharp_flat_punch(p.indenter)) {
    json r = json::array(), height = json::array();
    for (const auto& point : outline(p.indenter)) {
      r.push_back(finite(point.r_mm, "outline radius"));
      height.push_back(finite(point.height_mm, "outline height"));
    }
    out["indenter_outline"] = {{"r_mm", r}, {"height_mm", height}};
  }
  return out;
}

}  // namespace puncture::cli
