#pragma once
// The sharp flat-ended cylindrical punch of the paper: its contact model (contact_model.hpp).
// Three membrane parts: Part III under the flat tip (homogeneous, equibiaxial), Part II wrapped
// on the cylindrical side (with Coulomb friction), and the free Part I.  Configurations:
//   Stick               membrane held at the indenter's edge, Part III at the pre-stretch L0
//   SlipWithoutPartTwo  Part III stretched, capstan across the corner, Part I from the corner
//   SlipWithPartTwo     Part III, the corner wrapped by pi/2, Part II on the side, then Part I
// and their shooting parameters p:
//   Stick               t, the horizontal line tension at the edge (R = a / L0, lambda2 = L0)
//   SlipWithoutPartTwo  the Part III stretch Lambda
//   SlipWithPartTwo     lambda2 where Part I leaves the indenter's side (> a / A; it can be
//                       below 1 when material from beyond the indenter's radius climbs its side)
// Both slip parameters equal the same stretch where Part II appears, so p is continuous there.
// In depth control SlipWithPartTwo can also be given by (Part III stretch, p), the force then an
// output (contact_start): near a limit load the depth runs away from the force but not from the
// Part III stretch.
#include <fmt/format.h>

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "indentation/contact/contact_model.hpp"
#include "indentation/contact/flat_punch_face.hpp"
#include "indentation/contact/flat_punch_held_face.hpp"
#include "indentation/contact/flat_punch_side.hpp"
#include "indentation/free_part.hpp"
#include "indentation/membrane_fields.hpp"
#include "mechanics/inverse_stretch.hpp"
#include "numerics/even_samples.hpp"
#include "numerics/interior_maximum.hpp"
#include "numerics/root_in_bracket.hpp"
#include "numerics/shooting.hpp"

namespace puncture::detail {

inline constexpr double kHalfPi = boost::math::constants::half_pi<double>();

// the capstan ratio); pi/2 when kappa >= exp(mu pi/2).  The left side increases on [0, pi/2].
inline double corner_slope(double kappa, double mu) {
  if (kappa >= std::exp(mu * kHalfPi)) return kHalfPi;
  std::uintmax_t iterations = 100;
  return boost::math::tools::newton_raphson_iterate(
      [&](double phi) {
        const double e = std::exp(mu * phi);
        return std::make_pair(std::sin(phi) * e - kappa, (std::cos(phi) + mu * std::sin(phi)) * e);
      },
      0.5 * std::asin(std::min(kappa, 1.0)),
      0.0,
      kHalfPi,
      52,
      iterations);
}

struct FlatPunchSettings {
  double a;   // indenter radius / stress-free clamp radius A / L0
  double mu;  // Coulomb friction coefficient on the indenter
  PartTwoEquation equation;
};

template <class Law>
class FlatPunchContact {
 public:
  using law_type = Law;
  using Settings = FlatPunchSettings;

  FlatPunchContact(const FreePart<Law>& part_one, const FlatPunchSettings& settings)
      : part_one_(part_one),
        law_(part_one.law()),
        s_(settings),
        locking_i1_(part_one.locking_i1()),
        pressure_(part_one.pressure()),
        face_load_(0.5 * pressure_ * s_.a * s_.a),
        rough_face_(pressure_ > 0.0 && s_.mu > 0.0),
        held_face_(pressure_ > 0.0 ? std::make_shared<HeldFaceHistory<Law>>(
                                         part_one, s_.a, part_one.settings().dome_pole_stretch)
                                   : nullptr) {}

  // Under a gas pressure, the map of the material held on the face (built on first use; shared
  // by copies of the contact); null without pressure.
  const HeldFaceHistory<Law>* held_face() const { return held_face_.get(); }

  // Every configuration's parameter exceeds this floor: 1 for the stretches at the edge and of
  // Part III, a / A for the hoop stretch a / R at the top of Part II (R < A).
  double parameter_floor(Configuration configuration) const {
    if (configuration == Configuration::Stick) return 0.0;
    if (rough_face_) return 1.0;  // the pole stretch
    // Part III's stretch also exceeds a / (A / L0), which keeps its corner, at R = a / L,
    // inside the clamp (that bound exceeds 1 only for a pre-stretched membrane with a > A / L0).
    return configuration == Configuration::SlipWithPartTwo ? s_.a : std::max(1.0, s_.a);
  }

  // Held at the edge, the parameter is t >= 0, the horizontal component of the line tension
  // R s1 = sqrt(f^2 + t^2) where Part I leaves the edge (R = a / L0, lambda2 = L0: the material
  // the edge touched, at the pre-stretch), not the edge stretch: the end of the held branch is
  // the vertical exit t = 0, where the clamp residual is linear in t but goes as the square root
  // of the stretch's distance from the vertical exit's; shooting on the stretch, that distance
  // falls below an ulp (and the clamp residual stalls ~1e-8) while t still resolves it.
  // Under a gas pressure the held edge is the held face's (held_edge): on the face Part I leaves
  // it horizontally (R s1 = t), past it the corner's pull is f - P a^2 / 2; t is continuous.
  std::optional<FreeStart> held_start(double f, double t) const {
    if (!(t >= 0.0) || !std::isfinite(t)) return std::nullopt;
    const auto edge = held_edge(f);
    if (!edge) return std::nullopt;
    const auto [r0, l0] = *edge;
    const double v = pressure_ > 0.0 ? std::max(pull(f), 0.0) : f;  // the edge's vertical pull
    const auto l1 = invert_radial_stress(law_, std::hypot(v, t) / r0, l0);
    if (!l1 || !(first_invariant(*l1, l0) < locking_i1_)) return std::nullopt;
    return FreeStart{
        {t, *l1, l0, 0.0}, r0, std::atan2(v, t), std::numeric_limits<double>::infinity()};
  }

  std::optional<FreeStart> free_start(Configuration c, double f, double p) const {
    if (c == Configuration::Stick) return held_start(f, p);
    if (!(p > 0.0) || !std::isfinite(p)) return std::nullopt;
    if (rough_face_) return rough_start(c, f, p);
    switch (c) {
      case Configuration::SlipWithoutPartTwo: {
        // Part III stretch p: the corner material sits at R = a / p; the capstan law and the
        // vertical balance give the exit slope.
        const double s_eq = membrane_stress(law_, p, p).s1;
        if (!(s_eq > 0.0) || !std::isfinite(s_eq) || first_invariant(p, p) >= locking_i1_)
          return std::nullopt;
        // Under a gas pressure that alone carries f on a disc of the face, c^2 = 2 f / P < a^2,
        // the membrane leaves the face there, tangentially (docs/model.md §17).
        if (f < face_load_) return face_start(f, p, s_eq);
        const double r0 = s_.a / p;
        const double kappa = pull(f) / (r0 * s_eq);
        // Beyond exp(mu pi/2) the exit would have to be steeper than vertical: Part II exists.
        if (kappa > std::exp(s_.mu * kHalfPi) * (1.0 + 1e-9)) return std::nullopt;
        const double phi = corner_slope(kappa, s_.mu);
        const double ratio = std::exp(s_.mu * phi);  // capstan: the outer side pulls harder
        const auto l1 = invert_radial_stress(law_, s_eq * ratio, p, p);
        if (!l1) return std::nullopt;
        return FreeStart{{r0 * s_eq * ratio * std::cos(phi), *l1, p, 0.0}, r0, phi, ratio};
      }
      case Configuration::SlipWithPartTwo: {
        // Part I leaves the side vertically at R = a / p: R s1 = f (less the gas's share), t = 0.
        if (!(p > s_.a)) return std::nullopt;  // the top must lie inside the clamp
        if (pressure_ > 0.0 && !(pull(f) > 0.0)) return std::nullopt;
        const auto l1 = invert_radial_stress(law_, pull(f) * p / s_.a, p);
        if (!l1) return std::nullopt;
        return FreeStart{{0.0, *l1, p, 0.0}, s_.a / p, kHalfPi, std::exp(s_.mu * kHalfPi)};
      }
      case Configuration::Stick:  // held_start
      case Configuration::Unloaded:
      case Configuration::PartialSlip:  // curved probes only (partial_slip_path.hpp)
        break;
    }
    return std::nullopt;
  }

  // Parts III and II once Part I is integrated from `st`: the corner, Part III's stretch and, with
  // Part II, its march down the side to where the capstan condition with Part III holds.
  // Without `maxima` the side's largest I1 is not searched between the steps (the corner's is
  // kept): for the iterations of a search that assembles its end again.
  bool attach(Configuration c, const FreeStart& st, double p, bool record, ScaledSolution& sol,
              bool maxima = true) const {
    if (c == Configuration::Stick) {
      if (held_face_) return attach_held_face(st, record, sol);
      sol.r_corner = held_radius();
      sol.part_three_stretch = part_one_.prestretch();
      return true;
    }
    if (rough_face_) return attach_rough(c, st, p, record, sol, maxima);
    if (c == Configuration::SlipWithoutPartTwo) {
      sol.r_corner = st.r0;
      sol.part_three_stretch = p;
      return true;
    }
    // March down the side from the top of Part II until the capstan condition with Part III
    // holds (Eq. 22 with Eq. 20): s1(lambda1, a/R) = exp(mu pi/2) s_eq(a/R).
    const double capstan = st.ratio;
    // Where Part III would be locked (or the stresses are not finite) the corner lies higher up:
    // the gap counts as negative there.
    auto corner_gap = [&](double r, const PartTwoState& y) {
      const double l2 = s_.a / r;
      if (!(first_invariant(l2, l2) < locking_i1_)) return -1.0;
      const double gap =
          membrane_stress(law_, y[0], l2).s1 - capstan * membrane_stress(law_, l2, l2).s1;
      return std::isfinite(gap) ? gap : -1.0;
    };
    const PartTwoSystem<Law> side{law_, s_.a, s_.mu, s_.equation, locking_i1_, pressure_};
    PartTwoState y{st.state[1], 0.0};
    double r_prev = st.r0, r_hit = -1.0;
    PartTwoState y_prev = y;
    InteriorMaximum<PartTwoState> side_max;
    const double r_floor = s_.a / locking_radial_stretch(law_, 1.0);
    Knots<PartTwoState> knots;
    const bool ok =
        integrate_part(side,
                       y,
                       st.r0,
                       std::isfinite(r_floor) ? r_floor : 1e-6 * s_.a,
                       part_one_.settings().integration,
                       [&](double r, const PartTwoState& state) {
                         if (corner_gap(r, state) <= 0.0) {
                           r_hit = r;
                           return false;
                         }
                         r_prev = r;
                         y_prev = state;
                         if (record) knots.add(r, state);
                         if (maxima)
                           side_max.observe(r, state, first_invariant(state[0], s_.a / r));
                         return true;
                       });
    if (!ok || r_hit < 0.0) {
      sol.status = std::isfinite(locking_i1_) ? Status::BeyondLocking : Status::LimitLoad;
      sol.message = std::isfinite(locking_i1_)
                        ? "Part II reaches the locking stretch before meeting the capstan condition"
                        : "Part II never meets the capstan condition: the force is beyond the "
                          "membrane's limit load";
      return false;
    }
    // Where the corner is: at the top when the capstan condition holds there already (exactly at
    // the onset, to round-off: Part II of zero length; beyond that there is no Part II at this
    // force and top stretch), else inside the last step, located by re-integrating adaptively
    // from the last accepted state (near locking a single long step may leave the material's
    // domain).  A trial that cannot be integrated lies past the corner, towards locking: the gap
    // counts as negative there.
    double r_corner = st.r0;
    std::optional<PartTwoState> corner_state = y_prev;
    const auto gap_scale = [&](double r) {
      return 1e-8 * capstan * membrane_stress(law_, s_.a / r, s_.a / r).s1;
    };
    if (r_hit == st.r0) {
      if (!(corner_gap(st.r0, y_prev) >= -0.1 * gap_scale(st.r0))) {
        sol.message = "no Part II at this force and boundary stretch";
        return false;
      }
    } else {
      auto gap_at = [&](double r) {
        const auto y_r = step_or_advance(side, y_prev, r_prev, r, part_one_.settings().integration);
        return y_r ? corner_gap(r, *y_r) : -1.0;
      };
      // The step that met the side brackets the corner; near locking (a trial that cannot be
      // integrated) it may not: then there is no corner here, a status rather than Boost's throw.
      const double gap_hit = gap_at(r_hit), gap_prev = gap_at(r_prev);
      if (!(gap_hit * gap_prev <= 0.0)) {
        sol.status = Status::BeyondLocking;
        sol.message = "the corner of Part II could not be located (the material locks near it)";
        return false;
      }
      r_corner = root_in_bracket(gap_at, r_hit, r_prev, gap_hit, gap_prev);
      corner_state =
          step_or_advance(side, y_prev, r_prev, r_corner, part_one_.settings().integration);
      // The corner is located to ulps, where the gap (the difference of two stresses of about
      // the capstan factor times s_eq) is rounding: up to ~1e-8 of them at capstan factors of
      // 1e6 (mu' ~ 10, Mooney-Rivlin, seed 20261123 cases 2007, 3189).  A bracket closed on a
      // jump (past locking) leaves a gap of order 1: 1e-6 of them tells the two apart.
      if (!corner_state ||
          !(std::abs(corner_gap(r_corner, *corner_state)) <= 1e2 * gap_scale(r_corner))) {
        sol.status = Status::BeyondLocking;
        sol.message = "the corner of Part II lies beyond the material's locking limit";
        return false;
      }
    }
    const PartTwoState corner = *corner_state;
    // The last step, down to the corner, may hold the side's largest I1.
    if (maxima) side_max.observe(r_corner, corner, first_invariant(corner[0], s_.a / r_corner));
    if (record) {
      knots.add(r_corner, corner);
      sol.part_two.clear();
      for (const auto& [r, y] :
           even_samples(side, knots, field_intervals(), part_one_.settings().integration))
        sol.part_two.push_back({r, y[0], y[1]});
    }
    finish_part_two(side, side_max, r_corner, corner, sol);
    sol.depth += corner[1];
    return true;
  }

  // Depth control by the Part III stretch (contact_start) is offered with Part II.
  // (Not with friction under pressure: there Part III's stretch is not one number.)
  bool contact_controls(Configuration c) const {
    return c == Configuration::SlipWithPartTwo && !rough_face_;
  }

  // SlipWithPartTwo given by its Part III stretch l3 and the hoop stretch p at its top (depth
  // control): Part II marched up the side from the corner, where the capstan condition gives
  // lambda1 (Eq. 22), to the top at R = a / p, where Part I leaves vertically with R s1 = f.
  // Sets the force, Part II and the corner in `sol` (its depth: Part II's length; Part I's
  // height is added by the shooting); the start of Part I, or empty where l3 > p > a / A
  // does not hold or Part II cannot be integrated (locking).
  std::optional<FreeStart> contact_start(Configuration c, double l3, double p, bool record,
                                         ScaledSolution& sol) const {
    if (c != Configuration::SlipWithPartTwo) return std::nullopt;
    const PartTwoSystem<Law> side{law_, s_.a, s_.mu, s_.equation, locking_i1_, pressure_};
    InteriorMaximum<PartTwoState> side_max;
    Knots<PartTwoState> knots;
    const auto up = side_from_corner(
        l3, p, part_one_.settings().integration, [&](double r, const PartTwoState& x) {
          if (record) knots.add(r, x);
          side_max.observe(r, x, first_invariant(x[0], s_.a / r));
        });
    if (!up) return std::nullopt;
    sol.f = up->f;
    sol.max_i1 = 3.0;
    sol.part_two.clear();
    if (record) {
      // Samples as attach takes them: from the top down, y measured down from the top.
      const auto upward =
          even_samples(side, knots, field_intervals(), part_one_.settings().integration);
      for (auto it = upward.rbegin(); it != upward.rend(); ++it)
        sol.part_two.push_back({it->first, it->second[0], it->second[1] + up->length});
    }
    finish_part_two(side, side_max, s_.a / l3, {up->l1_corner, up->length}, sol);
    sol.depth = up->length;
    return up->start;
  }

  // Part II marched up the side from the corner, where the capstan condition with the Part III
  // stretch l3 gives lambda1 (Eq. 22), to its top at R = a / p, with observe(R, state) at every
  // step: the start of Part I there (leaving vertically), its force f = R s1 and Part II's length;
  // empty where l3 > p > a / A does not hold or Part II cannot be integrated (locking).
  struct SideFromCorner {
    FreeStart start;
    double f;
    double length;
    double l1_corner;
  };
  template <class Observer>
  std::optional<SideFromCorner> side_from_corner(double l3, double p,
                                                 const IntegrationSettings& integration,
                                                 Observer&& observe) const {
    if (!(p > s_.a) || !(l3 > p) || !std::isfinite(l3) || !(first_invariant(l3, l3) < locking_i1_))
      return std::nullopt;
    const double capstan = std::exp(s_.mu * kHalfPi);
    const auto l1_corner =
        invert_radial_stress(law_, capstan * membrane_stress(law_, l3, l3).s1, l3);
    if (!l1_corner) return std::nullopt;
    const double r_corner = s_.a / l3, r_top = s_.a / p;
    const PartTwoSystem<Law> side{law_, s_.a, s_.mu, s_.equation, locking_i1_, pressure_};
    // y runs from 0 at the corner to minus Part II's length at the top (it grows downward).
    PartTwoState y{*l1_corner, 0.0};
    if (!integrate_part(
            side, y, r_corner, r_top, integration, [&](double r, const PartTwoState& x) {
              observe(r, x);
              return true;
            }))
      return std::nullopt;
    const double f = r_top * membrane_stress(law_, y[0], p).s1 + face_load_;
    if (!(f > 0.0) || !std::isfinite(f)) return std::nullopt;
    return SideFromCorner{{{0.0, y[0], p, 0.0}, r_top, kHalfPi, capstan}, f, -y[1], *l1_corner};
  }

  // The stick stage holds the membrane at the edge; the slip stage finds whether Part II exists.
  template <class Residual>
  ShootingPlan plan(Stage stage, double f, Residual&& counted) const {
    return stage == Stage::Stick ? stick_plan(f, counted) : slip_plan(f, counted);
  }

  // The flat membrane at its pre-stretch: Part III under the tip, and the rest Part I, from the
  // indenter's edge to the clamp, sampled like a loaded Part I (at least field_points steps,
  // both ends included).
  ScaledSolution unloaded(bool record) const {
    ScaledSolution flat;
    flat.status = Status::Converged;
    const double l0 = part_one_.prestretch(), edge = held_radius();
    flat.r_corner = flat.r_top = edge;
    flat.part_three_stretch = l0;
    flat.configuration = Configuration::Unloaded;
    if (record) {
      const int n = std::max(1, part_one_.settings().field_points);
      for (int k = 0; k <= n; ++k) {
        const double r = k == n ? 1.0 : edge + (1.0 - edge) * k / n;
        flat.part_one.push_back({r, 0.0, l0, l0, 0.0});
      }
    }
    return flat;
  }

  Configuration configuration(Stage stage, bool past_change) const {
    if (stage == Stage::Stick) return Configuration::Stick;
    return past_change ? Configuration::SlipWithPartTwo : Configuration::SlipWithoutPartTwo;
  }

  // Part III stretch at which Part I leaves the corner vertically (wrap angle pi/2) at force f.
  std::optional<double> part_two_onset_stretch(double f) const {
    if (rough_face_) return rough_onset_stretch(f);
    // s_eq(L) / L = f exp(-mu pi/2) / a (f less the gas's share), increasing in L from 0 at 1.
    const double target = pull(f) * std::exp(-s_.mu * kHalfPi) / s_.a;
    if (pressure_ > 0.0 && !(target > 0.0)) return std::nullopt;
    auto g = [&](double l) -> std::optional<double> {
      const double s = membrane_stress(law_, l, l).s1;
      if (!std::isfinite(s) || first_invariant(l, l) >= locking_i1_) return std::nullopt;
      return s / l - target;
    };
    // g is undefined past the equibiaxial locking stretch; shoot_increasing treats that as beyond.
    const double cap = locking_radial_stretch(law_, 1.0);
    if (!std::isfinite(cap)) {
      // Without locking s_eq / L may stay bounded (neo-Hookean: below 1): if the target is out of
      // reach, no Part III stretch lets Part I leave the corner at or below vertical, and Part II
      // exists at every stretch.
      constexpr double kFar = 1e6;
      if (const auto far = g(kFar); far && *far < 0.0)
        return std::numeric_limits<double>::infinity();
    }
    const auto root = shoot_increasing(g, 1.0, -target, cap, 200);
    if (!root || !g(*root)) return std::nullopt;
    return root;
  }

  // Clamp residual of the Part I that leaves the corner vertically with no Part II: negative
  // while Part II is absent, >= 0 once it exists.  Empty past locking.
  std::optional<double> part_two_indicator(double f) const {
    // The membrane on the face carries no more than the gas's share: no corner, no Part II.
    if (pressure_ > 0.0 && !(pull(f) > 0.0)) return kTurnedBack;
    const auto onset = part_two_onset_stretch(f);
    if (!onset) return std::nullopt;
    if (std::isinf(*onset)) return 1.0;  // Part II at every stretch
    // With friction under pressure: the corner carries more than the pull even at an
    // unstretched pole (the capstan factor), so no pole stretch has Part II.
    if (rough_face_ && *onset <= 1.0) return kTurnedBack;
    // The vertical exit's corner, at R = a / L, would lie beyond the clamp (pre-stretched, a >
    // A / L0): every admissible Part III stretch exits flatter, so there is no Part II.  The
    // limit of the residual as that corner reaches the clamp, a - L0 < 0, stands in for it.
    if (*onset <= s_.a) return s_.a - part_one_.prestretch();
    // Part I leaving the corner vertically at the onset stretch: the SlipWithPartTwo start with a
    // Part II of zero length (exactly R s1 = f, free of the round-off in the capstan balance).
    return residual(Configuration::SlipWithPartTwo, f, *onset);
  }

  // The state where Part II appears in the slip stage (Part II of zero length); empty if it
  // never appears before the material locks.  Searched from a small force up, or from `f_from`
  // up: the force of a state on the loading path before the onset (on a later inflated state the
  // search from a small force finds the first state's onset, docs/model.md §17).
  template <class Shooting>
  std::optional<ScaledSolution> slip_change(const Shooting& shooting, double f_from = 0.0) const {
    // The indicator rises through zero at the onset force.  Below it, Part I leaving the corner
    // vertically turns back towards the axis (indicator kTurnedBack), so the sign change is found
    // by bracketing, starting from a force far below any onset.
    const auto indicator = [&](double f) { return part_two_indicator(f); };
    const int iterations = part_one_.settings().max_iterations;
    const auto f_on = f_from > 0.0 ? onset_force(indicator, iterations, 0.01 * f_from, f_from)
                                   : onset_force(indicator, iterations, 0.05);
    if (!f_on) return std::nullopt;
    const auto onset = part_two_onset_stretch(*f_on);
    if (!onset) return std::nullopt;
    // At the onset both slip configurations coincide; the one without Part II is assembled.
    auto sol = shooting.assemble(Configuration::SlipWithoutPartTwo, *f_on, *onset, false);
    if (!sol.integrated)
      sol = shooting.assemble(Configuration::SlipWithPartTwo, *f_on, *onset, false);
    if (!sol.integrated) return std::nullopt;
    return sol;
  }

  // Puncture in the slip stage with Part II and the crack at the corner, where I1 = i1c.  There
  // the corner's state is fixed by the capstan condition and I1 = i1c alone, whatever the force,
  // so marching Part II up from it to a top stretch p (the force an output) and shooting Part I
  // on to the clamp leaves a one-parameter shooting in p.  The state is returned with its fields
  // sampled.  Empty when the puncture is not of that kind (the caller then searches the loading
  // path).  `top_start`: a neighbouring problem's root p (a warm start), polished from directly;
  // if that fails the search runs cold.
  template <class Shooting>
  std::optional<ScaledSolution> direct_puncture(const Shooting& shooting, double i1c,
                                                std::optional<double> top_start = {}) const {
    // With friction under pressure the corner's state depends on the whole face: the loading
    // path is searched.
    if (rough_face_) return std::nullopt;
    const double capstan = std::exp(s_.mu * kHalfPi);
    // Corner state: s1(lambda1, L) = capstan s_eq(L) and I1(lambda1, L) = i1c, increasing in L.
    auto corner_l1 = [&](double l) -> std::optional<double> {
      const double s_eq = membrane_stress(law_, l, l).s1;
      if (!std::isfinite(s_eq) || first_invariant(l, l) >= locking_i1_) return std::nullopt;
      return invert_radial_stress(law_, capstan * s_eq, l, l);
    };
    auto excess = [&](double l) -> std::optional<double> {
      const auto l1 = corner_l1(l);
      if (!l1) return std::nullopt;
      return first_invariant(*l1, l) - i1c;
    };
    const auto l3 =
        shoot_increasing(excess, 1.0, 3.0 - i1c, locking_radial_stretch(law_, 1.0), 200);
    if (!l3) return std::nullopt;
    const auto l1_corner = corner_l1(*l3);
    if (!l1_corner) return std::nullopt;
    const double r_corner = s_.a / *l3;
    const double q_corner = r_corner * membrane_stress(law_, *l1_corner, *l3).s1;  // R s1 there
    // With R s1 unchanged up the side (no friction, ring balance) the force is R s1 at the corner
    // and the position of the top is left to the ordinary shooting at that force.
    if (s_.mu == 0.0 && s_.equation == PartTwoEquation::RingBalance) {
      auto sol = shooting.solve(Stage::Slip, q_corner + face_load_);
      if (!sol.ok() || std::abs(max_first_invariant_of(sol) - i1c) > 1e-7 * i1c)
        return std::nullopt;
      return sol;
    }
    // With the corner fixed, the state is given by the hoop stretch p at the top of Part II
    // (contact_start: Part II marched up to R = a / p, where f = R s1).  The clamp residual rises
    // from a - 1 < 0 as the top nears the clamp (p -> a) to positive values as Part II shrinks to
    // nothing (p -> l3): shoot on p, on the coarse integration first, then polished on the fine.
    const auto none = [](double, const PartTwoState&) {};
    const IntegrationSettings& fine = part_one_.settings().integration;
    auto g = [&](double p) -> std::optional<double> {
      const auto up = side_from_corner(*l3, p, fine, none);
      return up ? part_one_.residual(up->f, up->start) : std::nullopt;
    };
    auto g_coarse = [&](double p) -> std::optional<double> {
      const auto up = side_from_corner(*l3, p, shooting.coarse_integration(), none);
      return up ? shooting.coarse_free_residual(up->f, up->start) : std::nullopt;
    };
    // The state at a root p, when the march down finds the same corner and the crack sits there.
    auto state_at = [&](double p) -> std::optional<ScaledSolution> {
      const auto up = side_from_corner(*l3, p, fine, none);
      if (!up) return std::nullopt;
      auto sol = shooting.assemble(Configuration::SlipWithPartTwo, up->f, p, true);
      if (!sol.ok() || std::abs(sol.part_three_stretch - *l3) > 1e-7 * *l3 ||
          std::abs(max_first_invariant_of(sol) - i1c) > 1e-7 * i1c)
        return std::nullopt;
      return sol;
    };
    const double hi = *l3 * (1.0 - 1e-9);
    // A clamp residual within 1e-2 of the shooting's tolerance is the root (as in the shooting).
    const double good_enough = 1e-2 * part_one_.settings().shooting_tol;
    // Warm: a neighbour's root is close enough for the secant polish alone, which saves the
    // coarse bracket and root (31 % of this solve's instructions, docs/sweeps.md).
    if (top_start && *top_start > s_.a && *top_start < hi)
      if (const auto top = polish_coarse_root(
              g, g_coarse, *top_start, *top_start - s_.a, s_.a, hi, good_enough, 1e-2, 4))
        if (auto sol = state_at(*top)) return sol;
    // The top at the clamp may lie past locking (a long Part II): tops from l3 downward,
    // a + (l3 - a) / 2^k, until the residual is negative (as side_bracket_start does when its
    // floor fails).
    double lo = hi;
    std::optional<double> g_lo;
    for (int k = 1; k <= 50 && !(g_lo && *g_lo < 0.0); ++k) {
      lo = s_.a + (hi - s_.a) / std::ldexp(1.0, k);
      g_lo = g_coarse(lo);
    }
    if (!g_lo || *g_lo >= 0.0) return std::nullopt;
    const int iterations = part_one_.settings().max_iterations;
    std::optional<double> top;
    if (const auto p_coarse =
            shoot_increasing(g_coarse, lo, *g_lo, hi, iterations, 0.0, {1e-8, {}}))
      top = polish_coarse_root(
          g, g_coarse, *p_coarse, *p_coarse - s_.a, lo, hi, good_enough, 1e-2, 4);
    if (!top) top = shoot_increasing(g, lo, *g_lo, hi, iterations, 0.0, {good_enough, {}});
    if (!top) return std::nullopt;
    return state_at(*top);
  }

  const Law& law() const { return law_; }

  // The largest I1 is Part III's when it exceeds Parts I and II (a tie, without friction, is
  // reported at the corner's Part I/II side); Part II spans the side from the corner to its top.
  LargestFirstInvariant largest_first_invariant(const ScaledSolution& sol) const {
    // A non-uniform Part III (friction under pressure) keeps its largest I1 in sol.max_i1.
    const bool in_part_three = sol.max_i1 < max_first_invariant_of(sol) ||
                               (nonuniform_face(sol) && sol.max_i1_r < sol.r_corner);
    const MembranePart part =
        in_part_three ? MembranePart::Tip
        : sol.configuration == Configuration::SlipWithPartTwo && sol.max_i1_r < sol.r_top
            ? MembranePart::Side
            : MembranePart::Free;
    if (nonuniform_face(sol)) return {part, sol.max_i1_r, sol.max_i1_radius};
    return {part,
            in_part_three ? sol.r_corner : sol.max_i1_r,
            in_part_three ? sol.r_corner * sol.part_three_stretch : sol.max_i1_radius};
  }

  // Part I starts at the top of Part II.
  double free_part_inner_height(const ScaledSolution& sol) const { return sol.part_two_length; }

  // Part III (homogeneous under the flat tip, unstretched when held), then Part II from the
  // corner up the side (its samples were taken downward).
  void append_contact_fields(const ScaledSolution& sol, const FieldScales& u,
                             MembraneFields& m) const {
    const double big_a = u.clamp_radius_mm, g = u.shear_modulus_mpa;
    const double depth = sol.depth * big_a;
    const double l3 = sol.part_three_stretch;
    // The gas's contact pressure on the face (and added to Eq. 16 on the side), in MPa.
    const double gas_mpa = pressure_ * g * u.thickness_mm / big_a;
    // Non-uniform (friction under pressure): its samples from the pole to the edge.
    // Held (stick under pressure): the traction its map needs, towards the axis.
    const bool held = held_face_ && sol.configuration == Configuration::Stick;
    const double traction_mpa = g * u.thickness_mm / big_a;
    for (const auto& [r_ref, l1, l2] : sol.part_three)
      append_point(m,
                   MembranePart::Tip,
                   r_ref * big_a,
                   l2 * r_ref * big_a,
                   depth,
                   0.0,
                   l1,
                   l2,
                   membrane_stress(law_, l1, l2),
                   g,
                   gas_mpa,
                   held ? held_face_->tangential_near(l2 * r_ref) * traction_mpa : s_.mu * gas_mpa);
    constexpr int kPartThreePoints = 5;
    for (int i = 0; i < (sol.part_three.empty() ? kPartThreePoints : 0); ++i) {
      const double r_ref = sol.r_corner * i / (kPartThreePoints - 1);
      append_point(m,
                   MembranePart::Tip,
                   r_ref * big_a,
                   l3 * r_ref * big_a,
                   depth,
                   0.0,
                   l3,
                   l3,
                   membrane_stress(law_, l3, l3),
                   g,
                   gas_mpa,
                   s_.mu * gas_mpa);
    }
    const double radius_mm = s_.a * big_a;
    for (auto it = sol.part_two.rbegin(); it != sol.part_two.rend(); ++it) {
      const double r_ref = (*it)[0], l1 = (*it)[1], l2 = s_.a / r_ref;
      const auto st = membrane_stress(law_, l1, l2);
      const double pressure =
          st.s2 * g * u.thickness_mm / (l1 * radius_mm) + gas_mpa;  // Eq. (16) + gas
      const double z = depth - (sol.part_two_length - (*it)[2]) * big_a;
      append_point(m,
                   MembranePart::Side,
                   r_ref * big_a,
                   radius_mm,
                   z,
                   kHalfPi,
                   l1,
                   l2,
                   st,
                   g,
                   pressure,
                   s_.mu * pressure);
    }
  }

  std::string crack_location(const ScaledSolution& sol) const {
    if (held_face_ && sol.configuration == Configuration::Stick &&
        sol.max_i1_r < sol.r_corner * (1.0 - 1e-12))
      return "Part III, held on the indenter's face (where it touched the inflated dome)";
    if (rough_face_ && sol.max_i1_r < sol.r_corner * (1.0 - 1e-12))
      return "Part III, on the indenter's face (not uniform: friction under pressure)";
    const double l3 = sol.part_three_stretch;
    const double i1_tip = 2.0 * l3 * l3 + 1.0 / (l3 * l3 * l3 * l3);
    if (i1_tip > sol.max_i1 * (1.0 + 1e-9)) return "Part III, under the indenter's tip";
    const double tol = 1e-9;
    const bool on_face = sol.configuration == Configuration::SlipWithoutPartTwo &&
                         sol.r_corner * l3 < s_.a * (1.0 - 1e-12);
    if (on_face && std::abs(sol.max_i1_r - sol.r_corner) <= tol)
      return "Part I where it leaves the indenter's face (the edge of the contact disc)";
    if (std::abs(sol.max_i1_r - sol.r_corner) <= tol) {
      std::string where = sol.configuration == Configuration::SlipWithPartTwo
                              ? "Part II at the indenter's corner"
                              : "Part I at the indenter's corner";
      if (i1_tip >= sol.max_i1 * (1.0 - 1e-9))
        where += " (without friction Part III, under the tip, is as stretched)";
      return where;
    }
    if (sol.configuration == Configuration::SlipWithPartTwo && sol.max_i1_r < sol.r_top)
      return "Part II, on the indenter's side";
    return "Part I, off the indenter";
  }

 private:
  // Reference radius of the material at the indenter's edge before it slides: a / L0.
  double held_radius() const { return s_.a / part_one_.prestretch(); }

  // Where a held membrane leaves the face at force f: {R, lambda2} of the edge.  Without pressure
  // the material under the face, a / L0 at L0; under a gas pressure the held face's map at the
  // contact disc's edge c = sqrt(2 f / P), past the face (f >= P a^2 / 2) the map's end at the
  // corner.  Empty beyond the map (the material locked before the disc reached the corner).
  std::optional<std::pair<double, double>> held_edge(double f) const {
    if (!held_face_) return std::pair{held_radius(), part_one_.prestretch()};
    const auto& p = held_face_->points();
    if (f < face_load_) {
      const double c = std::sqrt(2.0 * f / pressure_);
      const auto r = held_face_->radius_at(c);
      if (!r || !(*r > 0.0)) return std::nullopt;
      return std::pair{*r, c / *r};
    }
    if (!held_face_->complete()) return std::nullopt;
    return std::pair{p.back().r, s_.a / p.back().r};
  }

  // A Part III that is not one stretch: the rough face's (friction under pressure) and the held
  // face's (stick under pressure); its largest I1 is in sol.max_i1.
  bool nonuniform_face(const ScaledSolution& sol) const {
    return rough_face_ || (held_face_ && sol.configuration == Configuration::Stick);
  }

  // The held face under pressure once Part I is integrated from its edge `st`: its samples (the
  // map's grid points inside the edge, then the edge), its largest I1 and the Coulomb ratio its
  // points need.  The reported Part III stretch is the pole's (held at the dome's).
  bool attach_held_face(const FreeStart& st, bool record, ScaledSolution& sol) const {
    const double r_edge = st.r0, l2_edge = st.state[2];
    if (record) sol.part_three.clear();
    auto track = [&](double l1, double l2, double r_ref) {
      const double i1 = first_invariant(l1, l2);
      if (i1 > sol.max_i1) {
        sol.max_i1 = i1;
        sol.max_i1_r = r_ref;
        sol.max_i1_radius = l2 * r_ref;
      }
      if (sol.wrinkle_r < 0.0 && r_ref > 0.0 && hoop_compressive(l1, l2)) {
        sol.wrinkle_r = r_ref;
        sol.wrinkle_radius = l2 * r_ref;
      }
      if (record) sol.part_three.push_back({r_ref, l1, l2});
    };
    for (const HeldFacePoint& q : held_face_->points()) {
      if (!(q.r < r_edge * (1.0 - 1e-12))) break;
      track(q.l1, q.r > 0.0 ? q.c / q.r : q.l1, q.r);
    }
    // The edge's material: held with the stretch the map gives it (on the face, as it joins,
    // Part I's; at the corner the face's, Part I's may differ across the held corner).
    const double c_edge = l2_edge * r_edge;
    const double l1_edge = sol.f < face_load_ ? st.state[1] : held_face_->points().back().l1;
    track(l1_edge, l2_edge, r_edge);
    sol.r_corner = r_edge;
    sol.part_three_stretch = held_face_->pole_stretch();
    sol.held_traction_ratio = held_face_->held_ratio(c_edge);
    // Past the face the held corner, wrapped by the exit slope phi, holds the jump of the line
    // tension between the face's edge and Part I (the same hoop stretch on both sides): the
    // capstan law needs mu >= |ln(s1_I / s1_face)| / phi (docs/model.md §17.3).
    if (sol.f >= face_load_ && st.slope > 0.0) {
      const double s1_face = membrane_stress(law_, l1_edge, l2_edge).s1;
      const double s1_free = membrane_stress(law_, st.state[1], l2_edge).s1;
      sol.held_traction_ratio =
          std::max(sol.held_traction_ratio, std::abs(std::log(s1_free / s1_face)) / st.slope);
    }
    return true;
  }

  // The force the membrane itself carries past the face: f less the gas pressure's resultant on
  // the face, P a^2 / 2 (f itself without pressure).
  double pull(double f) const { return f - face_load_; }

  // On the face (f < P a^2 / 2): Part III of stretch p on the disc of current radius c =
  // sqrt(2 f / P), where the gas alone carries f; Part I leaves it tangentially (t = R s1 = R
  // s_eq, vertical load zero there).  Empty when that disc's material lies beyond the clamp.
  std::optional<FreeStart> face_start(double f, double p, double s_eq) const {
    const double r0 = std::sqrt(2.0 * f / pressure_) / p;
    if (!(r0 < 1.0) || !(r0 > 0.0)) return std::nullopt;
    return FreeStart{{r0 * s_eq, p, p, 0.0}, r0, 0.0, 1.0};
  }

  // ---- Friction under a gas pressure (rough_face_): Part III not uniform (flat_punch_face.hpp),
  // both sliding configurations shot on its pole stretch p.  From the pole outward everything
  // is an initial-value problem: Part III to its edge (the contact disc's c = sqrt(2 f / P) on
  // the face, else the corner at r = a), the capstan law across the corner, and with Part II
  // the side marched up from the corner to where R s1 = f - P a^2 / 2 (Part I leaves there
  // vertically).

  // Part III's edge: reference radius, stretches, s1, and its largest I1 (reference and current
  // radius), from the pole stretch to the current radius `edge`.
  struct FaceEdge {
    double r_ref = 0.0, l1 = 0.0, l2 = 0.0, s1 = 0.0;
    double max_i1 = 0.0, max_i1_r = 0.0, max_i1_radius = 0.0;
  };
  // With `samples`: (R, lambda1, lambda2) from the pole (included) to the edge.  Empty when the
  // material locks on the way or the edge's material lies beyond the clamp.
  std::optional<FaceEdge> face_to(double pole, double edge,
                                  std::vector<std::array<double, 3>>* samples = nullptr) const {
    const PartThreeSystem<Law> face{law_, s_.mu * pressure_, locking_i1_};
    const IntegrationSettings& fine = part_one_.settings().integration;
    const double r_start = 1e-3 * edge;  // the series' error, O((mu P r)^2), is ~1e-12 there
    auto x = face.pole_start(pole, r_start);
    if (!x || !(edge > 0.0)) return std::nullopt;
    FaceEdge out;
    out.max_i1 = first_invariant(pole, pole);
    Knots<PartThreeState> knots;
    const bool ok = integrate_part(face, *x, r_start, edge, fine, [&](double r, const auto& y) {
      // Along the face lambda1 > lambda2 > 1 grow outward: I1 is largest at the steps' ends
      // (the edge in practice), so the step values suffice.
      if (const double i1 = first_invariant(y[1], r / y[0]); i1 > out.max_i1) {
        out.max_i1 = i1;
        out.max_i1_r = y[0];
        out.max_i1_radius = r;
      }
      if (samples) knots.add(r, y);
      return y[0] < 1.0;  // the edge's material must lie inside the clamp
    });
    if (!ok || !((*x)[0] < 1.0) || !all_finite(*x)) return std::nullopt;
    out.r_ref = (*x)[0];
    out.l1 = (*x)[1];
    out.l2 = edge / out.r_ref;
    out.s1 = membrane_stress(law_, out.l1, out.l2).s1;
    if (!(out.s1 > 0.0) || !std::isfinite(out.s1)) return std::nullopt;
    if (samples) {
      samples->assign(1, {0.0, pole, pole});
      for (const auto& [r, y] : even_samples(face, knots, field_intervals(), fine))
        samples->push_back({y[0], y[1], r / y[0]});
    }
    return out;
  }

  // Part II marched up from the corner (Part III's edge `e`, the capstan ratio exp(mu pi/2)) to
  // where R s1 = f - P a^2 / 2, with observe(R, state) at each step: Part I's start there and
  // Part II's length.  Empty when the corner alone already carries more (no Part II; 1e-9
  // relative is the onset itself, Part II of zero length).
  struct RoughSide {
    FreeStart start;
    double length;
  };
  template <class Observer>
  std::optional<RoughSide> rough_side(const FaceEdge& e, double f, Observer&& observe) const {
    const double capstan = std::exp(s_.mu * kHalfPi), q = pull(f);
    const auto l1_corner = invert_radial_stress(law_, capstan * e.s1, e.l2, e.l1);
    if (!l1_corner || !(q > 0.0)) return std::nullopt;
    const double q_corner = e.r_ref * capstan * e.s1;
    if (q_corner > q * (1.0 + 1e-9)) return std::nullopt;
    const PartTwoSystem<Law> side{law_, s_.a, s_.mu, s_.equation, locking_i1_, pressure_};
    const IntegrationSettings& fine = part_one_.settings().integration;
    // R s1 - q grows up the side (ring balance: d(R s1)/dR = mu (s2 + P a lambda1) > 0).
    auto excess = [&](double r, const PartTwoState& y) {
      const double v = r * membrane_stress(law_, y[0], s_.a / r).s1 - q;
      return std::isfinite(v) ? v : 1.0;
    };
    PartTwoState y{*l1_corner, 0.0}, y_prev = y;
    double r_top = e.r_ref;
    observe(r_top, y);
    double r_prev = e.r_ref, r_hit = -1.0;
    if (q_corner < q &&
        !integrate_part(side, y, e.r_ref, 1.0, fine, [&](double r, const PartTwoState& state) {
          if (excess(r, state) >= 0.0) {
            r_hit = r;
            return false;
          }
          r_prev = r;
          y_prev = state;
          return true;
        }))
      return std::nullopt;
    // The side reaches the clamp first: the top would lie beyond it.  Part I of zero length at the
    // clamp stands in, with the residual a - L0 < 0 that the top's approach to the clamp tends to
    // (the negative end of the shooting's bracket, as without friction).
    if (q_corner < q && r_hit < 0.0)
      return RoughSide{{{0.0, y[0], s_.a, 0.0}, 1.0, kHalfPi, capstan}, -y[1]};
    // Met beyond the corner: located inside the last step.  (Met at the corner itself, q_corner
    // within rounding of q, Part II has zero length.)
    if (r_hit > r_prev) {
      auto gap_at = [&](double r) {
        const auto y_r = step_or_advance(side, y_prev, r_prev, r, fine);
        return y_r ? excess(r, *y_r) : 1.0;
      };
      const double g_prev = gap_at(r_prev), g_hit = gap_at(r_hit);
      if (!(g_prev * g_hit <= 0.0)) return std::nullopt;
      r_top = root_in_bracket(gap_at, r_prev, r_hit, g_prev, g_hit);
      const auto y_top = step_or_advance(side, y_prev, r_prev, r_top, fine);
      if (!y_top) return std::nullopt;
      y = *y_top;
      observe(r_top, y);
    }
    // lambda1 at the top from R s1 = q exactly (as the start without friction has it).
    const double l2 = s_.a / r_top;
    const auto l1 = invert_radial_stress(law_, q / r_top, l2, y[0]);
    if (!l1) return std::nullopt;
    return RoughSide{{{0.0, *l1, l2, 0.0}, r_top, kHalfPi, capstan}, -y[1]};
  }

  std::optional<FreeStart> rough_start(Configuration c, double f, double pole) const {
    if (c == Configuration::SlipWithoutPartTwo && f < face_load_) {
      // On the face: Part I leaves the contact disc's edge tangentially, t = R s1.
      const auto e = face_to(pole, std::sqrt(2.0 * f / pressure_));
      if (!e) return std::nullopt;
      return FreeStart{{e->r_ref * e->s1, e->l1, e->l2, 0.0}, e->r_ref, 0.0, 1.0};
    }
    const auto e = face_to(pole, s_.a);
    if (!e) return std::nullopt;
    if (c == Configuration::SlipWithPartTwo) {
      const auto side = rough_side(*e, f, [](double, const PartTwoState&) {});
      if (!side) return std::nullopt;
      return side->start;
    }
    // Past the face without Part II: the corner slope from the capstan law, as without friction
    // but with Part III's edge stress.
    const double kappa = pull(f) / (e->r_ref * e->s1);
    if (!(kappa >= 0.0) || kappa > std::exp(s_.mu * kHalfPi) * (1.0 + 1e-9)) return std::nullopt;
    const double phi = corner_slope(kappa, s_.mu);
    const double ratio = std::exp(s_.mu * phi);
    const auto l1 = invert_radial_stress(law_, e->s1 * ratio, e->l2, e->l1);
    if (!l1) return std::nullopt;
    return FreeStart{
        {e->r_ref * e->s1 * ratio * std::cos(phi), *l1, e->l2, 0.0}, e->r_ref, phi, ratio};
  }

  // Parts III and II after Part I: the face again (sampled with `record`), its largest I1, and
  // Part II up to where Part I started.
  bool attach_rough(Configuration c, const FreeStart& /*start*/, double pole, bool record,
                    ScaledSolution& sol, bool maxima) const {
    const bool on_face = c == Configuration::SlipWithoutPartTwo && sol.f < face_load_;
    const auto e = face_to(pole,
                           on_face ? std::sqrt(2.0 * sol.f / pressure_) : s_.a,
                           record ? &sol.part_three : nullptr);
    if (!e) {
      sol.message = "Part III cannot be integrated to its edge";
      return false;
    }
    sol.r_corner = e->r_ref;
    sol.part_three_stretch = e->l2;  // its hoop stretch at the edge (at the pole: the fields)
    auto track = [&](double i1, double r_ref, double radius) {
      if (i1 > sol.max_i1) {
        sol.max_i1 = i1;
        sol.max_i1_r = r_ref;
        sol.max_i1_radius = radius;
      }
    };
    track(e->max_i1, e->max_i1_r, e->max_i1_radius);
    if (c == Configuration::SlipWithoutPartTwo) return true;
    InteriorMaximum<PartTwoState> side_max;
    Knots<PartTwoState> knots;
    const auto side = rough_side(*e, sol.f, [&](double r, const PartTwoState& y) {
      if (record) knots.add(r, y);
      if (maxima) side_max.observe(r, y, first_invariant(y[0], s_.a / r));
    });
    if (!side) {
      sol.message = "Part II cannot be marched up to where Part I starts";
      return false;
    }
    const PartTwoSystem<Law> side_system{law_, s_.a, s_.mu, s_.equation, locking_i1_, pressure_};
    if (maxima && side_max.observed()) {
      const auto peak =
          refined_maximum(side_max, side_system, [&](double r, const PartTwoState& y) {
            return first_invariant(y[0], s_.a / r);
          });
      track(peak.value, peak.r, s_.a);
    }
    if (record) {
      // Stored from the top down, y measured down from the top, as without friction.
      sol.part_two.clear();
      const auto up =
          even_samples(side_system, knots, field_intervals(), part_one_.settings().integration);
      for (auto it = up.rbegin(); it != up.rend(); ++it)
        sol.part_two.push_back({it->first, it->second[0], side->length + it->second[1]});
    }
    sol.part_two_length = side->length;
    sol.edge_s1 = std::exp(s_.mu * kHalfPi) * e->s1;
    sol.tension_ratio = std::exp(s_.mu * kHalfPi);
    sol.depth += side->length;
    return true;
  }

  // The pole stretch at which Part I leaves the corner vertically at force f: the corner's
  // R s1 after the capstan, exp(mu pi/2) R_b s1(edge), equals f - P a^2 / 2 (increasing in the
  // pole stretch).  Infinite where no stretch reaches it without locking.
  std::optional<double> rough_onset_stretch(double f) const {
    const double q = pull(f);
    if (!(q > 0.0)) return std::nullopt;
    const double capstan = std::exp(s_.mu * kHalfPi);
    auto g = [&](double pole) -> std::optional<double> {
      const auto e = face_to(pole, s_.a);
      if (!e) return std::nullopt;
      return capstan * e->r_ref * e->s1 - q;
    };
    const auto g_one = g(1.0);
    if (!g_one) return std::nullopt;
    if (*g_one >= 0.0) return 1.0;
    const double cap = locking_radial_stretch(law_, 1.0);
    if (!std::isfinite(cap))
      if (const auto far = g(1e3); far && *far < 0.0)
        return std::numeric_limits<double>::infinity();
    const auto root = shoot_increasing(g, 1.0, *g_one, cap, 200);
    if (!root || !g(*root)) return std::nullopt;
    return root;
  }

  // On the face (and, under pressure, past the corner without Part II): the Part III stretch
  // from the first of 1 + 2^-k (k = 1, 2, ...) with a negative clamp residual
  // (contact_model.hpp: bracket_from_below).
  template <class Residual>
  ShootingPlan face_plan(double /*f*/, Residual& counted) const {
    return bracket_from_below(counted,
                              Configuration::SlipWithoutPartTwo,
                              "flat-punch shooting on the face under pressure");
  }

  // Part II is sampled as Part I is (FreePart).
  int field_intervals() const { return std::max(1, part_one_.settings().field_points); }

  std::optional<double> residual(Configuration c, double f, double p) const {
    return part_one_.residual(f, free_start(c, f, p));
  }

  // Held at the edge: shoot on t (held_start), from the vertical exit t = 0 upward.
  template <class Residual>
  ShootingPlan stick_plan(double f, Residual& counted) const {
    if (held_face_ && f < face_load_) return held_face_plan(f, counted);
    ShootingPlan plan;
    plan.configuration = Configuration::Stick;
    if (held_face_ && !held_face_->complete()) {
      plan.status = Status::BeyondLocking;
      plan.message =
          "the membrane held on the face locks before the contact reaches the indenter's edge";
      return plan;
    }
    if (!held_start(f, 0.0)) {
      plan.status = Status::BeyondLocking;
      plan.message = "the force exceeds what the membrane at the indenter's edge can carry";
      return plan;
    }
    const double g0 = counted(Configuration::Stick, 0.0).value_or(kBeyondDomain);
    if (g0 >= 0.0) {
      plan.status = Status::StickWrapsSide;
      plan.message =
          "at this force a membrane held at the indenter's edge would have to wrap its side";
      return plan;
    }
    plan.lo = 0.0;
    plan.g_lo = g0;
    // Every law's s1 grows without bound (towards locking, or as a power of the stretch), so t
    // has no cap; steps doubling from f (a 45 degree exit) bracket it.
    plan.initial_step = f;
    plan.no_root_message = "stick shooting found no edge tension meeting the clamp condition";
    return plan;
  }

  // Held on the face under pressure (f < P a^2 / 2): t = R s1 of the edge
  // (flat_punch_held_face.hpp).
  template <class Residual>
  ShootingPlan held_face_plan(double f, Residual& counted) const {
    return held_face_tension_plan(*held_face_, f, pressure_, counted);
  }

  // Sliding: whether Part II exists decides the configuration and its parameter's bracket.
  template <class Residual>
  ShootingPlan slip_plan(double f, Residual& counted) const {
    if (f <= face_load_ && pressure_ > 0.0) return face_plan(f, counted);
    ShootingPlan plan;
    const auto onset = part_two_onset_stretch(f);
    if (!onset) {
      plan.status = Status::BeyondLocking;
      plan.message = "the force needs a stretch under the tip beyond the material's locking limit";
      return plan;
    }
    if (std::isinf(*onset) && s_.mu == 0.0 && s_.equation == PartTwoEquation::RingBalance) {
      // Without friction R s1 = f all down the side, so the corner, where s1 = s_eq(L) at
      // L = a / R, needs s_eq(L) / L = f / a: out of reach at every L.  (Marching down the side
      // to find that out takes 100 times a solve.)
      plan.status = Status::LimitLoad;
      plan.message =
          "the force is beyond the membrane's limit load (without friction the corner needs "
          "s_eq(L) / L = f / a under the tip, which this law never reaches)";
      return plan;
    }
    const double g_onset = part_two_indicator(f).value_or(kBeyondDomain);
    if (g_onset < 0.0 && pressure_ > 0.0) {
      // Under pressure a Part I that cannot be integrated is no sign of a stretch beyond the
      // root (the gas may curl a slack membrane): the stretch is bracketed from below, between
      // two candidates whose residuals are known (bracket_from_below; those below the onset
      // have no start and are passed over).
      ShootingPlan plan = face_plan(f, counted);
      if (plan.ok()) return plan;
    }
    if (g_onset < 0.0) {
      // Part I reaches the clamp with lambda2 < 1 even when it leaves the corner vertically, so
      // a larger Part III stretch (and a flatter exit) is needed: no Part II.
      plan.configuration = Configuration::SlipWithoutPartTwo;
      plan.lo = *onset;
      plan.g_lo = g_onset;
      plan.cap = locking_radial_stretch(law_, 1.0);
      if (*onset <= s_.a) {  // that exit's corner lies beyond the clamp: from the clamp inward
        plan.lo = s_.a * (1.0 + 1e-9);
        plan.g_lo = counted(Configuration::SlipWithoutPartTwo, plan.lo).value_or(kBeyondDomain);
        if (!(plan.g_lo < 0.0)) {
          plan.status = Status::NoConvergence;
          plan.message =
              "slip shooting: no Part III stretch with its corner inside the clamp has a "
              "negative clamp residual";
          return plan;
        }
      }
    } else {
      // Part II exists: shoot on lambda2 where Part I leaves the side (between 1 and the onset).
      // At the lowest top stretch, lambda2 -> a, Part I shrinks to the clamp and the residual
      // tends to a - 1 < 0.  (Top stretches below 1 occur on soft laws at large loads: material
      // from beyond the indenter's radius climbs its side, hoop-compressed but taut, s2 > 0.)
      // (A small indenter's top at the clamp is past locking: side_bracket_start.)
      const auto [lowest, g_low] =
          side_bracket_start(counted, parameter_floor(Configuration::SlipWithPartTwo), *onset);
      if (g_low >= 0.0) {
        plan.status = std::isfinite(locking_i1_) ? Status::BeyondLocking : Status::LimitLoad;
        plan.message = std::isfinite(locking_i1_)
                           ? "the force is beyond what the membrane can carry before the "
                             "material locks"
                           : "the force is beyond the membrane's limit load (this law's stress "
                             "under the tip grows too slowly with stretch to carry it)";
        return plan;
      }
      plan.configuration = Configuration::SlipWithPartTwo;
      plan.lo = lowest;
      plan.g_lo = g_low;
      plan.cap = *onset;
      plan.g_cap = g_onset;  // the indicator is the residual at the onset stretch
    }
    plan.no_root_message =
        fmt::format("slip shooting ({}) found no parameter meeting the clamp condition",
                    to_string(plan.configuration));
    return plan;
  }

  // The corner and the largest I1 of Part II (corner: lambda1 and Part II's length there).
  void finish_part_two(const PartTwoSystem<Law>& side,
                       const InteriorMaximum<PartTwoState>& side_max, double r_corner,
                       const PartTwoState& corner, ScaledSolution& sol) const {
    auto track = [&](double r, double i1) {  // on the side: current radius a
      if (i1 > sol.max_i1) {
        sol.max_i1 = i1;
        sol.max_i1_r = r;
        sol.max_i1_radius = s_.a;
      }
    };
    track(r_corner, first_invariant(corner[0], s_.a / r_corner));
    if (side_max.observed()) {
      const auto side_peak = refined_maximum(side_max, side, [&](double r, const PartTwoState& y) {
        return first_invariant(y[0], s_.a / r);
      });
      track(side_peak.r, side_peak.value);
    }
    sol.r_corner = r_corner;
    sol.part_three_stretch = s_.a / r_corner;
    sol.part_two_length = corner[1];
    const double l3 = sol.part_three_stretch;
    sol.edge_s1 = membrane_stress(law_, corner[0], l3).s1;
    sol.tension_ratio = sol.edge_s1 / membrane_stress(law_, l3, l3).s1;
  }

  const FreePart<Law>& part_one_;
  const Law& law_;
  FlatPunchSettings s_;
  double locking_i1_;
  double pressure_;   // gas pressure P under the membrane (0: none)
  double face_load_;  // its resultant on the face, P a^2 / 2
  // Friction under a gas pressure: Part III is not uniform (flat_punch_face.hpp), and both
  // sliding configurations are shot on its pole stretch.
  bool rough_face_;
  // Stick under a gas pressure: the material held on the face where it touched the dome.
  std::shared_ptr<HeldFaceHistory<Law>> held_face_;
};

}  // namespace puncture::detail
