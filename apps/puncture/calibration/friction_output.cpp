// Writers of `puncture calibrate friction`: readable summary, CSV (one row per method) and JSON.
#include <fmt/format.h>

#include "calibration/common_output.hpp"
#include "finite.hpp"
#include "json_helpers.hpp"
#include "tables.hpp"

namespace puncture::cli::calibration {

namespace {

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
  if (!e.friction.ok()) return;
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

}  // namespace

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

}  // namespace puncture::cli::calibration
