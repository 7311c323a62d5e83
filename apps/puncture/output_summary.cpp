// Readable summary: inputs with units, the key facts of the result, and a compact table.
#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "finite.hpp"
#include "output.hpp"
#include "puncture/reports.hpp"
#include "tables.hpp"

namespace puncture::cli {

namespace {

// About 16 evenly spaced rows (all up to 24), the last one, and both sides of a stage change.
std::vector<std::size_t> sampled_rows(const std::vector<CurvePoint>& points) {
  const std::size_t n = points.size();
  const auto spread = spread_rows(n);
  std::set<std::size_t> rows(spread.begin(), spread.end());
  for (std::size_t i = 1; i < n; ++i)
    if (points[i].stage != points[i - 1].stage) rows.insert({i - 1, i});
  return {rows.begin(), rows.end()};
}

// The standard's outputs, named as it names them.
void add_astm_f1306(std::string& out, const std::optional<AstmF1306Outputs>& o) {
  if (!o) return;
  out += fmt::format(
      "ASTM F1306 (probe tip radius {} mm, opening radius {} mm)\n"
      "  maximum force                      {} N\n"
      "  probe penetration to perforation   {} mm\n"
      "  energy to perforation              {}\n",
      num(kAstmF1306TipRadiusMm, "tip radius"),
      num(kAstmF1306OpeningRadiusMm, "opening radius"),
      num(o->maximum_force_n, "maximum force"),
      num(o->penetration_mm, "penetration"),
      o->energy_mj ? num(*o->energy_mj, "energy") + " mJ" : std::string("n/a"));
}

}  // namespace

std::string summary_text(const CurveReport& r) {
  const auto& c = r.curve;
  std::string out = full_report(r.problem);
  const double end = c.points.empty() ? 0.0 : c.points.back().depth_mm;
  out += fmt::format("Loading curve ({} points, depth 0 to {} mm{})\n",
                     c.points.size(),
                     num(end, "end depth"),
                     r.max_depth_mm > 0.0 ? ", set by --max-depth" : "");
  out += full_report(c, r.problem);
  add_astm_f1306(out, r.astm_f1306);
  out += "Curve (sampled; --format csv for every point)\n";
  text_table(out, curve_table(c.points), sampled_rows(c.points));
  return out;
}

std::string summary_text(const StateReport& r) {
  const auto& e = r.state;
  std::string out = full_report(r.problem);
  out += fmt::format(
      "Equilibrium at {}, {} stage ({})\n",
      r.requested_force_n
          ? "force " + num(*r.requested_force_n, "requested force") + " N"
          : "depth " + num(r.requested_depth_mm.value_or(0.0), "requested depth") + " mm",
      to_string(e.stage),
      r.stage_choice);
  out += full_report(e, r.problem);
  const auto table = fields_table(e.fields);
  out += fmt::format(
      "Fields from the centre to the clamp ({} points; part 3 under the tip, 2 on the\n"
      "indenter's side, 1 free; R reference and r current radius, z deflection [mm];\n"
      "s1, s2 nominal stresses [MPa])\n",
      table.rows.size());
  text_table(out, table, all_rows(table));
  return out;
}

std::string summary_text(const VerifyReport& r) {
  const VerificationReport& v = r.verification;
  // A smooth profile (sphere-tipped, ball, cone, a filleted flat punch): the elements lie on it.
  const auto* punch = std::get_if<FlatPunch>(&r.problem.indenter);
  const bool smooth_probe = !punch || punch->fillet_radius_mm > 0.0;
  std::string out = full_report(r.problem);
  if (r.problem.preload.pressure_mpa > 0.0)
    out += fmt::format(
        "Verification: the shooting solver against independent methods\n"
        "  second method: finite elements, {} quadratic elements along the free part (and {}\n"
        "  for their own error), minimising U - p V from their own inflated dome at mu' = 0,\n"
        "  the membrane lying on the probe's profile (e.g. a flat punch: face, corner or fillet,\n"
        "  side) up to a contact edge the method finds; on a smooth probe with --stick also\n"
        "  held where the membrane touched (up to the rule's switch, then mu' = 0).  Under\n"
        "  pressure the small-deflection (Foppl) limit is not checked: the elements' dome\n"
        "  against the shooting's instead; friction (mu' = {} here) is checked by the test\n"
        "  suite's Coulomb identities.\n",
        v.elements,
        v.elements / 2,
        num(r.problem.friction, "friction"));
  else if (smooth_probe)
    out += fmt::format(
        "Verification: the shooting solver against independent methods\n"
        "  second method: finite elements, {} quadratic elements along the free part (and {}\n"
        "  for their own error), the membrane lying on the probe's profile up to a contact\n"
        "  edge the method finds, minimising the stored energy at mu' = 0; with --stick also\n"
        "  held where the membrane touched (force, pole stretch, edge, largest I1; up to the\n"
        "  rule's switch, then mu' = 0).  The small-deflection (Foppl) limit is not checked;\n"
        "  friction (mu' = {} here) is checked by the test suite's Coulomb identities.\n",
        v.elements,
        v.elements / 2,
        num(r.problem.friction, "friction"));
  else
    out += fmt::format(
        "Verification: the shooting solver against independent methods\n"
        "  second method: finite elements, {} quadratic elements along the free part (and {}\n"
        "  for their own error), minimising the stored energy; it covers the two limits of\n"
        "  the friction, mu' = 0 and the membrane held at the indenter's edge.  Friction in\n"
        "  between (mu' = {} here) is checked by the test suite's Coulomb and capstan "
        "identities.\n",
        v.elements,
        v.elements / 2,
        num(r.problem.friction, "friction"));
  out += full_report(v);
  if (!v.ok()) out += "(tolerances and their reasons: --format csv or json)\n";
  return out;
}

std::string summary_text(const PunctureReport& r) {
  std::string out = full_report(r.problem);
  out += full_report(r.puncture);
  // With --criterion: which of them the membrane meets first.
  if (!r.problem.criteria.empty() && r.puncture.ok())
    out += fmt::format("  {:<24}{}\n", "criterion met first", r.puncture.criterion);
  add_astm_f1306(out, r.astm_f1306);
  return out;
}

}  // namespace puncture::cli
