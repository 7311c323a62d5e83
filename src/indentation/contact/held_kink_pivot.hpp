#pragma once
// The held membrane pivoting over the cone's kink (docs/model.md §15.5, "Past the kink"): once the
// held contact edge reaches the kink onto the shank (ProfileStickHistory ends there), the held
// cap is complete and frozen, the material point at the kink stays there, and Part I leaves it
// at a slope phi between the cone's, phi_t = pi/2 - alpha, and the vertical shank's, as the sharp
// punch's membrane held at its corner (§9).  Part I starts at the kink's material R_k with
//   lambda2 = a / R_k (fixed),  R_k s1 sin(phi) = f - P a^2 / 2,  t = R_k s1 cos(phi),
// one unknown, phi, set by the clamp.  At phi = phi_t this is the history's last (tangent) state.
// The kink carries a ring force, the jump of R s1 e_t across it (R s1 frozen at the held value on
// the cone's side); held points do no work, so dU/ddelta = F holds along the pivot too.
//
// Shooting parameter: the stick stage's p = 1 / R_c of the held cap continued past the kink,
//   p = P_k exp(-c (phi - phi_t)),  P_k = 1 / R_k,  c = ln(P_k) / (2 (pi/2 - phi_t)),
// p in [sqrt(P_k), P_k]: continuous with the cap's (the same state at P_k) and decreasing as the
// exit steepens, so the clamp residual grows with p through both (a steeper exit at one force
// stretches Part I less) and the depth Newton's predictor crosses the kink's state smoothly.
#include <cmath>
#include <optional>
#include <string>

#include "indentation/contact/contact_model.hpp"
#include "indentation/contact/profile_stick.hpp"
#include "indentation/free_part.hpp"
#include "mechanics/inverse_stretch.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

template <class Law>
class HeldKinkPivot {
 public:
  HeldKinkPivot(const ProfileStickHistory<Law>& history, const Law& law)
      : history_(history), law_(law) {}

  // Whether the held history ended at the cone's kink (then the pivot follows it).
  bool follows() const {
    return history_.profile().end == HeldProfileEnd::Kink &&
           history_.end() == ProfileHistoryEnd::ProfileEnd && history_.points().size() >= 4;
  }
  // The held material point at the kink: the history's last (its psi within 1e-6 of the kink's).
  const StuckPoint& kink() const { return history_.points().back(); }
  double kink_parameter() const { return 1.0 / kink().r; }
  // The vertical exit's parameter, sqrt(P_k) (> 1: the kink lies inside the clamp).
  double vertical_parameter() const { return std::sqrt(kink_parameter()); }
  bool pivoting(double p) const { return follows() && p < kink_parameter(); }

  // The exit slope of parameter p and back.
  double slope_of(double p) const {
    const double q = history_.profile().tangency;
    return q + turn() * std::log(kink_parameter() / p) / std::log(vertical_ratio());
  }
  double parameter_of(double slope) const {
    const double q = history_.profile().tangency;
    return kink_parameter() / std::pow(vertical_ratio(), (slope - q) / turn());
  }

  // Part I from the kink at force f, exit slope slope_of(p); ratio = s1 outside / s1 held at the
  // kink (the line tension's jump over it).  Empty past the material's domain or for a pull <= 0.
  std::optional<FreeStart> start(double p, double f) const {
    const StuckPoint& k = kink();
    const double phi = std::min(slope_of(p), kHalfPi);
    const double pull = f - history_.gas_load(k.theta, true);
    if (!(pull > 0.0) || !(phi > 0.0)) return std::nullopt;
    const double l2 = kink_hoop_stretch();
    const auto l1 = invert_radial_stress(law_, pull / (k.r * std::sin(phi)), l2);
    if (!l1) return std::nullopt;
    const double ratio = membrane_stress(law_, *l1, l2).s1 / held_s1();
    return FreeStart{{pull * std::cos(phi) / std::sin(phi), *l1, l2, 0.0}, k.r, phi, ratio};
  }

  // The plan at a force past the kink's: from the vertical exit (its clamp residual must be
  // negative; >= 0: the membrane would wrap the shank) up to the grid point before the kink on the
  // held cap's side.
  template <class Residual>
  ShootingPlan plan(Residual& counted) const {
    ShootingPlan plan;
    plan.configuration = Configuration::Stick;
    const double p_vertical = vertical_parameter();
    const auto g = counted(Configuration::Stick, p_vertical);
    if (g && *g >= 0.0) {
      plan.status = Status::StickWrapsSide;
      plan.message =
          "at this force the membrane held at the cone's kink leaves it vertically: it would "
          "wrap the shank, outside the stick model";
      return plan;
    }
    if (!g) {
      plan.status = Status::BeyondLocking;
      plan.message =
          "the force exceeds what the membrane held over the cone's kink carries before it locks";
      return plan;
    }
    const auto& p = history_.points();
    plan.lo = p_vertical;
    plan.g_lo = *g;
    plan.cap = 1.0 / p[p.size() - 2].r;
    plan.no_root_message =
        "the membrane held over the cone's kink: no exit slope meets the clamp condition";
    return plan;
  }

  // The kink's ring force per radian (/ (2 pi G H A / L0) per 2 pi): the membrane's pull on the
  // probe there, R (s1+ e+ - s1- e-), e = (cos, sin) of the exit and the cone's slopes.
  struct RingForce {
    double radial;
    double vertical;
  };
  RingForce ring_force(const FreeStart& st) const {
    const double q = history_.profile().tangency, r = kink().r;
    const double out = r * membrane_stress(law_, st.state[1], st.state[2]).s1, in = r * held_s1();
    return {out * std::cos(st.slope) - in * std::cos(q),
            out * std::sin(st.slope) - in * std::sin(q)};
  }

  // What Coulomb friction must reach to hold the kink: the capstan law over the kink's angle
  // theta = phi - phi_t, T+ <= T- exp(mu theta) (§5), so mu >= |ln(T+ / T-)| / theta; at
  // theta -> 0 the ratio's limit d ln T / dphi (a one-sided difference: 0 at theta = 0 itself).
  double kink_ratio(const FreeStart& st) const {
    const double turn_angle = st.slope - history_.profile().tangency;
    if (!(turn_angle > kSmallestTurn)) return 0.0;
    return std::abs(std::log(st.ratio)) / turn_angle;
  }

  // After attach_held_profile (which treats Part I's start as the held edge): the held cap's
  // kink sample at its own (held) stretch, its I1, the kink's Coulomb ratio and line-tension jump.
  void attach(const FreeStart& st, bool record, ScaledSolution& sol) const {
    const StuckPoint& k = kink();
    const double l2 = kink_hoop_stretch(), radius = l2 * k.r;
    const double i1 = membrane_stress(law_, k.l1, l2).i1;
    if (i1 > sol.max_i1) {
      sol.max_i1 = i1;
      sol.max_i1_r = k.r;
      sol.max_i1_radius = radius;
    }
    if (record && !sol.part_two.empty()) sol.part_two.back()[1] = k.l1;
    sol.held_traction_ratio = std::max(sol.held_traction_ratio, kink_ratio(st));
    sol.tension_ratio = st.ratio;
  }

 private:
  double kink_hoop_stretch() const { return history_.profile().radius(kink().theta) / kink().r; }
  double held_s1() const { return membrane_stress(law_, kink().l1, kink_hoop_stretch()).s1; }
  double turn() const { return kHalfPi - history_.profile().tangency; }
  double vertical_ratio() const { return kink_parameter() / vertical_parameter(); }

  static constexpr double kHalfPi = 0.5 * 3.141592653589793238462643383279502884;
  static constexpr double kSmallestTurn = 1e-9;  // rad: below it the kink's ratio is not resolved

  const ProfileStickHistory<Law>& history_;
  const Law& law_;
};

}  // namespace puncture::detail
