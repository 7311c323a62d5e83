// Readable summary: inputs with units, the key facts of the result, and a compact table.
#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <set>

#include "finite.hpp"
#include "output.hpp"
#include "part_two_onset.hpp"
#include "stick_spec.hpp"
#include "tables.hpp"

namespace puncture::cli {

namespace {

std::string num(double x, std::string_view what) { return fmt::format("{:.5g}", finite(x, what)); }

void line(std::string& out, std::string_view label, std::string_view value) {
  out += fmt::format("  {:<24}{}\n", label, value);
}

void inputs(std::string& out, const Problem& p) {
  const auto& g = p.geometry;
  out += "Inputs\n";
  line(out, "clamp radius A", num(g.clamp_radius_mm, "clamp radius") + " mm");
  // The flat punch's summary is unchanged; another shape is named.
  if (!std::holds_alternative<FlatPunch>(p.indenter)) line(out, "indenter", describe(p.indenter));
  line(out, "indenter radius a", num(radius_mm(p.indenter), "indenter radius") + " mm");
  line(out, "thickness H", num(g.thickness_mm, "thickness") + " mm");
  line(out, "material", describe(p.material));
  line(out, "friction mu'", num(p.friction, "friction"));
  line(out, "critical I1", num(p.critical_i1, "critical I1"));
  line(out, "stick criterion", describe_stick(p.stick));
  line(out, "Part II equation", to_string(p.part_two_equation));
  line(out,
       "force scale 2 pi G H A",
       num(force_scale_n(p), "force scale") + " N (normalised force = F / this)");
}

// About 16 evenly spaced rows (all up to 24), the last one, and both sides of a stage change.
std::vector<std::size_t> sampled_rows(const std::vector<CurvePoint>& points) {
  const std::size_t n = points.size();
  const auto spread = spread_rows(n);
  std::set<std::size_t> rows(spread.begin(), spread.end());
  for (std::size_t i = 1; i < n; ++i)
    if (points[i].stage != points[i - 1].stage) rows.insert({i - 1, i});
  return {rows.begin(), rows.end()};
}

std::string switch_text(const CurveReport& r) {
  const auto& c = r.curve;
  if (c.stick_slip.occurs)
    return fmt::format("at depth {} mm: force {} N (held) -> {} N (sliding)",
                       num(c.stick_slip.depth_mm, "switch depth"),
                       num(c.stick_slip.force_stuck_n, "force before the switch"),
                       num(c.stick_slip.force_sliding_n, "force after the switch"));
  if (r.problem.stick.rule == StickRule::None) return "none: slides from the first touch";
  if (r.problem.stick.rule == StickRule::Always) return "none: held throughout";
  return "none: still held at the end of the curve";
}

std::string part_two_text(const CurveReport& r) {
  const auto onset = part_two_onset(r.curve);
  if (!onset)
    return r.problem.stick.rule == StickRule::Always ? "never (the membrane is held)" : "not found";
  const auto& points = r.curve.points;
  const double end = points.empty() ? 0.0 : points.back().depth_mm;
  const auto text = fmt::format("at depth {} mm, force {} N{}",
                                num(onset->depth_mm, "Part II onset depth"),
                                num(onset->force_n, "Part II onset force"),
                                onset->at_switch ? ", on sliding at the stick -> slip switch" : "");
  return onset->depth_mm > end ? text + ", beyond the end of the curve" : text;
}

void puncture_lines(std::string& out, const PuncturePrediction& p) {
  out += "Puncture\n";
  if (!p.found) {
    line(out, "puncture", "not found: " + p.message);
    return;
  }
  line(out,
       "puncture force",
       fmt::format("{} N (F / 2 pi G H A = {})",
                   num(p.force_n, "puncture force"),
                   num(p.normalized_force, "normalised puncture force")));
  line(out, "puncture depth", num(p.depth_mm, "puncture depth") + " mm");
  line(out, "stage", to_string(p.stage));
  line(out, "configuration", to_string(p.configuration));
  line(out, "Part III stretch", num(p.part_three_stretch, "Part III stretch"));
  line(out, "largest I1", num(p.state.max_first_invariant, "largest I1"));
  line(out, "crack starts", p.crack_location);
  line(out,
       "crack position",
       fmt::format("reference radius R = {} mm, current radius r = {} mm",
                   num(p.crack_reference_radius_mm, "crack reference radius"),
                   num(p.crack_radius_mm, "crack radius")));
}

}  // namespace

std::string summary_text(const CurveReport& r) {
  const auto& c = r.curve;
  std::string out;
  inputs(out, r.problem);
  const double end = c.points.empty() ? 0.0 : c.points.back().depth_mm;
  out += fmt::format("Loading curve ({} points, depth 0 to {} mm{})\n",
                     c.points.size(),
                     num(end, "end depth"),
                     r.max_depth_mm > 0.0 ? ", set by --max-depth" : "");
  line(out, "stick -> slip switch", switch_text(r));
  line(out, "Part II appears", part_two_text(r));
  puncture_lines(out, c.puncture);
  if (c.puncture.found && c.puncture.depth_mm < end * (1.0 - 1e-9))
    out += "  (the curve continues past the puncture depth)\n";
  out += "Curve (sampled; --format csv for every point)\n";
  text_table(out, curve_table(c.points), sampled_rows(c.points));
  return out;
}

std::string summary_text(const StateReport& r) {
  const auto& e = r.state;
  std::string out;
  inputs(out, r.problem);
  out += fmt::format(
      "Equilibrium at {}, {} stage ({})\n",
      r.requested_force_n
          ? "force " + num(*r.requested_force_n, "requested force") + " N"
          : "depth " + num(r.requested_depth_mm.value_or(0.0), "requested depth") + " mm",
      to_string(e.stage),
      r.stage_choice);
  line(out, "configuration", to_string(e.configuration));
  line(out,
       "force",
       fmt::format("{} N (F / 2 pi G H A = {})",
                   num(e.force_n, "force"),
                   num(e.normalized_force, "normalised force")));
  line(out, "depth", num(e.depth_mm, "depth") + " mm");
  line(out, "Part III stretch", num(e.part_three_stretch, "Part III stretch"));
  line(out,
       "corner at reference R",
       num(e.corner_reference_radius_mm, "corner reference radius") + " mm");
  if (e.configuration == Configuration::SlipWithPartTwo)
    line(out,
         "Part II",
         fmt::format("length {} mm, top at reference R = {} mm",
                     num(e.part_two_length_mm, "Part II length"),
                     num(e.part_two_top_reference_radius_mm, "Part II top reference radius")));
  line(out,
       "corner slope",
       fmt::format("{} rad ({} deg)",
                   num(e.corner_slope_rad, "corner slope"),
                   num(e.corner_slope_rad * 180.0 / std::numbers::pi, "corner slope")));
  const auto ratio = finite_or_unbounded(e.corner_tension_ratio, "corner tension ratio");
  line(out,
       "corner tension ratio",
       ratio ? num(*ratio, "corner tension ratio") : "n/a (the membrane is held at the edge)");
  line(out,
       "largest I1",
       fmt::format("{} at reference R = {} mm ({} the critical {})",
                   num(e.max_first_invariant, "largest I1"),
                   num(e.max_first_invariant_reference_radius_mm, "largest I1 position"),
                   e.max_first_invariant >= r.problem.critical_i1 ? "at or beyond" : "below",
                   num(r.problem.critical_i1, "critical I1")));
  line(out, "clamp residual", fmt::format("{:.3g}", finite(e.clamp_residual, "clamp residual")));
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
  std::string out;
  inputs(out, r.problem);
  out += fmt::format(
      "Verification: the shooting solver against independent methods\n"
      "  second method: finite elements, {} quadratic elements along the free part (and {}\n"
      "  for their own error), minimising the stored energy; it covers the two limits of\n"
      "  the friction, mu' = 0 and the membrane held at the indenter's edge.  Friction in\n"
      "  between (mu' = {} here) is checked by the test suite's Coulomb and capstan identities.\n",
      v.elements,
      v.elements / 2,
      num(r.problem.friction, "friction"));
  std::string group, condition;
  for (const VerificationCheck& c : v.checks) {
    if (c.group != group) {
      group = c.group;
      condition.clear();
      out += fmt::format("{}\n  {:<40}{:>17}{:>17}{:>10}{:>9}  {}\n",
                         group,
                         "quantity",
                         "shooting",
                         "2nd method",
                         "rel.diff",
                         "tol",
                         "verdict");
    }
    if (c.condition != condition) out += fmt::format("  {}\n", condition = c.condition);
    if (!has_numbers(c)) {
      out += fmt::format("  {:<40}  {}: {}\n", c.quantity, to_string(c.verdict), c.note);
      continue;
    }
    out += fmt::format("  {:<40}{:>17.10g}{:>17.10g}{:>10.1e}{:>9.0e}  {}\n",
                       c.quantity,
                       finite(c.shooting, "shooting value"),
                       finite(c.reference, "second method's value"),
                       finite(c.difference, "difference"),
                       finite(c.tolerance, "tolerance"),
                       to_string(c.verdict));
  }
  out += fmt::format("Result: {} passed, {} failed, {} skipped{}\n",
                     v.count(Verdict::Pass),
                     v.count(Verdict::Fail),
                     v.count(Verdict::Skipped),
                     v.passed() ? "" : "  (tolerances and their reasons: --format csv or json)");
  return out;
}

std::string summary_text(const PunctureReport& r) {
  std::string out;
  inputs(out, r.problem);
  puncture_lines(out, r.puncture);
  return out;
}

}  // namespace puncture::cli
