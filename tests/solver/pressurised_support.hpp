#pragma once
// Shared by the tests of indentation under a gas pressure (pressurised_test.cpp,
// pressurised_friction_test.cpp): the paper's inflated membrane, and the quadratures of the
// constant-pressure energy balance (the work of F and Pi = U - p V from a state's fields).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solver_test_support.hpp"

namespace puncture::test {

inline constexpr double kPressureMpa =
    3e-4;  // the paper's membrane: pole stretch 1.118, dome 10.4 mm

inline Problem pressurised(double pressure_mpa = kPressureMpa, double friction = 0.0,
                           Indenter indenter = SphereTipped{2.0}) {
  Problem p = paper_problem(Gent{125.0}, friction);
  p.indenter = indenter;
  p.preload.pressure_mpa = pressure_mpa;
  return p;
}

inline Problem flat(double pressure_mpa = kPressureMpa) {
  return pressurised(pressure_mpa, 0.0, FlatPunch{2.0});
}

inline SolverOptions sampled(int points) {
  SolverOptions o;
  o.field_points = points;
  return o;
}

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
inline Quadrature potential(const Problem& p, const Equilibrium& e) {
  const auto& m = e.fields;
  std::vector<double> r_ref, w_r, r_squared, height;
  const double clamp_z = m.deflection_mm.back();
  for (std::size_t i = 0; i < m.size(); ++i) {
    r_ref.push_back(m.reference_radius_mm[i]);
    w_r.push_back(energy_density_mpa(p, m.radial_stretch[i], m.hoop_stretch[i]) * r_ref.back());
    r_squared.push_back(m.radius_mm[i] * m.radius_mm[i]);
    height.push_back(clamp_z - m.deflection_mm[i]);
  }
  const Quadrature u = integrate(r_ref, w_r), v = integrate(r_squared, height);
  const double scale_u = 2.0 * kPi * p.geometry.thickness_mm, pv = kPi * p.preload.pressure_mpa;
  return {scale_u * u.value - pv * v.value, scale_u * u.error + pv * v.error};
}

// The indenter's work from the inflated dome to `depth` [mJ]: Simpson's rule on a 401-point
// curve, its error bounded by |S_h - S_2h| (Simpson on every other point).
inline Quadrature simpson_work(const Problem& p, double depth) {
  CurveOptions c;
  c.points = 401;
  c.max_depth_mm = depth;
  const auto curve = loading_curve(p, c);
  EXPECT_TRUE(curve.ok()) << curve.message;
  if (!curve.ok()) return {0.0, 0.0};
  const std::size_t n = curve.points.size() - 1;
  const double h = depth / static_cast<double>(n);
  double fine = 0.0, coarse = 0.0;
  for (std::size_t k = 0; k <= n; ++k) {
    const bool end = k == 0 || k == n;
    fine += (end ? 1.0 : (k % 2 ? 4.0 : 2.0)) * curve.points[k].force_n;
    if (k % 2 == 0) coarse += (end ? 1.0 : ((k / 2) % 2 ? 4.0 : 2.0)) * curve.points[k].force_n;
  }
  fine *= h / 3.0;
  coarse *= 2.0 * h / 3.0;
  return {fine, std::abs(fine - coarse)};
}

}  // namespace puncture::test
