#pragma once
// The free membrane's ODEs along the reference radius R, under a transverse load: a point force
// at its inner end, a pressure on it, or both (docs/model.md, §3 and §14).  Normalised variables:
// lengths / A, stresses / G, f = F / (2 pi G H A), P = p A / (G H).  Part I of the indentation
// integrates it with the stretches and f alone, the inflation with the strains, the volume and
// the energy and P alone.
#include <cmath>
#include <numbers>

#include "mechanics/free_membrane_state.hpp"
#include "mechanics/transverse_load.hpp"
#include "numerics/integrate.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// With t = R s1 cos(phi) (horizontal force per radian) a state, the vertical balance
// R s1 sin(phi) = g = f + P r^2 / 2 gives R s1 = S = sqrt(t^2 + g^2), cos(phi) = t / S and
// sin(phi) = g / S: no square root of 1 - sin^2, which would be singular where the meridian is
// vertical (Part I leaving the indenter's side, a dome overhanging its clamp; t < 0 beyond).
//   dt/dR  = s2 - P r lambda1 sin(phi)      radial balance of a ring (hoop force, pressure)
//   d(R s1)/dR = s2 cos(phi)                radial and vertical balance together, for any f and
//                                           P (dg/dR = P r lambda1 cos(phi)), solved for lambda1'
//   dlambda2/dR = (lambda1 cos(phi) - lambda2) / R    lambda2 = r / R, dr/dR = lambda1 cos(phi)
//   dh/dR  = lambda1 sin(phi)               height, measured against the load
// and, in a layout that carries them, dv/dR = pi r^2 lambda1 sin(phi), de/dR = W R.
template <class Law, class Layout>
struct FreeMembraneSystem {
  using State = typename Layout::State;

  const Law& law;
  TransverseLoad load;
  double locking_i1;  // locking limit of the law

  void operator()(const State& x, State& dx, double r_ref) const {
    const double t = x[0], l1 = Layout::lambda1(x), l2 = Layout::lambda2(x);
    if (!(l1 > 0.0) || !(l2 > 0.0)) return outside_domain(dx);
    const auto st = membrane_stress(law, l1, l2);
    // s1 grows with lambda1 at fixed lambda2 for every law here; the lambda1 equation divides by
    // ds1/dlambda1.
    if (!(st.i1 < locking_i1) || !(st.ds1_dl1 > 0.0) || !std::isfinite(st.ds1_dl1))
      return outside_domain(dx);
    const double r = l2 * r_ref;
    const double g = load.vertical(r);
    const double s_total = Layout::resultant(t, g);
    const double cos_phi = t / s_total, sin_phi = g / s_total;
    const double dl2 = Layout::hoop_gap(x, t, g, s_total, cos_phi) / r_ref;
    const double dl1 = (cos_phi * st.s2 - st.s1 - r_ref * st.ds1_dl2 * dl2) / (r_ref * st.ds1_dl1);
    dx[0] = st.s2 - load.pressure * r * l1 * sin_phi;
    dx[1] = dl1;
    dx[2] = dl2;
    dx[3] = l1 * sin_phi;
    if constexpr (Layout::integrals) {
      dx[4] = std::numbers::pi * r * r * l1 * sin_phi;
      dx[5] = strain_energy_density(law, l1, l2, st.i1) * r_ref;
    }
  }
};

// Part I of the indentation: (t, lambda1, lambda2, h), h climbed from the inner end.
using PartOneState = Stretches::State;

}  // namespace puncture::detail
