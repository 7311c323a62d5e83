#include "puncture/problem.hpp"

#include <fmt/format.h>

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <variant>

#include "failure/cut_membrane.hpp"
#include "indentation/probe_shape_errors.hpp"
#include "mechanics/falling_stress.hpp"
#include "mechanics/membrane_validation.hpp"
#include "puncture/energy_release.hpp"
#include "puncture/failure.hpp"
#include "puncture/inflation.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture {

namespace detail {

void require_positive(std::vector<ValidationError>& errors, std::string parameter, const char* name,
                      double value, const char* unit) {
  if (!std::isfinite(value) || value <= 0.0)
    errors.push_back({std::move(parameter),
                      fmt::format("{} must be a finite number > 0 {}, got {}", name, unit, value)});
}

// Ogden (materials/ogden.hpp): 1 to 3 terms, one exponent per coefficient, the consistency
// condition sum mu_p alpha_p = 2 G (mu holds mu_p / G), and each term with mu_p alpha_p > 0 and
// |alpha_p| >= 1, which makes s1 grow with lambda1 and keeps the wrinkling sign rule.
static void append_ogden_errors(std::vector<ValidationError>& errors, const Ogden& ogden) {
  if (ogden.mu.size() != ogden.alpha.size()) {
    errors.push_back({"material.law.alpha",
                      fmt::format("Ogden needs one exponent alpha_p per coefficient mu_p: got {} "
                                  "mu and {} alpha",
                                  ogden.mu.size(),
                                  ogden.alpha.size())});
    return;
  }
  if (ogden.mu.empty() || ogden.mu.size() > 3) {
    errors.push_back(
        {"material.law.mu",
         fmt::format("Ogden takes 1 to 3 terms (mu_p, alpha_p), got {}", ogden.mu.size())});
    return;
  }
  double twice = 0.0;  // sum mu_p alpha_p / G
  for (std::size_t p = 0; p < ogden.mu.size(); ++p) {
    const double m = ogden.mu[p], a = ogden.alpha[p];
    twice += m * a;
    if (!std::isfinite(m) || !std::isfinite(a))
      errors.push_back({"material.law.mu",
                        fmt::format("Ogden term {}: mu_p and alpha_p must be finite numbers, got "
                                    "mu_p = {}, alpha_p = {}",
                                    p + 1,
                                    m,
                                    a)});
    else if (!(m * a > 0.0))
      errors.push_back(
          {"material.law.mu",
           fmt::format("Ogden term {}: mu_p alpha_p must be > 0 (each term's share of the "
                       "shear modulus; with mu_p alpha_p <= 0 the term softens the membrane as "
                       "it stretches and its hoop stress loses the sign the solver relies on), "
                       "got mu_p alpha_p = {:g} G",
                       p + 1,
                       m * a)});
    else if (!(std::abs(a) >= 1.0))
      errors.push_back(
          {"material.law.alpha",
           fmt::format("Ogden term {}: |alpha_p| must be >= 1 (with |alpha_p| < 1 the term's "
                       "radial stress falls at large stretch, a material instability the "
                       "membrane theory cannot follow), got alpha_p = {:g}",
                       p + 1,
                       a)});
  }
  if (std::isfinite(twice) && !(std::abs(twice - 2.0) <= 1e-12 * 2.0))
    errors.push_back({"material.law.mu",
                      fmt::format("Ogden's mu_p / G must satisfy sum mu_p alpha_p / G = 2 (G = "
                                  "sum mu_p alpha_p / 2 is the shear modulus; ogden_material() "
                                  "builds the law from MPa values), got {:.17g}",
                                  twice)});
}

void append_material_errors(std::vector<ValidationError>& errors, const Material& material) {
  require_positive(
      errors, "material.shear_modulus_mpa", "shear modulus", material.shear_modulus_mpa, "MPa");
  if (const auto* gent = std::get_if<Gent>(&material.law)) {
    if (!std::isfinite(gent->j_lim) || gent->j_lim <= 0.0)
      errors.push_back({"material.law.j_lim",
                        fmt::format("J_lim must be a finite number > 0, got {}", gent->j_lim)});
  }
  if (const auto* mr = std::get_if<MooneyRivlin>(&material.law)) {
    if (!std::isfinite(mr->alpha) || mr->alpha < 0.0 || mr->alpha >= 1.0)
      errors.push_back(
          {"material.law.alpha",
           fmt::format("Mooney-Rivlin alpha = C2/(C1+C2) must be in [0, 1), got {}", mr->alpha)});
  }
  if (const auto* yeoh = std::get_if<Yeoh>(&material.law)) {
    // materials/yeoh.hpp: with a negative coefficient s1 may fall as the stretch grows.
    for (const auto& [attribute, name, value] : {std::tuple{"material.law.c2", "C20", yeoh->c2},
                                                 std::tuple{"material.law.c3", "C30", yeoh->c3}})
      if (!std::isfinite(value) || value < 0.0)
        errors.push_back(
            {attribute,
             fmt::format("Yeoh {} / G must be a finite number >= 0 (a negative coefficient can "
                         "make the stress fall as the membrane stretches), got {}",
                         name,
                         value)});
  }
  if (const auto* ogden = std::get_if<Ogden>(&material.law)) append_ogden_errors(errors, *ogden);
  if (const auto* ab = std::get_if<ArrudaBoyce>(&material.law)) {
    if (!std::isfinite(ab->n) || ab->n <= 1.0)
      errors.push_back({"material.law.n",
                        fmt::format("Arruda-Boyce N (Kuhn segments per chain, the chain locking "
                                    "stretch squared) must be a finite number > 1, got {}",
                                    ab->n)});
  }
  if (const auto* gg = std::get_if<GentGent>(&material.law)) {
    if (!std::isfinite(gg->j_lim) || gg->j_lim <= 0.0)
      errors.push_back({"material.law.j_lim",
                        fmt::format("J_lim must be a finite number > 0, got {}", gg->j_lim)});
    if (!std::isfinite(gg->beta) || gg->beta < 0.0 || gg->beta >= 1.0)
      errors.push_back(
          {"material.law.beta",
           fmt::format("Gent-Gent beta = 2 C2 / (3 G), the I2 term's share of G, must be in "
                       "[0, 1), got {}",
                       gg->beta)});
    else if (std::isfinite(gg->j_lim) && gg->j_lim > 0.0)
      if (const auto at = where_radial_stress_falls(*gg))
        errors.push_back(
            {"material.law.beta",
             fmt::format("Gent-Gent beta = {:g} is too large for J_lim = {:g}: the concave "
                         "ln(I2) term makes the radial stress fall as the membrane stretches "
                         "(at lambda1 = {:.3g}, lambda2 = {:.3g}), a material instability the "
                         "membrane theory cannot follow",
                         gg->beta,
                         gg->j_lim,
                         at->first,
                         at->second)});
  }
}

void append_critical_i1_errors(std::vector<ValidationError>& errors, double critical_i1,
                               const MaterialLaw& law) {
  const double i1_max = locking_first_invariant(law);
  if (!std::isfinite(critical_i1) || critical_i1 <= 3.0)
    errors.push_back({"critical_i1",
                      fmt::format("critical I1 must be a finite number > 3, got {}", critical_i1)});
  else if (critical_i1 >= i1_max) {
    const auto [name, formula] = locking_limit_words(law);
    errors.push_back(
        {"critical_i1",
         fmt::format("critical I1 must be below the {} locking limit {} = {:g}, got {:g}",
                     name,
                     formula,
                     i1_max,
                     critical_i1)});
  }
}

// The energy-release criterion: a tearing energy > 0 on a problem it applies to, not already met
// by the pre-stretched membrane as it is mounted (cut at Part III's edge, at radius a / L0).
void append_energy_release_errors(std::vector<ValidationError>& errors, const Problem& p,
                                  const std::string& what, double tearing_energy) {
  if (!std::isfinite(tearing_energy) || tearing_energy <= 0.0) {
    errors.push_back(
        {"criteria",
         fmt::format(
             "{}: tearing energy must be a finite number > 0 N/mm, got {}", what, tearing_energy)});
    return;
  }
  const auto conflicts = energy_release_conflicts(p);
  for (const std::string& c : conflicts) errors.push_back({"criteria", what + " " + c});
  const double l0 = p.preload.prestretch, big_a = p.geometry.clamp_radius_mm,
               h = p.geometry.thickness_mm, g = p.material.shear_modulus_mpa;
  if (!conflicts.empty() || !errors.empty() || !(std::isfinite(l0) && l0 > 1.0)) return;
  const double a = std::get<FlatPunch>(p.indenter).radius_mm;
  // Normalised by A / L0 (detail::cut_membrane): the flat disc stores W(L0, L0) / 2.
  const auto cut = detail::cut_membrane(p.material.law, a * l0 / big_a, a / big_a, l0);
  if (!cut) return;
  const double unit = 2.0 * std::numbers::pi * g * h * (big_a / l0) * (big_a / l0);
  const double released =
      unit * (0.5 * strain_energy_density(p.material.law, l0, l0) - cut->energy);
  const double cost = tearing_energy * 2.0 * std::numbers::pi * (a / l0) * h;
  if (released >= cost)
    errors.push_back(
        {"preload.prestretch",
         fmt::format("pre-stretch {:g}: cutting the flat membrane at the indenter's "
                     "edge releases {:.6g} mJ before it is loaded, at or above the "
                     "{:.6g} mJ the cut costs ({}): the membrane would fail as it is mounted",
                     l0,
                     released,
                     cost,
                     what)});
}

// The criteria of Problem::criteria: each critical value in its range and reachable below the
// law's locking limit, and not already met by the pre-stretched membrane as it is mounted.
void append_criteria_errors(std::vector<ValidationError>& errors, const Problem& p) {
  const double i1_lock = locking_first_invariant(p.material.law);
  const auto [law_name, formula] = locking_limit_words(p.material.law);
  for (const FailureCriterion& c : p.criteria) {
    const double v = critical_value(c);
    const std::string what = fmt::format("{} criterion", criterion_name(c));
    if (!has_local_measure(c)) {
      append_energy_release_errors(errors, p, what, v);
      continue;
    }
    if (std::holds_alternative<CriticalFirstInvariant>(c)) {
      if (!std::isfinite(v) || v <= 3.0) {
        errors.push_back(
            {"criteria",
             fmt::format("{}: critical I1 must be a finite number > 3, got {}", what, v)});
        continue;
      }
      if (v >= i1_lock) {
        errors.push_back({"criteria",
                          fmt::format("{}: critical I1 must be below the {} locking limit {} = "
                                      "{:g}, got {:g}",
                                      what,
                                      law_name,
                                      formula,
                                      i1_lock,
                                      v)});
        continue;
      }
    } else if (std::holds_alternative<MaxPrincipalStretch>(c)) {
      if (!std::isfinite(v) || v <= 1.0) {
        errors.push_back(
            {"criteria",
             fmt::format("{}: critical stretch must be a finite number > 1, got {}", what, v)});
        continue;
      }
      // The least I1 at which a principal stretch reaches v is the uniaxial v^2 + 2 / v.
      if (const double i1 = v * v + 2.0 / v; i1 >= i1_lock) {
        errors.push_back({"criteria",
                          fmt::format("{}: a principal stretch of {:g} needs I1 >= {:.6g}, beyond "
                                      "the {} locking limit {} = {:g}",
                                      what,
                                      v,
                                      i1,
                                      law_name,
                                      formula,
                                      i1_lock)});
        continue;
      }
    } else if (!std::isfinite(v) || v <= 0.0) {
      errors.push_back(
          {"criteria",
           fmt::format("{}: critical value must be a finite number > 0 MPa, got {}", what, v)});
      continue;
    }
    const double l0 = p.preload.prestretch;
    if (std::isfinite(l0) && l0 > 1.0 && first_invariant(l0, l0) < i1_lock) {
      const double at_mount = measure_at(c, p.material, l0, l0);
      if (at_mount >= v)
        errors.push_back({"preload.prestretch",
                          fmt::format("pre-stretch {:g} gives a {} of {:.6g} before it is loaded, "
                                      "at or above the {} criterion's {:g}: the membrane would "
                                      "fail as it is mounted",
                                      l0,
                                      measure_name(c),
                                      at_mount,
                                      criterion_name(c),
                                      v)});
    }
  }
}

void append_prestretch_errors(std::vector<ValidationError>& errors, const char* parameter,
                              double prestretch, double critical_i1) {
  const double l0 = prestretch;
  if (!std::isfinite(l0) || l0 < 1.0)
    errors.push_back(
        {parameter,
         fmt::format("pre-stretch must be a finite number >= 1 (below 1 the clamped membrane is "
                     "compressed: it wrinkles, outside membrane theory), got {}",
                     l0)});
  else if (const double i1 = first_invariant(l0, l0);
           std::isfinite(critical_i1) && i1 >= critical_i1)
    errors.push_back(
        {parameter,
         fmt::format("pre-stretch {:g} gives I1 = {:.6g} before it is loaded, at or above the "
                     "critical I1 {:g}: the membrane would fail as it is mounted",
                     l0,
                     i1,
                     critical_i1)});
}

void throw_if_invalid(const char* heading, const std::vector<ValidationError>& errors) {
  if (!errors.empty()) throw InvalidInput(errors, heading);
}

// The flat punch's corner fillet: 0 <= rho < a; a rounded corner is solved sliding, also under a
// gas pressure (docs/model.md §17, §19).
void append_fillet_errors(std::vector<ValidationError>& errors, const Problem& p) {
  const auto* punch = std::get_if<FlatPunch>(&p.indenter);
  if (!punch) return;
  const double rho = punch->fillet_radius_mm, a = punch->radius_mm;
  if (!std::isfinite(rho) || rho < 0.0) {
    errors.push_back(
        {"indenter.fillet_radius_mm",
         fmt::format("fillet radius must be a finite number >= 0 mm (0: the sharp corner), got {}",
                     rho)});
    return;
  }
  if (rho == 0.0) return;
  if (std::isfinite(a) && rho >= a)
    errors.push_back(
        {"indenter.fillet_radius_mm",
         fmt::format("fillet radius must be smaller than the indenter radius ({} mm; a fillet "
                     "of that radius is the sphere-tipped probe, --indenter sphere-tipped), "
                     "got {} mm",
                     a,
                     rho)});
  // (held under a gas pressure: solved, docs/model.md §17.3; over a sealed chamber the flat
  // punch's own check refuses it, whatever its corner)
}

// Preload::inflated_state: 1, k >= 1 or the last; another than the first needs a held pressure
// and no more states than the membrane has at it (counted by the inflation solver, only then).
void append_inflated_state_errors(std::vector<ValidationError>& errors, const Problem& p) {
  const int k = p.preload.inflated_state;
  if (k == 1) return;
  if (k < 1 && k != kLastInflatedState) {
    errors.push_back({"preload.inflated_state",
                      fmt::format("inflated state must be 'first', 'last' or a number >= 1 (the "
                                  "k-th state at the pressure in order of pole stretch), got {}",
                                  k)});
    return;
  }
  if (!(p.preload.pressure_mpa > 0.0) || p.preload.gas_volume_mm3) {
    errors.push_back({"preload.inflated_state",
                      "an inflated state other than the first needs a held gas pressure (> 0 "
                      "MPa, no sealed chamber)"});
    return;
  }
  if (!errors.empty()) return;  // the inflation needs a valid membrane
  SolverOptions quiet;
  quiet.record_fields = false;
  const InflationAtPressure at =
      inflate_at_pressure(inflation_problem(p), p.preload.pressure_mpa, {}, quiet);
  const int found = at.ok() ? int(at.states.size()) : 0;
  if (k != kLastInflatedState && k > found)
    errors.push_back(
        {"preload.inflated_state",
         fmt::format("the membrane has {} inflated state{} at {} MPa below its burst{}, so "
                     "state {} does not exist",
                     found,
                     found == 1 ? "" : "s",
                     p.preload.pressure_mpa,
                     at.ok() ? "" : " (" + at.message + ")",
                     k)});
}

}  // namespace detail

std::vector<ValidationError> validation_errors(const Problem& p) {
  std::vector<ValidationError> errors;
  const auto& g = p.geometry;
  using detail::require_positive;
  require_positive(errors, "geometry.clamp_radius_mm", "clamp radius", g.clamp_radius_mm, "mm");
  const double a = radius_mm(p.indenter);
  require_positive(errors, "indenter.radius_mm", "indenter radius", a, "mm");
  require_positive(errors, "geometry.thickness_mm", "thickness", g.thickness_mm, "mm");
  if (std::isfinite(a) && std::isfinite(g.clamp_radius_mm) && a > 0.0 && g.clamp_radius_mm > 0.0 &&
      a >= g.clamp_radius_mm)
    errors.push_back(
        {"indenter.radius_mm",
         fmt::format("indenter radius must be smaller than the clamp radius ({} mm), got {} mm",
                     g.clamp_radius_mm,
                     a)});
  detail::append_fillet_errors(errors, p);
  detail::append_material_errors(errors, p.material);
  if (!std::isfinite(p.friction) || p.friction < 0.0)
    errors.push_back(
        {"friction",
         fmt::format("friction coefficient must be a finite number >= 0, got {}", p.friction)});
  else if (p.friction > 10.0)
    errors.push_back(
        {"friction",
         fmt::format(
             "friction coefficient must be <= 10 (beyond, the sliding under the tip is below "
             "double precision; use --stick always for a fully held membrane), got {}",
             p.friction)});
  if (p.criteria.empty()) {
    detail::append_critical_i1_errors(errors, p.critical_i1, p.material.law);
    detail::append_prestretch_errors(
        errors, "preload.prestretch", p.preload.prestretch, p.critical_i1);
  } else {
    detail::append_criteria_errors(errors, p);
    detail::append_prestretch_errors(
        errors, "preload.prestretch", p.preload.prestretch, std::nan(""));
  }
  if (const double pressure = p.preload.pressure_mpa; !std::isfinite(pressure) || pressure < 0.0)
    errors.push_back(
        {"preload.pressure_mpa",
         fmt::format("pressure must be a finite number >= 0 MPa (the gas under the membrane "
                     "pushes it towards the indenter), got {}",
                     pressure)});
  if (const auto v0 = p.preload.gas_volume_mm3) {
    if (!std::isfinite(*v0) || *v0 <= 0.0)
      errors.push_back({"preload.gas_volume_mm3",
                        fmt::format("gas volume must be a finite number > 0 mm^3 (the sealed "
                                    "chamber's volume under the flat membrane), got {}",
                                    *v0)});
    if (const double p_atm = p.preload.atmospheric_pressure_mpa;
        !std::isfinite(p_atm) || p_atm <= 0.0)
      errors.push_back({"preload.atmospheric_pressure_mpa",
                        fmt::format("atmospheric pressure must be a finite number > 0 MPa (the "
                                    "sealed gas's absolute pressure is the gauge pressure plus "
                                    "it), got {}",
                                    p_atm)});
    // The held face under a held pressure (docs/model.md §17.3) is built along a loading at one
    // pressure; over a sealed chamber the pressure changes along it: not solved.
    if (std::holds_alternative<FlatPunch>(p.indenter) && p.stick.rule != StickRule::None)
      errors.push_back({"stick.rule",
                        fmt::format("over a sealed gas chamber the flat punch is solved sliding "
                                    "only so far: stick rule must be 'none', got '{}'",
                                    to_string(p.stick.rule))});
  }
  detail::append_inflated_state_errors(errors, p);
  const auto& s = p.stick;
  // The sphere-tipped probe's stick stage (docs/model.md §15.4, §17.3) holds material where it
  // touched the membrane, flat or inflated at a held pressure; over a sealed chamber the pressure
  // changes along the history: not solved.
  if (std::holds_alternative<SphereTipped>(p.indenter) && s.rule != StickRule::None &&
      p.preload.gas_volume_mm3)
    errors.push_back({"stick.rule",
                      fmt::format("over a sealed gas chamber the sphere-tipped probe is solved "
                                  "sliding only so far: stick rule must be 'none', got '{}'",
                                  to_string(s.rule))});
  detail::append_probe_shape_errors(errors, p);
  // On the flat punch Coulomb friction cannot hold the membrane at all (docs/model.md §9), unless
  // a gas pressure presses it on the face (§17.3).
  if (s.rule == StickRule::Coulomb && std::holds_alternative<FlatPunch>(p.indenter) &&
      std::get<FlatPunch>(p.indenter).fillet_radius_mm == 0.0 && !(p.preload.pressure_mpa > 0.0))
    errors.push_back({"stick.rule",
                      "stick rule 'coulomb' needs a curved probe (sphere-tipped) or a gas "
                      "pressure (--pressure): on the flat punch Coulomb friction cannot hold the "
                      "membrane under the tip, use 'none'"});
  if (s.rule == StickRule::Force || s.rule == StickRule::Depth ||
      s.rule == StickRule::EdgeTension) {
    if (!std::isfinite(s.threshold) || s.threshold <= 0.0)
      errors.push_back({"stick.threshold",
                        fmt::format("stick threshold for rule '{}' must be a finite number > 0 {}, "
                                    "got {}",
                                    to_string(s.rule),
                                    s.rule == StickRule::Force   ? "N"
                                    : s.rule == StickRule::Depth ? "mm"
                                                                 : "N/mm",
                                    s.threshold)});
  }
  return errors;
}

std::vector<ValidationError> validation_errors(const Problem& problem, Unknown unknown) {
  Problem rest = problem;
  if (unknown == Unknown::Friction) {
    rest.friction = 0.0;
  } else if (std::holds_alternative<Gent>(rest.material.law)) {
    const double i1_excess = problem.critical_i1 - 3.0;
    rest.material.law = Gent{std::isfinite(i1_excess) && i1_excess > 0.0 ? 2.0 * i1_excess : 1.0};
  }
  return validation_errors(rest);
}

void validate(const Problem& problem) {
  detail::throw_if_invalid("invalid problem:", validation_errors(problem));
}

double force_scale_n(const Problem& p) {
  return 2.0 * boost::math::constants::pi<double>() * p.material.shear_modulus_mpa *
         p.geometry.thickness_mm * p.geometry.clamp_radius_mm;
}

double reference_clamp_radius_mm(const Problem& p) {
  return p.geometry.clamp_radius_mm / p.preload.prestretch;
}

std::string to_string(StickRule rule) {
  switch (rule) {
    case StickRule::None:
      return "none";
    case StickRule::Force:
      return "force";
    case StickRule::Depth:
      return "depth";
    case StickRule::EdgeTension:
      return "edge-tension";
    case StickRule::Always:
      return "always";
    case StickRule::Coulomb:
      return "coulomb";
  }
  return "?";
}

std::string describe(const StickCriterion& stick) {
  switch (stick.rule) {
    case StickRule::None:
      return "none (Coulomb friction only: slides from the first touch)";
    case StickRule::Always:
      return "always (held at the edge, never slides)";
    case StickRule::Coulomb:
      return "coulomb (held where it touched while the friction holds every held point)";
    case StickRule::Force:
      return fmt::format(
          "force:{:g} (held until the force reaches {:g} N)", stick.threshold, stick.threshold);
    case StickRule::Depth:
      return fmt::format(
          "depth:{:g} (held until the depth reaches {:g} mm)", stick.threshold, stick.threshold);
    case StickRule::EdgeTension:
      return fmt::format(
          "edge-tension:{:g} (held until the line tension at the edge reaches {:g} N/mm)",
          stick.threshold,
          stick.threshold);
  }
  return "?";
}

std::string to_string(PartTwoEquation equation) {
  return equation == PartTwoEquation::RingBalance ? "ring-balance" : "paper-eq18";
}

}  // namespace puncture
