#pragma once
// Shared by the tests of indentation under a gas pressure (pressurised_test.cpp,
// pressurised_friction_test.cpp): the paper's inflated membrane, and the quadratures of the
// constant-pressure energy balance (the work of F; Pi = U - p V from a state's fields is
// membrane_potential.hpp's).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "membrane_potential.hpp"
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
