// Writers of `puncture calibrate jlim`: readable summary, CSV (one row) and JSON.
#include <fmt/format.h>

#include <iterator>

#include "calibration/common_output.hpp"
#include "finite.hpp"
#include "json_helpers.hpp"
#include "tables.hpp"

namespace puncture::cli::calibration {

namespace {

json jlim_json(const JLimEstimate& e) {
  json scan = json::array();
  for (const auto& s : e.scan)
    scan.push_back({{"j_lim", finite(s.parameter, "scan J_lim")},
                    {"puncture_force_n", value_or_null(s.model, "scan force")}});
  json puncture = nullptr;
  if (e.puncture.ok())
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

}  // namespace

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
  if (p.ok())
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
  // The scan's stiff end is no physical bound: as J_lim falls to (critical I1 - 3) the law locks
  // at the puncture stretch and the puncture force grows without bound.
  line(out,
       "reachable forces",
       fmt::format("{} N (J_lim = {}; neo-Hookean limit {} N) and up, without bound",
                   num(e.smallest_force_n, "smallest force"),
                   num(e.max_j_lim, "largest J_lim"),
                   num(e.neo_hookean_force_n, "neo-Hookean force")));
  line(out,
       "",
       fmt::format("(as J_lim falls to critical I1 - 3 the rubber locks at the puncture stretch; "
                   "the scan stops at J_lim = {}, {} N)",
                   fmt::format("{:.8g}", finite(e.min_j_lim, "smallest J_lim")),
                   num(e.largest_force_n, "largest force")));
  return out;
}

std::string csv_text(const JLimReport& r) {
  const auto& e = r.estimate;
  const auto j = [](const std::optional<JLimEstimate>& x) -> std::optional<double> {
    return x ? value_of(x->j_lim) : std::nullopt;
  };
  const auto& p = e.puncture;
  const auto if_found = [&](double x) { return p.ok() ? std::optional<double>(x) : std::nullopt; };
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

}  // namespace puncture::cli::calibration
