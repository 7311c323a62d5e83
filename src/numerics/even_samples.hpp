#pragma once
// Samples of an integrated part at evenly spaced radii, interpolated between its accepted steps
// (the knots) by septic Hermite polynomials: at each knot the state and its first three
// derivatives (the right-hand side, then central differences of it along the solution).  The
// integration takes the same steps with or without samples, so both give the same state to the
// last bit.  (The samples used to be the steps themselves, capped at the samples' spacing: at 200
// samples that cost 6 times the integration; this costs about 1.5 times.)
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "numerics/integrate.hpp"

namespace puncture::detail {

// The accepted states of one integration, in its direction.
template <class State>
struct Knots {
  std::vector<double> r;
  std::vector<State> y;
  void add(double at, const State& state) {
    // A knot must move on (the interpolation needs strictly monotonic radii).
    if (!r.empty() && at == r.back()) return;
    r.push_back(at);
    y.push_back(state);
  }
};

namespace even_samples_detail {

// The first three derivatives of the solution through (r, x): the right-hand side F, then
// central differences of F along the solution's Taylor polynomial, (F(+) - F(-)) / (2 eps) and
// (F(+) - 2 F + F(-)) / eps^2, second order in eps.  The half-width eps = 1e-3 of the knot's
// shorter step keeps the truncation ~1e-6 and the rounding ~1e-10 of each; they enter the
// interpolant multiplied by h^2 / 2 and h^3 / 6.  False where a point leaves the material's
// domain.
template <class State, class System>
bool derivatives(const System& system, const State& x, double r, double eps, State& d1, State& d2,
                 State& d3) {
  system(x, d1, r);
  if (!all_finite(d1)) return false;
  auto along = [&](double h, bool curved, State& out) {
    State y;
    for (std::size_t j = 0; j < y.size(); ++j)
      y[j] = x[j] + h * d1[j] + (curved ? 0.5 * h * h * d2[j] : 0.0);
    system(y, out, r + h);
    return all_finite(out);
  };
  State plus, minus;
  if (!along(eps, false, plus) || !along(-eps, false, minus)) return false;
  for (std::size_t j = 0; j < x.size(); ++j) d2[j] = (plus[j] - minus[j]) / (2.0 * eps);
  if (!along(eps, true, plus) || !along(-eps, true, minus)) return false;
  for (std::size_t j = 0; j < x.size(); ++j)
    d3[j] = (plus[j] - 2.0 * d1[j] + minus[j]) / (eps * eps);
  return true;
}

// A knot with its derivatives.
template <class State>
struct HermiteKnot {
  double r;
  State y, d1, d2, d3;
};

// The septic Hermite interpolant of one interval at r, component by component: the basis of
// Boost.Math's septic_hermite, written out because that class wants one interpolator per
// component on increasing radii, with the knots copied into each; built so it made a solve at a
// force 7 % slower (0.264 -> 0.282 ms, bench/ratios.py), here the samples walk the knots.
template <class State>
State hermite_at(const HermiteKnot<State>& a, const HermiteKnot<State>& b, double r) {
  const double dx = b.r - a.r, t = (r - a.r) / dx;
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t;
  const double dx2 = 0.5 * dx * dx, dx3 = dx2 * dx / 3.0;
  const double s = t4 * (-35.0 + t * (84.0 + t * (-70.0 + 20.0 * t)));
  const double z0 = s + 1.0, z4 = -s;
  const double z1 = t * (1.0 + t3 * (-20.0 + t * (45.0 + t * (-36.0 + 10.0 * t))));
  const double z2 = t2 * (1.0 + t2 * (-10.0 + t * (20.0 + t * (-15.0 + 4.0 * t))));
  const double z3 = t3 * (1.0 + t * (-4.0 + t * (6.0 + t * (-4.0 + t))));
  const double z5 = t4 * (-15.0 + t * (39.0 + t * (-34.0 + 10.0 * t)));
  const double z6 = t4 * (5.0 + t * (-14.0 + t * (13.0 - 4.0 * t)));
  const double z7 = t4 * (-1.0 + t * (3.0 + t * (-3.0 + t)));
  State out;
  for (std::size_t j = 0; j < out.size(); ++j)
    out[j] = z0 * a.y[j] + z4 * b.y[j] + (z1 * a.d1[j] + z5 * b.d1[j]) * dx +
             (z2 * a.d2[j] + z6 * b.d2[j]) * dx2 + (z3 * a.d3[j] + z7 * b.d3[j]) * dx3;
  return out;
}

}  // namespace even_samples_detail

// The states at `intervals` + 1 evenly spaced radii from the first knot to the last (both
// included, as integrated), each with its radius.
//
// Each step of the integration is halved, the state at its midpoint integrated by one
// Runge-Kutta step from its start: the septic interpolant of RKF78's whole steps is up to ~1e-9
// off (its error goes as the eighth power of the interval), of the halves ~1e-11, as accurate as
// the integration itself (tests/solver/even_samples_test.cpp).  Where the derivatives cannot be
// formed (a state at the edge of the material's domain) the samples are integrated instead, each
// by a step from the knot before it.
template <class State, class System>
std::vector<std::pair<double, State>> even_samples(const System& system, const Knots<State>& k,
                                                   int intervals,
                                                   const IntegrationSettings& settings) {
  using Knot = even_samples_detail::HermiteKnot<State>;
  std::vector<std::pair<double, State>> out;
  const std::size_t m = k.r.size();
  if (m == 0) return out;
  const double r0 = k.r.front(), r1 = k.r.back();
  auto radius = [&](int s) { return s == intervals ? r1 : r0 + (r1 - r0) * s / intervals; };
  if (m == 1 || intervals < 1) {
    out.emplace_back(r0, k.y.front());
    if (m > 1) out.emplace_back(r1, k.y.back());
    return out;
  }
  auto knot = [&](double r, const State& y, double h) -> std::optional<Knot> {
    Knot out{r, y, {}, {}, {}};
    if (!even_samples_detail::derivatives(system, y, r, 1e-3 * std::abs(h), out.d1, out.d2, out.d3))
      return std::nullopt;
    return out;
  };
  // Knots in the integration's direction: the steps' ends and midpoints.
  std::vector<Knot> knots;
  knots.reserve(2 * m);
  for (std::size_t i = 0; i < m; ++i) {
    // Half the step that ends at the knot (the first knot: half the first step).
    const double h = i > 0 ? 0.5 * std::abs(k.r[i] - k.r[i - 1]) : 0.5 * std::abs(k.r[1] - k.r[0]);
    if (i > 0) {
      const double mid = 0.5 * (k.r[i - 1] + k.r[i]);
      const auto y_mid = step_or_advance(system, k.y[i - 1], k.r[i - 1], mid, settings);
      const auto c = y_mid ? knot(mid, *y_mid, h) : std::nullopt;
      if (!c) break;
      knots.push_back(*c);
    }
    const auto b = knot(k.r[i], k.y[i], h);
    if (!b) break;
    knots.push_back(*b);
  }
  const bool smooth = knots.size() == 2 * m - 1;  // every knot's derivatives formed
  out.reserve(static_cast<std::size_t>(intervals) + 1);
  std::size_t at = 0;  // the knot at or before the sample, in the integration's direction
  const double direction = r1 > r0 ? 1.0 : -1.0;
  for (int s = 0; s <= intervals; ++s) {
    const double r = radius(s);
    if (s == 0 || s == intervals) {
      out.emplace_back(r, s == 0 ? k.y.front() : k.y.back());
      continue;
    }
    if (smooth) {
      while (at + 2 < knots.size() && direction * (knots[at + 1].r - r) <= 0.0) ++at;
      out.emplace_back(r, even_samples_detail::hermite_at(knots[at], knots[at + 1], r));
      continue;
    }
    std::size_t j = 0;
    while (j + 1 < m && direction * (k.r[j + 1] - r) <= 0.0) ++j;
    const auto y = step_or_advance(system, k.y[j], k.r[j], r, settings);
    if (!y) break;
    out.emplace_back(r, *y);
  }
  return out;
}

}  // namespace puncture::detail
