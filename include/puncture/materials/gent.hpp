#pragma once
// Gent (1996) strain-energy function, the paper's Eq. (4):
//   W / G = -(J_lim / 2) ln(1 - (I1 - 3) / J_lim),
// which locks (W -> infinity) as I1 -> 3 + J_lim.
#include <cmath>
#include <limits>
#include <string_view>

#include "puncture/materials/invariant_derivatives.hpp"

namespace puncture {

struct Gent {
  double j_lim = 125.0;  // limiting value of I1 - 3 (dimensionless), the paper's J_lim

  static constexpr bool depends_on_i2 = false;
  static constexpr std::string_view name() { return "gent"; }
  double locking_i1() const { return 3.0 + j_lim; }

  // Energy per unit reference volume divided by the shear modulus, and its I1, I2 derivatives.
  InvariantDerivatives derivatives(double i1, double /*i2*/) const {
    const double x = 1.0 - (i1 - 3.0) / j_lim;
    if (x <= 0.0) {
      const double inf = std::numeric_limits<double>::infinity();
      return {inf, inf, 0.0, inf, 0.0, 0.0};
    }
    const double w1 = 0.5 / x;
    return {-0.5 * j_lim * std::log(x), w1, 0.0, 2.0 * w1 * w1 / j_lim, 0.0, 0.0};
  }
};

}  // namespace puncture
