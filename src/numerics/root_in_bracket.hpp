#pragma once
// A root of a function of one variable inside a known sign change.
#include <boost/math/tools/toms748_solve.hpp>
#include <cstdint>

namespace puncture::detail {

// The root of g between a and b, where g(a) = g_a and g(b) = g_b differ in sign (or one is
// zero): TOMS 748 to 50 bits, at most 100 evaluations, the final bracket's midpoint.
template <class G>
double root_in_bracket(G&& g, double a, double b, double g_a, double g_b) {
  std::uintmax_t iterations = 100;
  const auto bracket = boost::math::tools::toms748_solve(
      g, a, b, g_a, g_b, boost::math::tools::eps_tolerance<double>(50), iterations);
  return 0.5 * (bracket.first + bracket.second);
}

}  // namespace puncture::detail
