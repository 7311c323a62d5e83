#pragma once
// lambda1(s1, lambda2): Newton on the monotone map lambda1 -> s1(lambda1, lambda2) inside the
// bracket [lambda3-equal stretch, locking stretch], with Boost.Math's bracketed Newton.
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

template <class Law>
std::optional<double> invert_radial_stress(const Law& law, double s1, double l2,
                                           double guess = 0.0) {
  if (!(s1 >= 0.0) || !std::isfinite(s1) || !(l2 > 0.0) || !std::isfinite(l2)) return std::nullopt;
  double lo = 1.0 / std::sqrt(l2);  // s1 = 0 there (lambda1 = lambda3)
  if (s1 == 0.0) return lo;
  double hi = locking_radial_stretch(law, l2);
  if (!(hi > lo)) return std::nullopt;
  if (!std::isfinite(hi)) {  // no locking: s1 grows at least linearly, so doubling brackets it
    hi = 2.0 * lo;
    while (membrane_stress(law, hi, l2).s1 < s1) {
      lo = hi;
      hi *= 2.0;
      if (hi > 1e12) return std::nullopt;
    }
  }
  const double start = (guess > lo && guess < hi) ? guess : 0.5 * (lo + hi);
  std::uintmax_t max_iter = 200;
  const double x = boost::math::tools::newton_raphson_iterate(
      [&](double l1) {
        const auto st = membrane_stress(law, l1, l2);
        return std::make_pair(st.s1 - s1, st.ds1_dl1);
      },
      start,
      lo,
      hi,
      50,
      max_iter);
  if (!std::isfinite(x)) return std::nullopt;
  return x;
}

}  // namespace puncture::detail
