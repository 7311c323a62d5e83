#pragma once
// The free membrane (Part I) loaded by a transverse force at its inner end, in the normalised
// variables of docs/model.md: lengths / A, stresses / G, force f = F / (2 pi G H A).
#include <array>
#include <cmath>

#include "numerics/integrate.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// Part I state: t = R s1 cos(phi) (horizontal force per radian), lambda1, lambda2, and the height
// h climbed from the inner end of Part I.  The vertical balance R s1 sin(phi) = f (Eq. 12) gives
// R s1 = sqrt(t^2 + f^2) =: S, so phi never needs a square root of 1 - sin^2, which would be
// singular where Part I leaves the indenter's side vertically.
using PartOneState = std::array<double, 4>;

template <class Law>
struct PartOneSystem {
  const Law& law;
  double f;       // normalised indenter force
  double max_i1;  // locking limit of the law

  void operator()(const PartOneState& x, PartOneState& dx, double r_ref) const {
    const double t = x[0], l1 = x[1], l2 = x[2];
    if (!(l1 > 0.0) || !(l2 > 0.0)) throw IntegrationFailure{};
    const auto st = membrane_stress(law, l1, l2);
    if (!(st.i1 < max_i1) || !std::isfinite(st.ds1_dl1)) throw IntegrationFailure{};
    const double s_total = std::sqrt(t * t + f * f);
    const double cos_phi = t / s_total, sin_phi = f / s_total;
    const double dl2 = (l1 * cos_phi - l2) / r_ref;  // Eq. (11)
    // d(R s1)/dR = dS/dR = cos(phi) s2 (Eq. 13 with Eq. 12), solved for dlambda1/dR.
    const double dl1 = (cos_phi * st.s2 - st.s1 - r_ref * st.ds1_dl2 * dl2) / (r_ref * st.ds1_dl1);
    dx[0] = st.s2;  // Eq. (13): d(R s1 cos phi)/dR = s2
    dx[1] = dl1;
    dx[2] = dl2;
    dx[3] = l1 * sin_phi;  // Eq. (9)
  }
};

}  // namespace puncture::detail
