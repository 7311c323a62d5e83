#pragma once
// The inflated membrane's ODEs and their regular start at the pole, in normalised variables:
// lengths / A, stresses / G, pressure P = p A / (G H) (docs/model.md, "Inflation (bulge) test").
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "numerics/integrate.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// State along the reference radius R: t = R s1 cos(phi) (horizontal force per radian), the
// strains lambda1 - 1 and lambda2 - 1 (so that the integrator's relative tolerance is relative
// to the strain, which keeps small pressures accurate), the drop h below the pole, and the
// running integrals v (enclosed volume / A^3) and e (stored energy / (2 pi G H A^2)).  The vertical
// balance of the cap inside R, R s1 sin(phi) = P r^2 / 2, gives R s1 = S = sqrt(t^2 + g^2) with g =
// P r^2 / 2, so phi in (0, pi) comes from atan2(g, t) without a square root of 1 - sin^2: the
// meridian may pass the vertical (t < 0) where the dome overhangs the clamp.
using InflationOdeState = std::array<double, 6>;

template <class Law>
struct InflationSystem {
  const Law& law;
  double pressure;  // P
  double max_i1;    // locking limit of the law

  void operator()(const InflationOdeState& x, InflationOdeState& dx, double r_ref) const {
    const double t = x[0], l1 = 1.0 + x[1], l2 = 1.0 + x[2];
    if (!(l1 > 0.0) || !(l2 > 0.0)) throw IntegrationFailure{};
    const auto st = membrane_stress(law, l1, l2);
    if (!(st.i1 < max_i1) || !(st.ds1_dl1 > 0.0) || !std::isfinite(st.ds1_dl1))
      throw IntegrationFailure{};
    const double r = l2 * r_ref;
    const double g = 0.5 * pressure * r * r;
    const double s_total = std::hypot(t, g);
    const double cos_phi = t / s_total, sin_phi = g / s_total;
    // 1 - cos(phi) without cancellation where phi is small.
    const double one_minus_cos = t > 0.0 ? g * g / (s_total * (s_total + t)) : 1.0 - cos_phi;
    const double dl2 = (x[1] * cos_phi - x[2] - one_minus_cos) / r_ref;  // (l1 cos - l2) / R
    // d(R s1)/dR = cos(phi) s2 (radial and vertical balance together), solved for lambda1'.
    const double dl1 = (cos_phi * st.s2 - st.s1 - r_ref * st.ds1_dl2 * dl2) / (r_ref * st.ds1_dl1);
    const double i2 = second_invariant(l1, l2);
    dx[0] = st.s2 - pressure * r * l1 * sin_phi;  // radial balance of a ring
    dx[1] = dl1;
    dx[2] = dl2;
    dx[3] = l1 * sin_phi;                             // drop below the pole
    dx[4] = std::numbers::pi * r * r * l1 * sin_phi;  // pi r^2 |dz|
    dx[5] = law.derivatives(st.i1, i2).w * r_ref;     // W R
  }
};

// The solution near the pole, where the equations are singular (1/R), as a series:
//   lambda1 = l0 + a R^2,  lambda2 = l0 + b R^2,  phi = c R,  c = P l0^2 / (2 s0),
// from the vertical balance (c), d(R s1)/dR = s2 cos(phi) at order R^2 and lambda2 = r / R
// with r = int lambda1 cos(phi) (a, b); docs/model.md gives the derivation.  The state at
// R = eps is then exact to O(eps^4) relative; eps = 1e-3 / max(1, c) makes that 1e-12.
struct PoleStart {
  double r_ref;         // eps
  InflationOdeState x;  // the state there
  double slope_rate;    // c = dphi/dR at the pole
  double pole_stress;   // s0 = s_eq(l0)
  double pole_energy;   // W(l0, l0) / G
};

template <class Law>
std::optional<PoleStart> pole_start(const Law& law, double l0, double pressure, double max_i1) {
  const auto st = membrane_stress(law, l0, l0);
  if (!(st.i1 < max_i1) || !(st.s1 > 0.0) || !(st.ds1_dl1 > 0.0)) return std::nullopt;
  const double s0 = st.s1, a1 = st.ds1_dl1, a2 = st.ds1_dl2;
  const double c = pressure * l0 * l0 / (2.0 * s0);
  const double a = c * c * ((3.0 * a2 - a1) * l0 - 3.0 * s0) / (16.0 * a1);
  const double b = (a - 0.5 * l0 * c * c) / 3.0;
  const double eps = 1e-3 / std::max(1.0, c);
  const double l1 = l0 + a * eps * eps, l2 = l0 + b * eps * eps;
  const auto se = membrane_stress(law, l1, l2);
  if (!(se.i1 < max_i1)) return std::nullopt;
  const double s_total = eps * se.s1;
  const double g = 0.5 * pressure * (l2 * eps) * (l2 * eps);
  if (!(s_total > g)) return std::nullopt;
  const double t = std::sqrt((s_total - g) * (s_total + g));
  const double w0 = law.derivatives(st.i1, second_invariant(l0, l0)).w;
  const double e2 = eps * eps;
  PoleStart start{eps,
                  {t,
                   (l0 - 1.0) + a * eps * eps,
                   (l0 - 1.0) + b * eps * eps,
                   0.5 * l0 * c * e2,                                     // int l0 c R dR
                   0.25 * std::numbers::pi * l0 * l0 * l0 * c * e2 * e2,  // int pi l0^3 c R^3
                   0.5 * w0 * e2},                                        // int W0 R dR
                  c,
                  s0,
                  w0};
  return start;
}

}  // namespace puncture::detail
