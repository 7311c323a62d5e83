#pragma once
// Mooney-Rivlin solid, written with the shear modulus G = 2 (C1 + C2) factored out:
//   W / G = (1 - alpha) (I1 - 3) / 2 + alpha (I2 - 3) / 2,   alpha = C2 / (C1 + C2) in [0, 1).
// alpha = 0 is neo-Hookean.
#include <limits>
#include <string_view>

#include "puncture/materials/invariant_derivatives.hpp"

namespace puncture {

struct MooneyRivlin {
  double alpha = 0.1;  // share of the shear modulus carried by the I2 term, C2 / (C1 + C2)

  static constexpr std::string_view name() { return "mooney-rivlin"; }
  static constexpr double locking_i1() { return std::numeric_limits<double>::infinity(); }

  InvariantDerivatives derivatives(double i1, double i2) const {
    return {0.5 * (1.0 - alpha) * (i1 - 3.0) + 0.5 * alpha * (i2 - 3.0),
            0.5 * (1.0 - alpha),
            0.5 * alpha,
            0.0,
            0.0,
            0.0};
  }
};

}  // namespace puncture
