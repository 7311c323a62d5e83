#pragma once
// Gent-Gent solid (Pucci & Saccomandi 2002): Gent's locking I1 term and a logarithmic I2 term,
//   W = -(mu / 2) J_lim ln(1 - (I1 - 3) / J_lim) + C2 ln(I2 / 3),
// written with the initial shear modulus G = mu + 2 C2 / 3 factored out and the I2 term's share
// of it, beta = 2 C2 / (3 G):
//   W / G = -(1 - beta) (J_lim / 2) ln(1 - (I1 - 3) / J_lim) + (3 beta / 2) ln(I2 / 3).
// beta = 0 is Gent (to the bit); at small strain it is Mooney-Rivlin with alpha = beta.  It
// locks at I1 = 3 + J_lim; the I2 term does not lock.  W1, W2 > 0 for 0 <= beta < 1, but ln(I2)
// is concave: where lambda2 >> lambda1 a large beta makes s1 fall as lambda1 grows, which the
// membrane solver cannot follow (validation_errors checks it, docs/model.md).
#include <cmath>
#include <limits>
#include <string_view>

#include "puncture/materials/invariant_derivatives.hpp"

namespace puncture {

struct GentGent {
  double j_lim = 125.0;  // limiting value of I1 - 3 (dimensionless), as Gent's
  double beta = 0.1;     // share of G carried by the I2 term, 2 C2 / (3 G), in [0, 1)

  static constexpr std::string_view name() { return "gent-gent"; }
  double locking_i1() const { return 3.0 + j_lim; }

  InvariantDerivatives derivatives(double i1, double i2) const {
    const double x = 1.0 - (i1 - 3.0) / j_lim;
    if (x <= 0.0) {
      const double inf = std::numeric_limits<double>::infinity();
      return {inf, inf, 0.0, inf, 0.0, 0.0};
    }
    // Gent's terms as gent.hpp writes them, times 1 - beta (exact for beta = 0).
    const double gent = 1.0 - beta, c = 1.5 * beta;
    const double w1 = 0.5 / x;
    return {gent * (-0.5 * j_lim * std::log(x)) + c * std::log(i2 / 3.0),
            gent * w1,
            c / i2,
            gent * (2.0 * w1 * w1 / j_lim),
            0.0,
            -c / (i2 * i2)};
  }
};

}  // namespace puncture
