#pragma once
// The potential of an indented membrane from its fields alone, for the energy balances of the
// physics tests: Pi = U - p V at constant gas pressure p (U alone without pressure).
#include <cmath>
#include <vector>

#include "solver_test_support.hpp"

namespace puncture::test {

// A quadrature along the fields with its error estimate: the trapezoid rule on every sample and
// on every other one, Richardson's extrapolation of the two, and (T_h - T_2h) / 3.
struct Quadrature {
  double value;
  double error;
};
inline Quadrature integrate(const std::vector<double>& x, const std::vector<double>& y) {
  const double fine = trapezoid(x, y, 1), coarse = trapezoid(x, y, 2);
  return {fine + (fine - coarse) / 3.0, std::abs(fine - coarse) / 3.0};
}

// Pi = U - p V of a state [mJ] from its fields alone: U = 2 pi H int W R dR over every part, V =
// pi int y d(r^2) the volume between the membrane and the clamp plane (y the height above it:
// the clamp's deflection minus the point's; the probe's side, where r is constant, adds none).
// Each part is integrated on its own samples: the stretches may jump where two parts meet at one
// reference radius (a held membrane's, at the indenter's edge), which a Richardson step across
// them would smear.
inline Quadrature potential(const Problem& p, const Equilibrium& e) {
  const auto& m = e.fields;
  const double clamp_z = m.deflection_mm.back();
  Quadrature u{0.0, 0.0}, v{0.0, 0.0};
  for (std::size_t first = 0; first < m.size();) {
    std::size_t last = first;
    while (last + 1 < m.size() && m.part[last + 1] == m.part[first]) ++last;
    // Parts that meet without a shared sample: the interval between them goes with this part.
    const bool shared =
        first == 0 || m.reference_radius_mm[first] == m.reference_radius_mm[first - 1];
    std::vector<double> r_ref, w_r, r_squared, height;
    for (std::size_t i = shared ? first : first - 1; i <= last; ++i) {
      r_ref.push_back(m.reference_radius_mm[i]);
      w_r.push_back(energy_density_mpa(p, m.radial_stretch[i], m.hoop_stretch[i]) * r_ref.back());
      r_squared.push_back(m.radius_mm[i] * m.radius_mm[i]);
      height.push_back(clamp_z - m.deflection_mm[i]);
    }
    const Quadrature du = integrate(r_ref, w_r), dv = integrate(r_squared, height);
    u = {u.value + du.value, u.error + du.error};
    v = {v.value + dv.value, v.error + dv.error};
    first = last + 1;
  }
  const double scale_u = 2.0 * kPi * p.geometry.thickness_mm, pv = kPi * p.preload.pressure_mpa;
  return {scale_u * u.value - pv * v.value, scale_u * u.error + pv * v.error};
}

}  // namespace puncture::test
