// JSON writer: the same facts as the summary, every number checked finite; a quantity that is
// unbounded in some states (the corner tension ratio of a held membrane) is written as null.
#include "finite.hpp"
#include "json_helpers.hpp"
#include "output.hpp"
#include "puncture/energy_release.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/failure.hpp"
#include "puncture/material.hpp"
#include "tables.hpp"

namespace puncture::cli {

namespace {

json inputs_json(const Problem& p) {
  json out = problem_json(p);
  out["force_scale_n"] = finite(force_scale_n(p), "force scale");
  return out;
}

// Which failure comes first (docs/model.md §8.1).
json failure_verdict_json(const FailureVerdict& v) {
  return {{"mode", to_token(v.mode)},
          {"depth_mm", finite(v.depth_mm, "first failure depth")},
          {"force_n", finite(v.force_n, "first failure force")},
          {"where", v.where},
          {"reason", v.reason}};
}

json puncture_json(const PuncturePrediction& p, const Problem& problem) {
  if (!p.ok()) return {{"found", false}, {"message", p.message}};
  json out = rows_json(puncture_table(p)).at(0);
  out["found"] = true;
  if (!problem.criteria.empty()) out["criterion"] = p.criterion;
  // Written only when there is one (a pre-tensioned membrane).
  if (p.failure_verdict) out["failure_verdict"] = failure_verdict_json(*p.failure_verdict);
  // Written only when the path snaps through at a fold of the depth on the way (docs/model.md
  // §8.1): the puncture is depth control's.
  if (const auto& snap = p.snap_through)
    out["snap_through"] = {
        {"control", "depth"},
        {"depth_mm", finite(snap->depth_mm, "snap-through depth")},
        {"force_before_n", finite(snap->force_n, "force before the snap-through")},
        {"force_after_n",
         finite(snap->force_after_n.value_or(0.0), "force after the snap-through")},
        {"touches_again_at_mm",
         snap->end_depth_mm ? json(finite(*snap->end_depth_mm, "depth of the next touch"))
                            : json(nullptr)},
        {"description", snap->description}};
  return out;
}

// The energy-release criterion's balance [mJ].
json energy_release_json(const EnergyRelease& b) {
  return {{"stored_energy_mj", finite(b.stored_energy_mj, "stored energy")},
          {"cut_membrane_energy_mj", finite(b.punctured_energy_mj, "cut membrane's energy")},
          {"released_energy_mj", finite(b.released_energy_mj(), "released energy")},
          {"cut_energy_mj", finite(b.cut_energy_mj, "cut's tearing energy")},
          {"ratio", finite(b.ratio(), "released over cost")},
          {"cut_reference_radius_mm", finite(b.cut_reference_radius_mm, "cut's R")},
          {"collar_reference_radius_mm", finite(b.collar_reference_radius_mm, "collar's end R")},
          {"hole_radius_mm", finite(b.hole_radius_mm, "hole's radius")}};
}

// Each of the problem's --criterion on the state: measure where largest, place, ratio (and the
// energy release's balance).
json criteria_json(const Equilibrium& e, const Problem& p) {
  json out = json::array();
  for (const FailureCriterion& c : p.criteria) {
    const FailureAssessment a = assess(c, e, p);
    json item = {{"name", criterion_name(c)},
                 {"measure", measure_name(c)},
                 {"unit", criterion_unit(c)},
                 {"value", finite(a.value, "criterion measure")},
                 {"critical", finite(a.critical, "critical value")},
                 {"ratio", finite(a.ratio(), "ratio to the critical value")},
                 {"part", static_cast<int>(a.part)},
                 {"reference_radius_mm", finite(a.reference_radius_mm, "criterion's R")},
                 {"radius_mm", finite(a.radius_mm, "criterion's r")}};
    if (const auto* energy = std::get_if<CriticalEnergyRelease>(&c))
      item["energy_release"] =
          energy_release_json(energy_release(p, e, energy->tearing_energy_n_per_mm));
    out.push_back(item);
  }
  return out;
}

// The standard's outputs (null when the report has none).
json astm_f1306_json(const std::optional<AstmF1306Outputs>& o) {
  if (!o) return nullptr;
  return {{"probe_tip_radius_mm", kAstmF1306TipRadiusMm},
          {"opening_radius_mm", kAstmF1306OpeningRadiusMm},
          {"maximum_force_n", finite(o->maximum_force_n, "maximum force")},
          {"penetration_to_perforation_mm", finite(o->penetration_mm, "penetration")},
          {"energy_to_perforation_mj",
           o->energy_mj ? json(finite(*o->energy_mj, "energy to perforation")) : json()}};
}

json state_json(const Equilibrium& e) {
  json out = {
      {"status", to_string(e.status)},
      {"stage", to_string(e.stage)},
      {"configuration", to_token(e.configuration)},
      {"force_n", finite(e.force_n, "force")},
      {"normalized_force", finite(e.normalized_force, "normalised force")},
      {"depth_mm", finite(e.depth_mm, "depth")},
      {"part_three_stretch", finite(e.part_three_stretch, "Part III stretch")},
      {"corner_reference_radius_mm",
       finite(e.corner_reference_radius_mm, "corner reference radius")},
      {"part_two_top_reference_radius_mm",
       finite(e.part_two_top_reference_radius_mm, "Part II top reference radius")},
      {"part_two_length_mm", finite(e.part_two_length_mm, "Part II length")},
      {"corner_slope_rad", finite(e.corner_slope_rad, "corner slope")},
      {"corner_tension_ratio", nullptr},
      {"max_i1", finite(e.max_first_invariant, "largest I1")},
      {"max_i1_reference_radius_mm",
       finite(e.max_first_invariant_reference_radius_mm, "reference radius of the largest I1")},
      {"clamp_residual", finite(e.clamp_residual, "clamp residual")},
      {"shooting_evaluations", e.shooting_evaluations},
      {"beyond_puncture", e.beyond_puncture},
  };
  if (const auto ratio = finite_or_unbounded(e.corner_tension_ratio, "corner tension ratio"))
    out["corner_tension_ratio"] = *ratio;
  if (e.configuration == Configuration::PartialSlip) {
    out["slip_front_reference_radius_mm"] =
        finite(e.slip_front_reference_radius_mm, "slip front reference radius");
    out["slip_front_radius_mm"] = finite(e.slip_front_radius_mm, "slip front radius");
  }
  if (e.gas)
    out["gas"] = {{"pressure_mpa", finite(e.gas->pressure_mpa, "chamber's gas pressure")},
                  {"volume_mm3", finite(e.gas->volume_mm3, "enclosed volume")}};
  out["fields"] = rows_json(fields_table(e.fields));
  return out;
}

json curve_json(const CurveReport& r) {
  const auto& c = r.curve;
  json stick_slip = {{"occurs", c.stick_slip.occurs}};
  if (!c.points.empty()) stick_slip["first_stage"] = to_string(c.points.front().stage);
  if (c.stick_slip.occurs) {
    stick_slip["depth_mm"] = finite(c.stick_slip.depth_mm, "switch depth");
    stick_slip["force_stuck_n"] = finite(c.stick_slip.force_stuck_n, "force before the switch");
    stick_slip["force_sliding_n"] = finite(c.stick_slip.force_sliding_n, "force after the switch");
    if (c.stick_slip.full_sliding_depth_mm) {
      stick_slip["full_sliding_depth_mm"] =
          finite(*c.stick_slip.full_sliding_depth_mm, "depth of full sliding");
      stick_slip["full_sliding_force_n"] =
          finite(c.stick_slip.full_sliding_force_n, "force at full sliding");
    }
  }
  json part_two = nullptr;
  if (c.part_two_onset_depth_mm && c.part_two_onset_force_n)
    part_two = {{"depth_mm", finite(*c.part_two_onset_depth_mm, "Part II onset depth")},
                {"force_n", finite(*c.part_two_onset_force_n, "Part II onset force")},
                {"at_stick_slip_switch", c.part_two_onset_at_switch}};
  json out = {{"points_requested", r.points_requested},
              {"max_depth_mm", nullptr},
              {"stick_slip", stick_slip},
              {"part_two_onset", part_two},
              {"points", rows_json(curve_table(c.points))}};
  if (r.max_depth_mm > 0.0) out["max_depth_mm"] = finite(r.max_depth_mm, "max depth");
  // Written only when there are any (docs/model.md §8.1).
  if (!c.events.empty()) {
    json events = json::array();
    for (const CurveEvent& e : c.events) {
      json event = {
          {"kind", to_token(e.kind)},
          {"depth_mm", finite(e.depth_mm, "event depth")},
          {"force_n", finite(e.force_n, "event force")},
          {"end_depth_mm",
           e.end_depth_mm ? json(finite(*e.end_depth_mm, "event end depth")) : json(nullptr)},
          {"contact_reach_mm", finite(e.contact_reach_mm, "contact reach")},
          {"depth_uncertainty_mm", finite(e.depth_uncertainty_mm, "event depth uncertainty")},
          {"description", e.description}};
      if (e.force_after_n) event["force_after_n"] = finite(*e.force_after_n, "force after");
      events.push_back(event);
    }
    out["events"] = events;
  }
  // The branch past a fold of the depth, followed by arc length (docs/model.md §8.1).
  if (!c.beyond_fold.empty()) out["beyond_fold"] = rows_json(curve_table(c.beyond_fold));
  if (c.failure_verdict) out["failure_verdict"] = failure_verdict_json(*c.failure_verdict);
  // A flat punch under a gas pressure with friction: the points before it are not the membrane's
  // states (its face slides inward there).
  if (std::holds_alternative<FlatPunch>(r.problem.indenter) &&
      (r.problem.preload.pressure_mpa > 0.0 || r.problem.preload.gas_volume_mm3) &&
      r.problem.friction > 0.0)
    out["face_slides_outward_from_mm"] =
        c.face_slides_outward_from_mm
            ? json(finite(*c.face_slides_outward_from_mm, "face's outward sliding depth"))
            : json(nullptr);
  return out;
}

}  // namespace

std::string json_text(const CurveReport& r) {
  json out = {{"inputs", inputs_json(r.problem)},
              {"curve", curve_json(r)},
              {"puncture", puncture_json(r.curve.puncture, r.problem)}};
  if (r.astm_f1306) out["astm_f1306"] = astm_f1306_json(r.astm_f1306);
  return dump(out);
}

std::string json_text(const StateReport& r) {
  json request = {{"stage", to_string(r.state.stage)}, {"stage_choice", r.stage_choice}};
  if (r.requested_force_n) request["force_n"] = finite(*r.requested_force_n, "requested force");
  if (r.requested_depth_mm) request["depth_mm"] = finite(*r.requested_depth_mm, "requested depth");
  json state = state_json(r.state);
  if (!r.problem.criteria.empty()) state["criteria"] = criteria_json(r.state, r.problem);
  return dump({{"inputs", inputs_json(r.problem)}, {"request", request}, {"state", state}});
}

std::string json_text(const VerifyReport& r) {
  const VerificationReport& v = r.verification;
  json checks = json::array();
  for (const VerificationCheck& c : v.checks) {
    const bool skipped = !has_numbers(c);
    auto number = [&](double x, const char* what) {
      return skipped ? json() : json(finite(x, what));
    };
    checks.push_back({{"group", c.group},
                      {"quantity", c.quantity},
                      {"condition", c.condition},
                      {"shooting", number(c.shooting, "shooting value")},
                      {"second_method", number(c.reference, "second method's value")},
                      {"relative_difference", number(c.difference, "difference")},
                      {"tolerance", number(c.tolerance, "tolerance")},
                      {"verdict", to_string(c.verdict)},
                      {"note", c.note}});
  }
  return dump({{"inputs", inputs_json(r.problem)},
               {"finite_elements", v.elements},
               {"passed", v.ok()},
               {"counts",
                {{"pass", v.count(Verdict::Pass)},
                 {"fail", v.count(Verdict::Fail)},
                 {"skipped", v.count(Verdict::Skipped)}}},
               {"checks", checks}});
}

std::string json_text(const PunctureReport& r) {
  json out = {{"inputs", inputs_json(r.problem)},
              {"puncture", puncture_json(r.puncture, r.problem)}};
  if (r.astm_f1306) out["astm_f1306"] = astm_f1306_json(r.astm_f1306);
  return dump(out);
}

}  // namespace puncture::cli
