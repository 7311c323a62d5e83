// Writers of `puncture calibrate band`: readable summary, CSV (one row per evaluation) and
// JSON.
#include <fmt/format.h>

#include "calibration/common_output.hpp"
#include "finite.hpp"
#include "json_helpers.hpp"
#include "puncture/puncture_band.hpp"
#include "tables.hpp"

namespace puncture::cli::calibration {

namespace {

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

std::vector<Cell> evaluation_row(const std::string& kind, const BandEvaluation& e) {
  const auto if_found = [&](double x) { return e.ok() ? std::optional<double>(x) : std::nullopt; };
  return {kind,
          e.parameters.critical_i1,
          e.parameters.friction,
          e.parameters.j_lim,
          e.parameters.shear_modulus_mpa,
          std::string(e.ok() ? "yes" : "no"),
          if_found(e.force_n),
          if_found(e.depth_mm),
          if_found(e.part_three_stretch),
          e.ok() ? std::string() : e.message};
}

json evaluation_json(const BandEvaluation& e) {
  json parameters = {{"critical_i1", finite(e.parameters.critical_i1, "critical I1")},
                     {"friction", finite(e.parameters.friction, "friction")},
                     {"j_lim", value_or_null(e.parameters.j_lim, "J_lim")},
                     {"shear_modulus_mpa", finite(e.parameters.shear_modulus_mpa, "G")}};
  if (!e.ok()) return {{"parameters", parameters}, {"found", false}, {"message", e.message}};
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

}  // namespace

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
    return e.ok() ? std::optional<double>(x) : std::nullopt;
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
         {"complete", b.ok()},
         {"consistent_with_documented_directions", b.consistent_with_documented_directions},
         {"warnings", b.warnings}}},
       {"sensitivities", sensitivities},
       {"corners", corners}});
}

}  // namespace puncture::cli::calibration
