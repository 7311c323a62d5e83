#pragma once
// A root of a function of one variable inside a known sign change.
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <utility>

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

// The bracket [lo, hi] of g's root (g(lo) = g_lo, g(hi) = g_hi of opposite signs, lo < hi) closed
// by TOMS 748 to an absolute width `width`, at most 100 evaluations.
template <class G>
std::pair<double, double> bracket_to_width(G&& g, double lo, double hi, double g_lo, double g_hi,
                                           double width) {
  std::uintmax_t iterations = 100;
  return boost::math::tools::toms748_solve(
      g,
      lo,
      hi,
      g_lo,
      g_hi,
      [width](double a, double b) { return std::abs(b - a) <= width; },
      iterations);
}

// Closes a sign change of g(p) between lo and hi (either order) on a gas pressure p, to 1e-12 of
// the absolute pressure p + p_atm: below what an enclosed volume's ~1e-10 lets a gas law resolve.
// TOMS 748, at most 40 evaluations; g keeps its own best trial, so the bracket is not returned.
template <class G>
void close_gas_pressure_bracket(G&& g, double lo, double hi, double g_lo, double g_hi,
                                double p_atm) {
  if (hi < lo) {
    std::swap(lo, hi);
    std::swap(g_lo, g_hi);
  }
  std::uintmax_t iterations = 40;
  boost::math::tools::toms748_solve(
      g,
      lo,
      hi,
      g_lo,
      g_hi,
      [&](double a, double b) { return std::abs(b - a) <= 1e-12 * (std::abs(a) + p_atm); },
      iterations);
}

}  // namespace puncture::detail
