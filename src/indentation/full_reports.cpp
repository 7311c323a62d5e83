// The full reports of the indentation results (puncture/reports.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>

#include "indentation/face_slip.hpp"
#include "puncture/energy_release.hpp"
#include "puncture/failure.hpp"
#include "puncture/inflation.hpp"
#include "puncture/reports.hpp"

namespace puncture {

namespace {

// Five significant digits; "n/a" for a number that is not finite (no report shows NaN).
std::string num(double x) { return std::isfinite(x) ? fmt::format("{:.5g}", x) : "n/a"; }

void line(std::string& out, std::string_view label, std::string_view value) {
  out += fmt::format("  {:<24}{}\n", label, value);
}

std::string failure(const Outcome& o) {
  return fmt::format("  {}: {}\n", to_string(o.status), o.message);
}

std::string switch_text(const LoadingCurve& c, const Problem& p) {
  // After a Coulomb release the curve follows the partial slip that joins the held and the
  // sliding branches continuously (docs/model.md §15.4).
  if (c.stick_slip.occurs && c.stick_slip.full_sliding_depth_mm)
    return fmt::format(
        "at depth {} mm, force {} N: the held edge needs |tau|/p = mu; a slip zone starts at "
        "the contact's edge and spreads inward (partial slip, no jump); its front reaches the "
        "pole at depth {} mm, force {} N: full sliding from there (docs/model.md, section 15.4)",
        num(c.stick_slip.depth_mm),
        num(c.stick_slip.force_stuck_n),
        num(*c.stick_slip.full_sliding_depth_mm),
        num(c.stick_slip.full_sliding_force_n));
  if (c.stick_slip.occurs && p.stick.rule == StickRule::Coulomb)
    return fmt::format(
        "at depth {} mm: force {} N (held) -> {} N (sliding); the curve jumps to full "
        "sliding here, where the held edge needs |tau|/p = mu: the partial slip that joins the "
        "two branches (docs/model.md, section 15.4) is not solved here (a flat face under a gas "
        "pressure, which slides too, or where the ends of its family are not found)",
        num(c.stick_slip.depth_mm),
        num(c.stick_slip.force_stuck_n),
        num(c.stick_slip.force_sliding_n));
  if (c.stick_slip.occurs)
    return fmt::format("at depth {} mm: force {} N (held) -> {} N (sliding)",
                       num(c.stick_slip.depth_mm),
                       num(c.stick_slip.force_stuck_n),
                       num(c.stick_slip.force_sliding_n));
  if (p.stick.rule == StickRule::None) return "none: slides from the first touch";
  if (p.stick.rule == StickRule::Always) return "none: held throughout";
  if (p.stick.rule == StickRule::Coulomb && !c.points.empty() &&
      c.points.back().stage == Stage::Slip)
    return "none: friction cannot hold the first material touched; slides from the first touch";
  if (c.puncture.ok() && c.puncture.at_switch && c.puncture.stage == Stage::Stick)
    return fmt::format(
        "at depth {} mm, force {} N (held): the membrane punctures as it starts "
        "sliding",
        num(c.puncture.depth_mm),
        num(c.puncture.force_n));
  return "none: still held at the end of the curve";
}

std::string part_two_text(const LoadingCurve& c, const Problem& p) {
  if (!c.part_two_onset_depth_mm || !c.part_two_onset_force_n)
    return p.stick.rule == StickRule::Always ? "never (the membrane is held)" : "not found";
  const double end = c.points.empty() ? 0.0 : c.points.back().depth_mm;
  const auto text =
      fmt::format("at depth {} mm, force {} N{}",
                  num(*c.part_two_onset_depth_mm),
                  num(*c.part_two_onset_force_n),
                  c.part_two_onset_at_switch ? ", on sliding at the stick -> slip switch" : "");
  return *c.part_two_onset_depth_mm > end ? text + ", beyond the end of the curve" : text;
}

// The curve's events, one line each (or that there are none: the force and the contact grow
// all the way).
void events_lines(std::string& out, const LoadingCurve& c) {
  if (c.events.empty()) {
    line(out, "snap-through", "none: the force and the contact grow with the depth");
    return;
  }
  for (const CurveEvent& e : c.events) {
    const char* label = e.kind == CurveEventKind::ForceMaximum  ? "SNAP-THROUGH (force)"
                        : e.kind == CurveEventKind::SnapThrough ? "SNAP-THROUGH (depth)"
                                                                : "CONTACT SHRINKS";
    line(out, label, e.description);
  }
}

// A sealed chamber's gas in a state.
// "fails first": the mode and why (docs/model.md §8.1).
std::string failure_verdict_text(const FailureVerdict& v) {
  return fmt::format("{}: {}", to_string(v.mode), v.reason);
}

std::string gas_text(const ChamberGas& gas) {
  return fmt::format("pressure {} MPa (gauge), enclosed volume {} mm^3 above the clamp plane",
                     num(gas.pressure_mpa),
                     num(gas.volume_mm3));
}

// The problem's criteria in words, "; "-separated.
std::string criteria_text(const Problem& p) {
  std::string out;
  for (const FailureCriterion& c : failure_criteria(p))
    out += fmt::format("{}{}", out.empty() ? "" : "; ", describe(c));
  return out;
}

// Each of Problem::criteria on the state: its measure where largest, there, and the ratio to
// its critical value.
void criteria_lines(std::string& out, const Equilibrium& e, const Problem& p) {
  for (const FailureCriterion& c : p.criteria) {
    if (const auto* energy = std::get_if<CriticalEnergyRelease>(&c)) {
      const EnergyRelease b = energy_release(p, e, energy->tearing_energy_n_per_mm);
      // "criterion energy-release" would fill the label's column.
      line(out,
           "energy balance",
           fmt::format("cut at R = {} mm releases {} mJ (intact {} mJ, cut {} mJ) against the "
                       "{} mJ it costs: ratio {}",
                       num(b.cut_reference_radius_mm),
                       num(b.released_energy_mj()),
                       num(b.stored_energy_mj),
                       num(b.punctured_energy_mj),
                       num(b.cut_energy_mj),
                       num(b.ratio())));
      continue;
    }
    const FailureAssessment a = assess(c, e, p);
    const std::string unit =
        criterion_unit(c).empty() ? std::string() : fmt::format(" {}", criterion_unit(c));
    line(out,
         fmt::format("criterion {}", criterion_name(c)),
         fmt::format("{}{} in {} at R = {} mm, r = {} mm: ratio {} to the critical {}{}",
                     num(a.value),
                     unit,
                     to_string(a.part),
                     num(a.reference_radius_mm),
                     num(a.radius_mm),
                     num(a.ratio()),
                     num(a.critical),
                     unit));
  }
}

}  // namespace

std::string full_report(const Problem& p) {
  const auto& g = p.geometry;
  std::string out = "Inputs\n";
  line(out, "clamp radius A", num(g.clamp_radius_mm) + " mm");
  line(out, "indenter", describe(p.indenter));
  line(out, "thickness H", num(g.thickness_mm) + " mm (stress-free)");
  const double l0 = p.preload.prestretch;
  line(out,
       "pre-stretch L0",
       l0 == 1.0 ? std::string("1 (mounted stress-free)")
                 : fmt::format("{} (equibiaxial: the stress-free disc of radius {} mm clamped at "
                               "A; I1 = {} before indentation)",
                               num(l0),
                               num(reference_clamp_radius_mm(p)),
                               num(2.0 * l0 * l0 + 1.0 / (l0 * l0 * l0 * l0))));
  if (p.preload.pressure_mpa > 0.0) {
    line(out,
         "gas pressure p",
         num(p.preload.pressure_mpa) +
             (p.preload.gas_volume_mm3
                  ? " MPa (gauge, when the chamber is sealed; the membrane is inflated first, "
                    "depths from the inflated pole)"
                  : " MPa (held; the membrane is inflated first, depths from the inflated pole)"));
    // Which inflated state the indentation starts from, when there is one (else the solve says
    // why): the first, reached by inflating slowly from flat, unless Preload::inflated_state
    // chooses another.
    SolverOptions quiet;
    quiet.record_fields = false;
    const int chosen = p.preload.inflated_state;
    if (const auto at =
            inflate_at_pressure(inflation_problem(p), p.preload.pressure_mpa, {}, quiet);
        at.ok()) {
      const std::size_t n = at.states.size();
      const std::size_t k =
          chosen == kLastInflatedState ? n : std::min(n, std::size_t(std::max(chosen, 1)));
      const auto& used = at.states[k - 1];
      std::string which;
      if (chosen == 1 && n > 1)
        which = fmt::format(
            " (the first of {} states at this pressure, reached by inflating slowly from flat; "
            "the others are not used)",
            n);
      else if (chosen != 1)
        which = fmt::format(
            " (state {} of {} at this pressure in order of pole stretch, as "
            "chosen; the first is reached by inflating slowly from flat)",
            k,
            n);
      line(out,
           "inflated state",
           fmt::format("pole stretch {}, pole {} mm above the clamp{}",
                       num(used.pole_stretch),
                       num(used.pole_height_mm),
                       which));
    }
  }
  if (const auto v0 = p.preload.gas_volume_mm3)
    line(out,
         "sealed chamber",
         fmt::format("{} mm^3 of gas under the flat membrane, closed at {} MPa gauge "
                     "(atmosphere {} MPa): isothermal, its pressure follows the enclosed volume",
                     num(*v0),
                     num(p.preload.pressure_mpa),
                     num(p.preload.atmospheric_pressure_mpa)));
  line(out, "material", describe(p.material));
  line(out, "friction mu'", num(p.friction));
  if (p.criteria.empty())
    line(out, "critical I1", num(p.critical_i1));
  else
    line(out, "failure criteria", criteria_text(p));
  line(out, "stick criterion", describe(p.stick));
  line(out, "Part II equation", to_string(p.part_two_equation));
  line(out, "force scale 2 pi G H A", num(force_scale_n(p)) + " N (normalised force = F / this)");
  return out;
}

std::string full_report(const Equilibrium& e, const Problem& p) {
  if (!e.ok()) return failure(e);
  std::string out;
  if (e.beyond_puncture)
    line(out,
         "BEYOND PUNCTURE",
         fmt::format("the criterion ({}) is exceeded: loaded to this state the membrane would "
                     "already have punctured",
                     criteria_text(p)));
  line(out, "configuration", to_string(e.configuration));
  line(out,
       "force",
       fmt::format("{} N (F / 2 pi G H A = {})", num(e.force_n), num(e.normalized_force)));
  line(out, "depth", num(e.depth_mm) + " mm");
  if (e.gas) line(out, "chamber gas", gas_text(*e.gas));
  if (e.configuration == Configuration::PartialSlip) {
    // The held core, the slipping annulus and Part I: no corner; the fields are not sampled.
    line(out, "pole stretch", num(e.part_three_stretch) + " (held where it touched)");
    line(out,
         "slip front",
         fmt::format("reference R = {} mm, current r = {} mm (held inside, sliding outside)",
                     num(e.slip_front_reference_radius_mm),
                     num(e.slip_front_radius_mm)));
    line(out,
         "contact edge",
         fmt::format("r = {} mm, {} mm above the tip",
                     num(e.contact_edge_radius_mm),
                     num(e.contact_edge_height_mm)));
    line(out, "largest I1", num(e.max_first_invariant));
    line(out, "note", e.message);
    return out;
  }
  line(out, "Part III stretch", num(e.part_three_stretch));
  line(out, "corner at reference R", num(e.corner_reference_radius_mm) + " mm");
  if (e.configuration == Configuration::SlipWithPartTwo)
    line(out,
         "Part II",
         fmt::format("length {} mm, top at reference R = {} mm",
                     num(e.part_two_length_mm),
                     num(e.part_two_top_reference_radius_mm)));
  line(out,
       "corner slope",
       fmt::format("{} rad ({} deg)",
                   num(e.corner_slope_rad),
                   num(e.corner_slope_rad * 180.0 / std::numbers::pi)));
  line(out,
       "corner tension ratio",
       std::isinf(e.corner_tension_ratio) ? "n/a (the membrane is held at the edge)"
                                          : num(e.corner_tension_ratio));
  if (p.criteria.empty())
    line(out,
         "largest I1",
         fmt::format("{} at reference R = {} mm ({} the critical {})",
                     num(e.max_first_invariant),
                     num(e.max_first_invariant_reference_radius_mm),
                     e.max_first_invariant >= p.critical_i1 ? "at or beyond" : "below",
                     num(p.critical_i1)));
  else {
    line(out,
         "largest I1",
         fmt::format("{} at reference R = {} mm",
                     num(e.max_first_invariant),
                     num(e.max_first_invariant_reference_radius_mm)));
    criteria_lines(out, e, p);
  }
  line(out,
       "clamp residual",
       std::isfinite(e.clamp_residual) ? fmt::format("{:.3g}", e.clamp_residual) : "n/a");
  return out;
}

std::string full_report(const PuncturePrediction& p) {
  std::string out = "Puncture\n";
  if (!p.ok()) {
    line(out, "puncture", "not found: " + p.message);
    return out;
  }
  line(out,
       "puncture force",
       fmt::format("{} N (F / 2 pi G H A = {})", num(p.force_n), num(p.normalized_force)));
  line(out, "puncture depth", num(p.depth_mm) + " mm");
  if (const auto& snap = p.snap_through)
    line(out,
         "snap-through (depth)",
         fmt::format("on the way, under depth control (the loading curve's), at {} mm: the force "
                     "drops from {} N to {} N, onto the first inflated state{}; the puncture is "
                     "on that state (under force control the path passes the fold)",
                     num(snap->depth_mm),
                     num(snap->force_n),
                     num(snap->force_after_n.value_or(0.0)),
                     snap->end_depth_mm ? fmt::format(" (the probe leaves the membrane and "
                                                      "touches it again at {} mm)",
                                                      num(*snap->end_depth_mm))
                                        : std::string()));
  if (p.state.gas) line(out, "chamber gas", gas_text(*p.state.gas));
  if (p.energy_to_puncture_mj)
    line(out,
         "energy to puncture",
         num(*p.energy_to_puncture_mj) +
             (p.snap_through ? " mJ (the area under the force-depth curve depth control "
                               "follows: the drop at the snap-through adds nothing)"
                             : " mJ (the area under the force-depth curve)"));
  else if (!p.message.empty())
    line(out, "note", p.message);
  line(out, "stage", to_string(p.stage));
  line(out, "configuration", to_string(p.configuration));
  line(out, "Part III stretch", num(p.part_three_stretch));
  line(out, "largest I1", num(p.state.max_first_invariant));
  line(out, "crack starts", p.crack_location);
  line(out,
       "crack position",
       fmt::format("reference radius R = {} mm, current radius r = {} mm",
                   num(p.crack_reference_radius_mm),
                   num(p.crack_radius_mm)));
  if (p.failure_verdict) line(out, "fails first", failure_verdict_text(*p.failure_verdict));
  return out;
}

std::string full_report(const LoadingCurve& c, const Problem& p) {
  if (!c.ok()) return failure(c);
  std::string out;
  const auto beyond = std::count_if(
      c.points.begin(), c.points.end(), [](const CurvePoint& q) { return q.beyond_puncture; });
  if (beyond > 0)
    line(out,
         "BEYOND PUNCTURE",
         fmt::format("{} of the {} points lie past the puncture point: the membrane would "
                     "already have punctured (beyond_puncture = 1 in the table)",
                     beyond,
                     c.points.size()));
  if (detail::face_friction_direction_matters(p)) {
    const auto before = std::count_if(c.points.begin(), c.points.end(), [&](const CurvePoint& q) {
      return !c.face_slides_outward_from_mm || q.depth_mm < *c.face_slides_outward_from_mm;
    });
    if (before > 0)
      line(out,
           "NOT THE MEMBRANE'S",
           fmt::format("{} of the {} points: there the membrane on the punch's face slides inward, "
                       "where the model's friction assumes outward sliding (docs/model.md §17); {}",
                       before,
                       c.points.size(),
                       c.face_slides_outward_from_mm
                           ? fmt::format("it slides outward from {} mm on",
                                         num(*c.face_slides_outward_from_mm))
                           : std::string("no point slides outward")));
  }
  line(out, "stick -> slip switch", switch_text(c, p));
  line(out, "Part II appears", part_two_text(c, p));
  events_lines(out, c);
  if (!c.beyond_fold.empty())
    line(out,
         "beyond the fold",
         fmt::format("{} states past the fold followed by arc length (not reached under depth "
                     "control): the depth falls to {} mm as the force rises to {} N",
                     c.beyond_fold.size(),
                     num(c.beyond_fold.back().depth_mm),
                     num(c.beyond_fold.back().force_n)));
  out += full_report(c.puncture);
  if (c.failure_verdict) line(out, "fails first", failure_verdict_text(*c.failure_verdict));
  const double end = c.points.empty() ? 0.0 : c.points.back().depth_mm;
  if (c.puncture.ok() && c.puncture.depth_mm < end * (1.0 - 1e-9))
    out += "  (the curve continues past the puncture depth)\n";
  return out;
}

}  // namespace puncture
