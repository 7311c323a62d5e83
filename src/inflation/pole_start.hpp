#pragma once
// The inflated membrane's regular start at the pole, where its ODEs (the free membrane's,
// mechanics/free_membrane_ode.hpp, in the StrainsAndIntegrals layout under the pressure alone)
// are singular.  Normalised variables: lengths / A, stresses / G, pressure P = p A / (G H)
// (docs/model.md, "Inflation (bulge) test").
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "mechanics/free_membrane_state.hpp"
#include "mechanics/transverse_load.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// (t, lambda1 - 1, lambda2 - 1, h, v, e), h the drop below the pole.
using InflationOdeState = StrainsAndIntegrals::State;

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
std::optional<PoleStart> pole_start(const Law& law, double l0, double pressure, double locking_i1) {
  const auto st = membrane_stress(law, l0, l0);
  if (!(st.i1 < locking_i1) || !(st.s1 > 0.0) || !(st.ds1_dl1 > 0.0)) return std::nullopt;
  const double s0 = st.s1, a1 = st.ds1_dl1, a2 = st.ds1_dl2;
  const double c = pressure * l0 * l0 / (2.0 * s0);
  const double a = c * c * ((3.0 * a2 - a1) * l0 - 3.0 * s0) / (16.0 * a1);
  const double b = (a - 0.5 * l0 * c * c) / 3.0;
  const double eps = 1e-3 / std::max(1.0, c);
  const double l1 = l0 + a * eps * eps, l2 = l0 + b * eps * eps;
  const auto se = membrane_stress(law, l1, l2);
  if (!(se.i1 < locking_i1)) return std::nullopt;
  const double s_total = eps * se.s1;
  const double g = TransverseLoad{0.0, pressure}.vertical(l2 * eps);  // P r^2 / 2
  if (!(s_total > g)) return std::nullopt;
  const double t = std::sqrt((s_total - g) * (s_total + g));
  const double w0 = strain_energy_density(law, l0, l0, st.i1);
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
