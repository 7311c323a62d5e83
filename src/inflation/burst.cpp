// The burst: the first pole stretch at which the largest I1 in the membrane reaches the
// critical I1.  The largest I1 is usually at the pole, but not always (a Mooney-Rivlin membrane
// inflated far is stretched hardest at the clamp), so it is searched for, not assumed.
#include <fmt/format.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>

#include "inflation/scaled_inflation.hpp"
#include "puncture/kinematics.hpp"

namespace puncture {

InflationBurst inflation_burst(const InflationProblem& problem, const SolverOptions& options) {
  validate(problem);
  const double critical = problem.critical_i1;
  const double flat = problem.prestretch;
  InflationBurst out;
  SolverOptions inner = options;
  inner.record_fields = false;
  // The pole alone reaches the critical I1 here, so the largest I1 does at or before it.
  const double upper = equibiaxial_stretch_for_first_invariant(critical);
  double guess = 0.0;
  std::optional<detail::ScaledInflation> failure;
  auto excess = [&](double l0) -> std::optional<double> {
    auto s = detail::solve_inflation(problem, l0, inner, guess);
    if (!s.ok()) {
      failure = std::move(s);
      return std::nullopt;
    }
    guess = s.pressure;
    return s.max_i1 - critical;
  };
  // A coarse scan for the first crossing (the largest I1 need not grow monotonically).
  constexpr int kScan = 32;
  // The flat state's I1 is 3 without pre-stretch (below the critical I1 by validation).
  double lo = flat, g_lo = (flat == 1.0 ? 3.0 : first_invariant(flat, flat)) - critical;
  double hi = upper, g_hi = 0.0;
  bool bracketed = false;
  for (int k = 1; k <= kScan; ++k) {
    const double l0 = flat + (upper - flat) * k / kScan;
    const auto g = excess(l0);
    if (!g) {
      out.message = fmt::format(
          "the solver failed at pole stretch {:g} before the burst: {}", l0, failure->message);
      out.state = detail::to_physical(problem, *failure);
      return out;
    }
    if (*g >= 0.0) {
      hi = l0;
      g_hi = *g;
      bracketed = true;
      break;
    }
    lo = l0;
    g_lo = *g;
  }
  if (!bracketed) {  // rounding at the pole: I1(upper) = critical to the last bits
    hi = upper;
    g_hi = 0.0;
  }
  double at = hi;
  if (g_hi > 0.0) {
    std::uintmax_t iterations = 100;
    bool failed = false;
    const auto bracket = boost::math::tools::toms748_solve(
        [&](double l0) {
          const auto g = excess(l0);
          if (!g) failed = true;
          return g ? *g : 1.0;  // a failure is treated as beyond, and reported below
        },
        lo,
        hi,
        g_lo,
        g_hi,
        boost::math::tools::eps_tolerance<double>(45),
        iterations);
    if (failed) {
      out.message = "the solver failed while locating the burst: " + failure->message;
      out.state = detail::to_physical(problem, *failure);
      return out;
    }
    at = 0.5 * (bracket.first + bracket.second);
  }
  out.state = detail::to_physical(problem, detail::solve_inflation(problem, at, options, guess));
  out.status = out.state.status;
  if (!out.ok()) out.message = "the burst state could not be solved: " + out.state.message;
  return out;
}

}  // namespace puncture
