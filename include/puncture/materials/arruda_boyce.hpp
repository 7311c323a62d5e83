#pragma once
// Arruda & Boyce (1993) eight-chain solid.  With the chain stretch lambda_c = sqrt(I1 / 3), its
// ratio to the locking stretch sqrt(N) x = lambda_c / sqrt(N) and b = L^-1(x) (langevin.hpp),
//   W = mu N (x b + ln(b / sinh b)) + const,   dW/dI1 = mu b / (6 x).
// Written with the initial shear modulus G = 2 dW/dI1 at I1 = 3 factored out (G = mu g(x0) / 3,
// g = b / x, x0 = 1 / sqrt(N); G -> mu as N -> infinity):
//   W / G = (3 N / g0) (h(x) - h(x0)),  h = x b - ln(sinh b / b),   W1 = g(x) / (2 g0).
// It locks as x -> 1, at I1 = 3 N.  g(x) = 3 + 9 x^2 / 5 + O(x^4) grows with x, so W1 > 1/2 and
// W11 > 0: s1 grows with lambda1 for every N > 1.  As N -> infinity, W1 / (1/2) = 1 + (I1 - 3) /
// (5 N) + O(N^-2): neo-Hookean at rate 1/N.
#include <cmath>
#include <limits>
#include <string_view>

#include "puncture/materials/invariant_derivatives.hpp"
#include "puncture/materials/langevin.hpp"

namespace puncture {

struct ArrudaBoyce {
  double n = 128.0 / 3.0;  // Kuhn segments per chain N (> 1); this default locks at the default
                           // Gent law's I1 = 128 (3 N = 3 + J_lim, Horgan & Saccomandi 2002)

  static constexpr bool depends_on_i2 = false;
  static constexpr std::string_view name() { return "arruda-boyce"; }
  double locking_i1() const { return 3.0 * n; }
  // The locking stretch of a chain, sqrt(N).
  double chain_stretch() const { return std::sqrt(n); }

  InvariantDerivatives derivatives(double i1, double /*i2*/) const {
    const double x = std::sqrt(i1 / (3.0 * n));
    if (!(x < 1.0)) {
      const double inf = std::numeric_limits<double>::infinity();
      return {inf, inf, 0.0, inf, 0.0, 0.0};
    }
    const double x0 = 1.0 / std::sqrt(n);
    const double b = langevin::inverse(x), b0 = langevin::inverse(x0);
    const double g = b / x, g0 = b0 / x0;
    const double h = x * b - langevin::log_sinh_over(b);
    const double h0 = x0 * b0 - langevin::log_sinh_over(b0);
    // dg/dx = (x db/dx - b) / x^2 with db/dx = 1 / L'(b); dx/dI1 = 1 / (6 N x).
    const double dg_dx = (x / langevin::derivative(b) - b) / (x * x);
    return {3.0 * n / g0 * (h - h0), 0.5 * g / g0, 0.0, 0.5 * dg_dx / (g0 * 6.0 * n * x), 0.0, 0.0};
  }
};

}  // namespace puncture
