#pragma once
// What the free membrane's ODE state holds (free_membrane_ode.hpp): the stretches themselves, or
// the strains and two running integrals.  The balance equations do not depend on the choice;
// each layout also fixes how lambda1 cos(phi) - lambda2 is formed, and with it the rounding of
// the solutions it has produced.
#include <array>
#include <cmath>

namespace puncture::detail {

// (t, lambda1, lambda2, h), t = R s1 cos(phi): Part I of the indentation, integrated so since it
// was written; S and lambda1 cos(phi) - lambda2 are formed as then, so that its results stay the
// same to the last bit.
struct Stretches {
  using State = std::array<double, 4>;
  static constexpr bool integrals = false;

  static double lambda1(const State& x) { return x[1]; }
  static double lambda2(const State& x) { return x[2]; }
  // R s1 = sqrt(t^2 + g^2), g = R s1 sin(phi).
  static double resultant(double t, double g) { return std::sqrt(t * t + g * g); }
  // lambda1 cos(phi) - lambda2 (= R dlambda2/dR).
  static double hoop_gap(const State& x, double /*t*/, double /*g*/, double /*s_total*/,
                         double cos_phi) {
    return x[1] * cos_phi - x[2];
  }
};

// (t, lambda1 - 1, lambda2 - 1, h, v, e): the inflated membrane, whose strains can be 1e-5 at
// small pressures.  Integrating the strains makes the integrator's relative tolerance relative to
// them, and lambda1 cos(phi) - lambda2 = (lambda1 - 1) cos(phi) - (lambda2 - 1) - (1 - cos(phi))
// is formed from the strains, with 1 - cos(phi) = g^2 / (S (S + t)) free of cancellation where
// phi is small (t > 0).  v = sum of pi r^2 dh is the volume inside the membrane between the
// planes through its inner end and through R (/ A^3), e = sum of W R dR the stored energy
// (/ (2 pi G H A^2)).
struct StrainsAndIntegrals {
  using State = std::array<double, 6>;
  static constexpr bool integrals = true;

  static double lambda1(const State& x) { return 1.0 + x[1]; }
  static double lambda2(const State& x) { return 1.0 + x[2]; }
  static double resultant(double t, double g) { return std::hypot(t, g); }
  static double hoop_gap(const State& x, double t, double g, double s_total, double cos_phi) {
    const double one_minus_cos = t > 0.0 ? g * g / (s_total * (s_total + t)) : 1.0 - cos_phi;
    return x[1] * cos_phi - x[2] - one_minus_cos;
  }
};

}  // namespace puncture::detail
