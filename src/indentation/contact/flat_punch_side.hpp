#pragma once
// Part II: the membrane wrapped on the cylindrical side of a flat punch, in normalised variables
// (lengths / A, stresses / G).
#include <array>
#include <cmath>

#include "numerics/integrate.hpp"
#include "puncture/membrane_stress.hpp"
#include "puncture/problem.hpp"

namespace puncture::detail {

// Part II state: lambda1 and the length y along the side measured down from the Part I / II
// boundary; lambda2 = a / R (Eq. 15).  Integrated inward (decreasing R).
using PartTwoState = std::array<double, 2>;

template <class Law>
struct PartTwoSystem {
  const Law& law;
  double a;   // normalised indenter radius
  double mu;  // friction coefficient
  PartTwoEquation equation;
  double locking_i1;
  // A gas pressure P (normalised) pressing the membrane onto the side adds P to the contact
  // pressure (docs/model.md §17), hence mu P a lambda1 to the ring balance; 0 without gas.
  double pressure = 0.0;

  void operator()(const PartTwoState& x, PartTwoState& dx, double r_ref) const {
    const double l1 = x[0], l2 = a / r_ref;
    if (!(l1 > 0.0)) return outside_domain(dx);
    const auto st = membrane_stress(law, l1, l2);
    if (!(st.i1 < locking_i1) || !std::isfinite(st.ds1_dl1)) return outside_domain(dx);
    const double dl2 = -l2 / r_ref;
    // Ring balance: d(R s1)/dR = mu s2.  Paper Eq. (18): ds1/dR = mu lambda2 s2 / a = mu s2 / R.
    // Under a gas pressure s2 becomes s2 + P a lambda1 (Eq. 16 plus the gas's contact pressure).
    const double s2 = pressure == 0.0 ? st.s2 : st.s2 + pressure * a * l1;
    const double ds1 =
        equation == PartTwoEquation::RingBalance ? (mu * s2 - st.s1) / r_ref : mu * s2 / r_ref;
    dx[0] = (ds1 - st.ds1_dl2 * dl2) / st.ds1_dl1;
    dx[1] = -l1;  // Eq. (14): dz/dR = lambda1, and y grows downward
  }
};

}  // namespace puncture::detail
