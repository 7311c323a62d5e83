#pragma once
// Where a law's radial stress s1 falls as lambda1 grows at fixed lambda2 (ds1/dlambda1 <= 0), on
// a grid of the stretches the membrane can reach: tension (lambda1^2 lambda2 >= 1, s1 >= 0) below
// the locking I1.  The membrane solver needs s1 to grow (it inverts s1(lambda1)); for Gent-Gent
// this is not a property of the law alone (its ln I2 term is concave), so validation scans for it.
// A grid scan, not a proof: the laws whose monotonicity is proven (materials/*.hpp) do not use it.
#include <cmath>
#include <optional>
#include <utility>

#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// The first grid point (lambda1, lambda2) where ds1/dlambda1 <= 0, if any.  Needs a finite
// locking I1 (the scanned region is bounded by it).
template <class Law>
std::optional<std::pair<double, double>> where_radial_stress_falls(const Law& law) {
  constexpr int kPoints = 160;
  const double i1_max = law.locking_i1();
  if (!std::isfinite(i1_max)) return std::nullopt;
  // lambda2 >= 1 / I1_max: lambda1 >= lambda2^(-1/2) and lambda1^2 < I1_max.
  const double log_max = 0.5 * std::log(i1_max), log_l2_min = -std::log(i1_max);
  for (int j = 0; j <= kPoints; ++j) {
    const double log_l2 = log_l2_min + (log_max - log_l2_min) * j / kPoints;
    const double log_l1_min = -0.5 * log_l2;
    for (int i = 0; i <= kPoints; ++i) {
      const double l1 = std::exp(log_l1_min + (log_max - log_l1_min) * i / kPoints);
      const double l2 = std::exp(log_l2);
      if (!(first_invariant(l1, l2) < i1_max)) break;
      if (!(membrane_stress(law, l1, l2).ds1_dl1 > 0.0)) return std::pair{l1, l2};
    }
  }
  return std::nullopt;
}

}  // namespace puncture::detail
