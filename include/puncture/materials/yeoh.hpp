#pragma once
// Yeoh (1993) solid, W = C10 (I1 - 3) + C20 (I1 - 3)^2 + C30 (I1 - 3)^3, written with the
// shear modulus G = 2 C10 factored out:
//   W / G = x / 2 + c2 x^2 + c3 x^3,   x = I1 - 3,   c2 = C20 / G,   c3 = C30 / G.
// c2 = c3 = 0 is neo-Hookean.  It does not lock.  The membrane solver inverts s1(lambda1) at
// fixed lambda2, which needs s1 to grow with lambda1: c2, c3 >= 0 guarantee it (dW/dI1 >= 1/2,
// d2W/dI1^2 >= 0).  A negative C20, common in fits, can make s1 fall over a range of stretch
// (e.g. c2 = -0.05, c3 = 0.002 near I1 = 7): a material instability this theory cannot follow,
// so it is refused (validation_errors).
#include <limits>
#include <string_view>

#include "puncture/materials/invariant_derivatives.hpp"

namespace puncture {

struct Yeoh {
  double c2 = 0.0;  // C20 / G = C20 / (2 C10), >= 0
  double c3 = 0.0;  // C30 / G = C30 / (2 C10), >= 0

  static constexpr bool depends_on_i2 = false;
  static constexpr std::string_view name() { return "yeoh"; }
  static constexpr double locking_i1() { return std::numeric_limits<double>::infinity(); }

  InvariantDerivatives derivatives(double i1, double /*i2*/) const {
    const double x = i1 - 3.0;
    return {x * (0.5 + x * (c2 + x * c3)),
            0.5 + x * (2.0 * c2 + 3.0 * c3 * x),
            0.0,
            2.0 * c2 + 6.0 * c3 * x,
            0.0,
            0.0};
  }
};

}  // namespace puncture
