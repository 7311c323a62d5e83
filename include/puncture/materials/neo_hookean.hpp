#pragma once
// Neo-Hookean solid: W / G = (I1 - 3) / 2.  The J_lim -> infinity limit of Gent.
#include <limits>
#include <string_view>

#include "puncture/materials/invariant_derivatives.hpp"

namespace puncture {

struct NeoHookean {
  static constexpr bool depends_on_i2 = false;
  static constexpr std::string_view name() { return "neo-hookean"; }
  static constexpr double locking_i1() { return std::numeric_limits<double>::infinity(); }

  InvariantDerivatives derivatives(double i1, double /*i2*/) const {
    return {0.5 * (i1 - 3.0), 0.5, 0.0, 0.0, 0.0, 0.0};
  }
};

}  // namespace puncture
