#pragma once
// The small-deflection (Föppl) limit of a clamped membrane pushed by a frictionless rigid sphere,
// independent of the large-strain solver: the check of the sphere-tipped probe and of the ball
// (the same sphere up to its equator) at small forces.
#include <array>
#include <boost/math/tools/roots.hpp>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace puncture::detail {

// The Föppl (moderate rotation, small strain) membrane pushed by a frictionless rigid sphere of
// radius a, written here from the Föppl equations alone (as verification/foppl_membrane.hpp does
// for a disc): linear isotropic membrane, E h = 3 (E = 3 G, incompressible: nu = 1/2), clamp at
// r = 1, force F = 2 pi f, so that r N_r w' = f.  u the radial displacement, q = r N_r:
//   eps_t = u / r, eps_r = q / (r K) - nu eps_t, K = E h / (1 - nu^2),
//   u' = eps_r - w'^2 / 2, q' = N_t = K (eps_t + nu eps_r),
// with the slope |w'| = r / a on the sphere and f / q off it; the contact edge is where the
// two agree (q r / a = f).  The pole is equibiaxial, u = e0 r; shooting on e0 for u(1) = 0.
// Returns the depth.
inline double foppl_sphere_depth(double a, double f) {
  namespace odeint = boost::numeric::odeint;
  constexpr double nu = 0.5, eh = 3.0;
  const double k = eh / (1.0 - nu * nu);
  using State = std::array<double, 3>;  // u, q, integral of the free part's slope
  auto rhs = [&](bool on_sphere) {
    return [=](const State& x, State& dx, double r) {
      const double slope = on_sphere ? r / a : f / x[1];
      const double eps_t = x[0] / r, eps_r = x[1] / (r * k) - nu * eps_t;
      dx[0] = eps_r - 0.5 * slope * slope;
      dx[1] = k * (eps_t + nu * eps_r);
      dx[2] = on_sphere ? 0.0 : slope;
    };
  };
  struct Run {
    double u_clamp;
    double depth;
  };
  auto shoot = [&](double e0) -> Run {
    const double r0 = 1e-6 * a;
    State x{e0 * r0, k * (1.0 + nu) * e0 * r0, 0.0};
    // The cap, with dense output to locate the edge.
    auto stepper = odeint::make_dense_output(1e-14, 1e-14, odeint::runge_kutta_dopri5<State>());
    stepper.initialize(x, r0, 1e-3 * a);
    auto edge_gap = [&](double r, const State& y) { return y[1] * r / a - f; };
    while (edge_gap(stepper.current_time(), stepper.current_state()) < 0.0) {
      if (stepper.current_time() >= 1.0 || stepper.current_state()[1] <= 0.0) return {-1.0, 0.0};
      stepper.do_step(rhs(true));
    }
    std::uintmax_t iterations = 200;
    State y;
    const auto bracket = boost::math::tools::toms748_solve(
        [&](double r) {
          stepper.calc_state(r, y);
          return edge_gap(r, y);
        },
        stepper.previous_time(),
        stepper.current_time(),
        boost::math::tools::eps_tolerance<double>(50),
        iterations);
    const double c = 0.5 * (bracket.first + bracket.second);
    stepper.calc_state(c, y);
    if (c >= 1.0) return {-1.0, 0.0};
    try {
      odeint::integrate_adaptive(
          odeint::make_controlled(1e-14, 1e-14, odeint::runge_kutta_fehlberg78<State>()),
          [&](const State& s, State& ds, double r) {
            if (!(s[1] > 0.0)) throw std::domain_error("tension lost");
            rhs(false)(s, ds, r);
          },
          y,
          c,
          1.0,
          1e-4);
    } catch (const std::domain_error&) {
      return {-1.0, 0.0};
    }
    return {y[0], c * c / (2.0 * a) + y[2]};
  };
  // u(1) grows with the pole strain: bracket geometrically from a Föppl-sized guess.
  double lo = 1e-3 * std::cbrt(f * f), hi = lo;
  while (shoot(hi).u_clamp < 0.0) hi *= 2.0;
  while (shoot(lo).u_clamp > 0.0) lo *= 0.5;
  std::uintmax_t iterations = 200;
  const auto root = boost::math::tools::toms748_solve([&](double e) { return shoot(e).u_clamp; },
                                                      lo,
                                                      hi,
                                                      boost::math::tools::eps_tolerance<double>(50),
                                                      iterations);
  return shoot(0.5 * (root.first + root.second)).depth;
}

}  // namespace puncture::detail
