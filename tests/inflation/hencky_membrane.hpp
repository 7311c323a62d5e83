#pragma once
// The Föppl-Hencky membrane: a clamped circular membrane of small strain under uniform pressure,
// solved independently of the library's large-strain inflation solver (it shares nothing with
// it but Boost.Odeint and Boost.Math).
//
// Linear isotropic membrane, Young's modulus E, Poisson's ratio nu, thickness h, radius A,
// pressure q.  With u the radial displacement, w the deflection and N_r, N_t the stress
// resultants (Föppl's moderate rotations: w'^2 kept against u', sin = tan = w'):
//   eps_r = u' + w'^2 / 2,  eps_t = u / r,  N_r = K (eps_r + nu eps_t),  N_t = K (eps_t + nu
//   eps_r), K = E h / (1 - nu^2),   d(r N_r)/dr = N_t (radial balance),   r N_r |w'| = q r^2 / 2
//   (the vertical balance of the disc inside r).
// Clamp: u(A) = 0.  At the centre the state is equibiaxial, N_r = N_t = N0, u = eps0 r.  Every
// quantity scales with a power of q (w ~ q^(1/3), N ~ q^(2/3)), so the centre deflection is
//   w0 = K_H(nu) A (q A / (E h))^(1/3),
// Hencky's constant, found here once per nu by shooting on N0 with u(A) = 0.
#include <array>
#include <boost/math/tools/roots.hpp>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace puncture::verification {

inline double hencky_constant(double nu) {
  namespace odeint = boost::numeric::odeint;
  // Units: A = 1, E h = 1, q = 1, so w0 = K_H.
  const double k = 1.0 / (1.0 - nu * nu);
  using State = std::array<double, 3>;  // u, r N_r, drop of the deflection from the centre
  auto rhs = [&](const State& x, State& dx, double r) {
    const double u = x[0], n_r = x[1] / r;
    if (!(n_r > 0.0)) throw std::domain_error("radial tension lost");
    const double slope = 0.5 * r / n_r;  // |w'| = q r / (2 N_r)
    const double eps_t = u / r;
    const double eps_r = n_r / k - nu * eps_t;
    dx[0] = eps_r - 0.5 * slope * slope;
    dx[1] = k * (eps_t + nu * eps_r);
    dx[2] = slope;
  };
  // Start just off the centre with the equibiaxial state (relative error ~ r0^2).
  const double r0 = 1e-7;
  auto shoot = [&](double n0, double* depth) {
    const double eps0 = n0 / (k * (1.0 + nu));
    State x{eps0 * r0, n0 * r0, 0.25 * r0 * r0 / n0};
    try {
      odeint::integrate_adaptive(
          odeint::make_controlled(1e-15, 1e-13, odeint::runge_kutta_fehlberg78<State>()),
          rhs,
          x,
          r0,
          1.0,
          1e-6);
    } catch (const std::domain_error&) {
      return -1.0;  // too little tension at the centre: the far side of the root
    }
    if (depth) *depth = x[2];
    return x[0];
  };
  // u(A) grows with N0; bracket geometrically, then TOMS 748.
  double lo = 0.1, hi = 0.1;
  if (shoot(lo, nullptr) < 0.0) {
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
  return depth;
}

}  // namespace puncture::verification
