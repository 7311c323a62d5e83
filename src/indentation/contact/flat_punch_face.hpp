#pragma once
// Part III on the flat face of the punch when a gas pressure P presses the membrane onto it and
// Coulomb friction acts (docs/model.md §17): the contact pressure on the flat face is P, so the
// membrane sliding outward over the face is held back by the traction mu P (per current area) and
// Part III is no longer uniform.  Normalised variables (lengths / (A / L0), stresses / G).
//
// Radial balance of a ring on the face (reference radius R, current r = lambda2 R, flat:
// dr/dR = lambda1), the friction pointing towards the axis:
//   d(R s1)/dR = s2 + mu P lambda1 r.
// Integrated in the current radius r (its end, the contact edge c or the punch's radius a, is
// known beforehand), state (R, lambda1), lambda2 = r / R:
//   dR/dr = 1 / lambda1,
//   dlambda1/dr = [(s2 - s1) / lambda1 + mu P r - ds1/dlambda2 (1 - lambda2 / lambda1)]
//                 / (R ds1/dlambda1).
// The pole (r = 0) is a regular singular point; the regular solution starts as
//   lambda2 = L + b R, lambda1 = L + 2 b R, b = mu P L^2 / (3 ds1/dlambda1(L, L)),
// L the pole stretch (a series; the sphere's cap has the same with its Laplace pressure).
#include <array>
#include <cmath>
#include <optional>

#include "numerics/integrate.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// (R, lambda1) along the current radius r.
using PartThreeState = std::array<double, 2>;

template <class Law>
struct PartThreeSystem {
  const Law& law;
  double mu_pressure;  // mu P: the friction traction on the face
  double locking_i1;

  void operator()(const PartThreeState& x, PartThreeState& dx, double r) const {
    const double big_r = x[0], l1 = x[1];
    if (!(big_r > 0.0) || !(l1 > 0.0)) return outside_domain(dx);
    const double l2 = r / big_r;
    const auto st = membrane_stress(law, l1, l2);
    if (!(st.i1 < locking_i1) || !std::isfinite(st.ds1_dl1) || !(st.ds1_dl1 > 0.0))
      return outside_domain(dx);
    dx[0] = 1.0 / l1;
    dx[1] = ((st.s2 - st.s1) / l1 + mu_pressure * r - st.ds1_dl2 * (1.0 - l2 / l1)) /
            (big_r * st.ds1_dl1);
  }

  // The regular solution's start at the small current radius r from the pole stretch L (first
  // order in r; the error, O((mu P r)^2), is far below the integration's tolerance at the
  // radii used).  Empty outside the material's domain.
  std::optional<PartThreeState> pole_start(double pole_stretch, double r) const {
    const auto st = membrane_stress(law, pole_stretch, pole_stretch);
    if (!(st.i1 < locking_i1) || !(st.ds1_dl1 > 0.0) || !std::isfinite(st.ds1_dl1))
      return std::nullopt;
    const double l = pole_stretch;
    const double b = mu_pressure * l * l / (3.0 * st.ds1_dl1);
    // r = lambda2 R = L R + b R^2, so R = r / L - b r^2 / L^3 to second order.
    const double big_r = r / l - b * r * r / (l * l * l);
    return PartThreeState{big_r, l + 2.0 * b * big_r};
  }
};

}  // namespace puncture::detail
