#pragma once
// Gent-Gent (Pucci & Saccomandi 2002): Gent's locking I1 term and a logarithmic I2 term,
// W = -(mu J_lim / 2) ln(1 - (I1 - 3) / J_lim) + C2 ln(I2 / 3), written with the initial shear
// modulus G = mu + 2 C2 / 3 factored out and alpha = (2 C2 / 3) / G the share of G in the I2
// term (Mooney-Rivlin's alpha at small strain):
//   W / G = -(1 - alpha) (J_lim / 2) ln(1 - (I1 - 3) / J_lim) + alpha (3 / 2) ln(I2 / 3).
// alpha = 0 is Gent.  It locks where Gent does, at I1 = 3 + J_lim.
#include <cmath>
#include <limits>
#include <string_view>

#include "puncture/materials/invariant_derivatives.hpp"

namespace puncture {

struct GentGent {
  double j_lim = 125.0;  // limiting value of I1 - 3 (dimensionless)
  double alpha = 0.1;    // share of the shear modulus carried by the I2 term, in [0, 1)

  static constexpr std::string_view name() { return "gent-gent"; }
  double locking_i1() const { return 3.0 + j_lim; }

  InvariantDerivatives derivatives(double i1, double i2) const {
    const double x = 1.0 - (i1 - 3.0) / j_lim;
    if (x <= 0.0) {
      const double inf = std::numeric_limits<double>::infinity();
      return {inf, inf, 0.0, inf, 0.0, 0.0};
    }
    const double gent = 1.0 - alpha, w1 = 0.5 * gent / x, w2 = 1.5 * alpha / i2;
    return {-0.5 * gent * j_lim * std::log(x) + 1.5 * alpha * std::log(i2 / 3.0),
            w1,
            w2,
            0.5 * gent / (j_lim * x * x),
            0.0,
            -w2 / i2};
  }
};

}  // namespace puncture
