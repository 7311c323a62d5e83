#include "puncture/kinematics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <utility>

#include "puncture/outcome.hpp"

namespace puncture {

double equibiaxial_first_invariant(double stretch) {
  const double l2 = stretch * stretch;
  return 2.0 * l2 + 1.0 / (l2 * l2);
}

double equibiaxial_stretch_for_first_invariant(double i1) {
  if (!std::isfinite(i1) || i1 < 3.0)
    throw InvalidInput("i1",
                       fmt::format("equibiaxial I1 must be a finite number >= 3, got {}", i1));
  if (i1 == 3.0) return 1.0;
  // I1(l) increases on l >= 1 (dI1/dl = 4 l - 4 l^-5 > 0); 2 l^2 <= I1 bounds the root above.
  const auto f = [i1](double l) {
    const double l2 = l * l;
    return std::pair{2.0 * l2 + 1.0 / (l2 * l2) - i1, 4.0 * l - 4.0 / (l2 * l2 * l)};
  };
  const double upper = std::sqrt(0.5 * i1) + 1.0;
  const double guess = std::max(std::sqrt(0.5 * i1), 1.0 + 1e-3);
  std::uintmax_t max_iter = 100;
  return boost::math::tools::newton_raphson_iterate(f, guess, 1.0, upper, 50, max_iter);
}

}  // namespace puncture
