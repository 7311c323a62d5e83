#pragma once
// The Föppl (moderate rotation, small strain) limit of the clamped membrane pushed by a rigid
// flat disc, solved independently of the library's large-strain shooting: it shares nothing with
// it but Boost.Odeint and Boost.Math.
//
// Linear isotropic membrane, Young's modulus E, Poisson's ratio nu, thickness h, clamp radius A,
// disc radius a, force F.  For a <= r <= A (free part), with u the radial displacement, w the
// deflection and N_r, N_t the stress resultants:
//   eps_r = u' + w'^2 / 2,  eps_t = u / r,  N_r = K (eps_r + nu eps_t),  N_t = K (eps_t + nu
//   eps_r), K = E h / (1 - nu^2),   d(r N_r)/dr = N_t,   2 pi r N_r w' = F (vertical balance).
// Clamp: u(A) = 0.  At the disc's edge either the membrane is held (u(a) = 0) or it slides freely
// over the disc, whose part is then homogeneous: u = c r, N_r = N_t = K (1 + nu) c, so
// N_r(a) = K (1 + nu) u(a) / a.  Everything scales: u ~ F^(2/3), w ~ F^(1/3), so
//   F = C(a/A) E h delta^3 / A^2
// with delta the depth, and C found once per a/A by shooting on N_r(a).
#include <array>
#include <boost/math/tools/roots.hpp>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

namespace puncture::verification {

enum class DiscEdge { Held, Sliding };

// C(a/A) for Poisson's ratio nu (1/2 for an incompressible rubber).
inline double foppl_coefficient(double a_over_A, DiscEdge edge, double nu = 0.5) {
  namespace odeint = boost::numeric::odeint;
  // Units: A = 1, E h = 1, F = 2 pi (so r N_r w' = 1).
  const double a = a_over_A, k = 1.0 / (1.0 - nu * nu);
  using State = std::array<double, 3>;  // u, r N_r, depth integral
  auto rhs = [&](const State& x, State& dx, double r) {
    const double u = x[0], n_r = x[1] / r;
    if (!(n_r > 0.0)) throw std::domain_error("radial tension lost");
    const double slope = 1.0 / (r * n_r);  // |w'|
    const double eps_t = u / r;
    const double eps_r = n_r / k - nu * eps_t;
    dx[0] = eps_r - 0.5 * slope * slope;
    dx[1] = k * (eps_t + nu * eps_r);  // d(r N_r)/dr = N_t
    dx[2] = slope;
  };
  // Clamp residual u(1) for a trial N_r(a).
  auto shoot = [&](double n_a, double* depth) {
    const double u_a = edge == DiscEdge::Held ? 0.0 : n_a * a / (k * (1.0 + nu));
    State x{u_a, a * n_a, 0.0};
    try {
      odeint::integrate_adaptive(
          odeint::make_controlled(1e-14, 1e-12, odeint::runge_kutta_fehlberg78<State>()),
          rhs,
          x,
          a,
          1.0,
          1e-4);
    } catch (const std::domain_error&) {
      // Too little tension at the disc: the hoop strain turns compressive and the radial tension
      // is used up before the clamp, the far side of the root (u(A) < 0).
      return -1.0;
    }
    if (depth) *depth = x[2];
    return x[0];
  };
  // u(1) grows with N_r(a); bracket geometrically, then TOMS 748.
  double lo = 1.0, hi = 1.0;
  if (shoot(1.0, nullptr) < 0.0) {
    while (shoot(hi, nullptr) < 0.0) hi *= 2.0;
    lo = 0.5 * hi;
  } else {
    while (shoot(lo, nullptr) > 0.0) lo *= 0.5;
    hi = 2.0 * lo;
  }
  std::uintmax_t iterations = 200;
  const auto root = boost::math::tools::toms748_solve([&](double n) { return shoot(n, nullptr); },
                                                      lo,
                                                      hi,
                                                      boost::math::tools::eps_tolerance<double>(50),
                                                      iterations);
  double depth = 0.0;
  shoot(0.5 * (root.first + root.second), &depth);
  // F = 2 pi in these units: C = F / (E h delta^3 / A^2).
  return 2.0 * std::numbers::pi / (depth * depth * depth);
}

}  // namespace puncture::verification
