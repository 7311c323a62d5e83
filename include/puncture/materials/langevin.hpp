#pragma once
// The Langevin function L(b) = coth(b) - 1/b, its derivative and its inverse, as the
// Arruda-Boyce law needs them to rounding: below b = 1/2 from their Taylor series (the closed
// forms lose digits to cancellation there), above it from the closed forms.
#include <array>
#include <cmath>
#include <limits>

namespace puncture::langevin {

// Taylor coefficients of coth(b) - 1/b in powers b^(2n-1), n = 1..10: 2^(2n) B_2n / (2n)!.  The
// first omitted term is < 1e-16 of the sum for b < 1/2.
inline constexpr std::array<double, 10> kSeries{1.0 / 3.0,
                                                -1.0 / 45.0,
                                                2.0 / 945.0,
                                                -1.0 / 4725.0,
                                                2.0 / 93555.0,
                                                -1382.0 / 638512875.0,
                                                4.0 / 18243225.0,
                                                -3617.0 / 162820783125.0,
                                                87734.0 / 38979295480125.0,
                                                -349222.0 / 1531329465290625.0};
inline constexpr double kSeriesBelow = 0.5;

// L(b), b >= 0.
inline double function(double b) {
  if (b < kSeriesBelow) {
    const double b2 = b * b;
    double sum = 0.0;
    for (auto it = kSeries.rbegin(); it != kSeries.rend(); ++it) sum = sum * b2 + *it;
    return sum * b;
  }
  return 1.0 / std::tanh(b) - 1.0 / b;
}

// L'(b) = 1/b^2 - 1/sinh(b)^2, b >= 0.
inline double derivative(double b) {
  if (b < kSeriesBelow) {
    const double b2 = b * b;
    double sum = 0.0;
    for (int n = static_cast<int>(kSeries.size()); n >= 1; --n)
      sum = sum * b2 + (2 * n - 1) * kSeries[n - 1];
    return sum;
  }
  const double s = std::sinh(b);  // inf for b > 710: 1/s^2 = 0
  return 1.0 / (b * b) - 1.0 / (s * s);
}

// ln(sinh(b) / b), b >= 0: its series is the integral of L, 2^(2n) B_2n / (2n (2n)!) b^(2n).
inline double log_sinh_over(double b) {
  if (b < kSeriesBelow) {
    const double b2 = b * b;
    double sum = 0.0;
    for (int n = static_cast<int>(kSeries.size()); n >= 1; --n)
      sum = sum * b2 + kSeries[n - 1] / (2 * n);
    return sum * b2;
  }
  // ln sinh(b) = b + ln(1 - exp(-2b)) - ln 2, finite for every b.
  return b + std::log1p(-std::exp(-2.0 * b)) - std::log(2.0) - std::log(b);
}

// The inverse b = L^-1(x), 0 <= x < 1: Newton from Cohen's (1991) Pade approximant
// x (3 - x^2) / (1 - x^2) (within 5 %).  L is increasing and concave, so after the first step
// the iterates rise monotonically to the root.  Newton converges quadratically: once a step is
// below 1e-9 b, one more leaves an error at rounding.  NaN for x outside [0, 1).
inline double inverse(double x) {
  if (!(x >= 0.0) || !(x < 1.0)) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0.0) return 0.0;
  double b = x * (3.0 - x * x) / (1.0 - x * x);
  for (int i = 0; i < 60; ++i) {
    const double step = (function(b) - x) / derivative(b);
    b = b - step > 0.0 ? b - step : 0.5 * b;  // the first step may overshoot below zero
    if (std::abs(step) <= 1e-9 * b) return b - (function(b) - x) / derivative(b);
  }
  return b;
}

}  // namespace puncture::langevin
