#pragma once
// Ogden (1972) solid with 1 to 3 terms, written in principal stretches (not invariants):
//   W = sum_p mu_p / alpha_p (lambda1^alpha_p + lambda2^alpha_p + lambda3^alpha_p - 3),
// with the initial shear modulus G = sum_p mu_p alpha_p / 2 factored out: `mu` holds mu_p / G,
// so sum_p mu_p alpha_p = 2 (ogden_material() in material.hpp builds it from MPa values).  In
// the membrane (lambda3 = 1 / (lambda1 lambda2)) the nominal stresses are
//   s1 = sum_p mu_p (lambda1^alpha_p - lambda3^alpha_p) / lambda1   (s2 likewise)
// and their derivatives
//   ds1/dlambda1 = sum_p mu_p ((alpha_p - 1) lambda1^alpha_p + (alpha_p + 1) lambda3^alpha_p)
//                  / lambda1^2,
//   ds1/dlambda2 = sum_p mu_p alpha_p lambda3^alpha_p / (lambda1 lambda2).
// Every term with mu_p alpha_p > 0 and |alpha_p| >= 1 makes ds1/dlambda1 > 0 (both of its terms
// are >= 0, one > 0), and keeps the sign of s2 that of lambda2 - lambda3 (the wrinkling rule):
// validation_errors requires both of each term (docs/model.md).  It does not lock.
// mu = {1}, alpha = {2} is neo-Hookean; alpha = {2, -2} with mu = {1 - a, -a} is Mooney-Rivlin.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string_view>
#include <vector>

#include "puncture/membrane_stress.hpp"

namespace puncture {

struct Ogden {
  std::vector<double> mu{1.0};     // mu_p / G [dimensionless], sum mu_p alpha_p = 2
  std::vector<double> alpha{2.0};  // exponents alpha_p [dimensionless], |alpha_p| >= 1

  static constexpr std::string_view name() { return "ogden"; }
  static constexpr double locking_i1() { return std::numeric_limits<double>::infinity(); }
  // Lists of different lengths are invalid (validation_errors); the terms both give are used.
  std::size_t terms() const { return std::min(mu.size(), alpha.size()); }

  // The membrane stresses / G and their derivatives, directly in the stretches
  // (membrane_stress() calls this instead of going through the invariants).
  MembraneStress stresses(double l1, double l2) const {
    // lambda^alpha = exp(alpha ln lambda): three logarithms for all the terms.
    const double ln1 = std::log(l1), ln2 = std::log(l2), ln3 = -(ln1 + ln2);
    const double il1 = 1.0 / l1, il2 = 1.0 / l2;
    MembraneStress s{0.0, 0.0, 0.0, 0.0, 0.0, first_invariant(l1, l2)};
    for (std::size_t p = 0; p < terms(); ++p) {
      const double a = alpha[p], m = mu[p];
      // lambda^a - 1 by expm1: the stresses keep their digits near the unstretched state.
      const double e1 = std::expm1(a * ln1), e2 = std::expm1(a * ln2), e3 = std::expm1(a * ln3);
      const double p1 = 1.0 + e1, p2 = 1.0 + e2, p3 = 1.0 + e3;
      s.s1 += m * (e1 - e3) * il1;
      s.s2 += m * (e2 - e3) * il2;
      s.ds1_dl1 += m * ((a - 1.0) * p1 + (a + 1.0) * p3) * il1 * il1;
      s.ds1_dl2 += m * a * p3 * il1 * il2;
      s.ds2_dl2 += m * ((a - 1.0) * p2 + (a + 1.0) * p3) * il2 * il2;
    }
    return s;
  }

  // W / G at the stretches.
  double energy(double l1, double l2) const {
    const double ln1 = std::log(l1), ln2 = std::log(l2), ln3 = -(ln1 + ln2);
    double w = 0.0;
    for (std::size_t p = 0; p < terms(); ++p) {
      const double a = alpha[p];
      w += mu[p] / a * (std::expm1(a * ln1) + std::expm1(a * ln2) + std::expm1(a * ln3));
    }
    return w;
  }
};

}  // namespace puncture
