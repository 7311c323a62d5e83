#pragma once
// Scalar shooting: the root of a residual that increases with the shooting parameter, bracketed
// from a known-negative end and refined with Boost.Math's TOMS 748.
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace puncture::detail {

// Value used for a residual that cannot be evaluated because the parameter drives the material
// past its locking limit: that happens only beyond the root, where the residual is positive.
inline constexpr double kBeyondDomain = 1e10;

template <class Residual>
double residual_or_beyond(Residual& g, double p) {
  const std::optional<double> r = g(p);
  return r ? *r : kBeyondDomain;
}

// How a shooting ends besides a bracket closed to a few ulps.
struct ShootingEnd {
  double good_enough = 0.0;     // a parameter whose |g| is at most this is taken as the root
  std::optional<double> g_cap;  // g at a finite cap, when the caller knows it already
};

// Root in (lo, cap) of g, increasing, with g(lo) = g_lo < 0.  Empty if no sign change is found.
// Without a finite cap the bracket grows from lo by initial_step, doubling.
template <class Residual>
std::optional<double> shoot_increasing(Residual&& g_in, double lo, double g_lo, double cap,
                                       int max_iterations, double initial_step = 0.0,
                                       const ShootingEnd& end = {}) {
  // A residual within `good_enough` counts as zero: TOMS 748 stops at an exact zero at once,
  // where it would otherwise take one or two more evaluations to close the bracket to ulps.
  auto g = [&](double p) -> std::optional<double> {
    const std::optional<double> r = g_in(p);
    if (r && std::abs(*r) <= end.good_enough) return 0.0;
    return r;
  };
  double hi = lo, g_hi = g_lo;
  const bool bounded = std::isfinite(cap);
  if (bounded && end.g_cap && *end.g_cap >= 0.0) {  // the whole bracket is known
    hi = cap;
    g_hi = std::abs(*end.g_cap) <= end.good_enough ? 0.0 : *end.g_cap;
  }
  double step = initial_step > 0.0 ? initial_step : 0.05 * std::max(lo, 1e-3);
  for (int k = 1; k <= 60 && g_hi < 0.0; ++k) {
    lo = hi;
    g_lo = g_hi;
    hi = bounded ? lo + 0.5 * (cap - lo) : lo + step;
    step *= 2.0;
    g_hi = residual_or_beyond(g, hi);
  }
  // Halving towards a cap never evaluates the cap itself, where the root lies when it is the
  // bracket's end (e.g. a Part II of zero length at the force where it appears).  A cap outside
  // the domain (a locking stretch) is no root.
  if (g_hi < 0.0 && bounded) {
    if (const std::optional<double> g_cap = g(cap); g_cap && *g_cap >= 0.0) {
      lo = hi;
      g_lo = g_hi;
      hi = cap;
      g_hi = *g_cap;
    }
  }
  if (g_hi < 0.0) return std::nullopt;
  if (g_hi == 0.0) return hi;
  std::uintmax_t iterations = static_cast<std::uintmax_t>(max_iterations);
  const auto tolerance = [](double x0, double x1) {
    return std::abs(x1 - x0) <= 4.0 * std::numeric_limits<double>::epsilon() * std::abs(x1);
  };
  const auto bracket =
      boost::math::tools::toms748_solve([&](double p) { return residual_or_beyond(g, p); },
                                        lo,
                                        hi,
                                        g_lo,
                                        g_hi,
                                        tolerance,
                                        iterations);
  if (iterations >= static_cast<std::uintmax_t>(max_iterations)) return std::nullopt;
  return 0.5 * (bracket.first + bracket.second);
}

// The root of g polished from a coarse one: secant steps on g from p0, the first with the slope
// of a coarse model of g (a step of 1e-4 of `scale` beside p0), within (lo, hi).  The root is
// the first parameter with |g| <= good_enough.  Empty when a value is missing or beyond
// give_up (a stand-in, or too far from the root for secant steps), a step leaves (lo, hi) or
// max_steps do not converge: the caller's full search runs then.
template <class Fine, class Coarse>
std::optional<double> polish_coarse_root(Fine&& fine, Coarse&& coarse, double p0, double scale,
                                         double lo, double hi, double good_enough, double give_up,
                                         int max_steps) {
  const std::optional<double> g_start = fine(p0);
  if (!g_start || !(std::abs(*g_start) <= give_up)) return std::nullopt;
  double g0 = *g_start;
  if (std::abs(g0) <= good_enough) return p0;
  const double h = 1e-4 * scale;
  const std::optional<double> g_side = coarse(p0 + h), g_here = coarse(p0);
  if (!g_side || !g_here) return std::nullopt;
  double slope = (*g_side - *g_here) / h;
  for (int k = 0; k < max_steps; ++k) {
    const double p1 = p0 - g0 / slope;
    if (!std::isfinite(p1) || !(p1 > lo) || !(p1 < hi)) return std::nullopt;
    const std::optional<double> g1 = fine(p1);
    if (!g1 || !(std::abs(*g1) <= give_up)) return std::nullopt;
    if (std::abs(*g1) <= good_enough) return p1;
    slope = (*g1 - g0) / (p1 - p0);
    p0 = p1;
    g0 = *g1;
  }
  return std::nullopt;
}

}  // namespace puncture::detail
