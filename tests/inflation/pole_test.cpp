// The pole of every inflated state is a thin spherical balloon: p = 2 T / rho, with T the true
// line tension H s_eq(l0) / l0 of the equibiaxial pole and rho its radius of curvature, here
// measured on the computed profile (a fit of the height against r^2 near the pole), not taken
// from the solver's own start.
#include <Eigen/Dense>
#include <cmath>

#include "inflation_test_support.hpp"

namespace puncture {
namespace {

using test::laws;
using test::membrane;
using test::solved;

// Radius of curvature at the pole from the profile: z(r) = z0 - r^2 / (2 rho) + c2 r^4 + c3 r^6
// fitted by least squares to the samples with r < 5 % of the clamp radius.
double fitted_pole_radius_mm(const MembraneFields& f, double clamp_radius_mm) {
  std::vector<std::size_t> near;
  for (std::size_t i = 0; i < f.size(); ++i)
    if (f.radius_mm[i] < 0.05 * clamp_radius_mm) near.push_back(i);
  Eigen::MatrixXd m(near.size(), 4);
  Eigen::VectorXd z(near.size());
  for (std::size_t k = 0; k < near.size(); ++k) {
    const double x = std::pow(f.radius_mm[near[k]] / clamp_radius_mm, 2);
    m.row(k) << 1.0, x, x * x, x * x * x;
    z(k) = f.deflection_mm[near[k]] / clamp_radius_mm;
  }
  const Eigen::VectorXd c = m.colPivHouseholderQr().solve(z);
  return -clamp_radius_mm / (2.0 * c(1));
}

TEST(InflationPole, ThinBalloonRelationHoldsAtThePoleForEveryLaw) {
  SolverOptions o;
  o.field_points = 4000;  // ~200 samples within r < 0.05 A for the fit
  for (const auto& [name, law] : laws()) {
    const auto p = membrane(law);
    for (const double l0 : {1.05, 1.5, 2.5, 3.2}) {
      SCOPED_TRACE(name + " at pole stretch " + std::to_string(l0));
      const auto s = solved(p, l0, o);
      const double rho = fitted_pole_radius_mm(s.fields, p.clamp_radius_mm);
      const double tension = p.thickness_mm * equibiaxial_stress(p.material.law, l0) *
                             p.material.shear_modulus_mpa / l0;
      // The fit's truncation (r^8 ~ 4e-11 relative at r = 0.05 A) and the integration
      // tolerance (1e-10) allow a few 1e-10 (measured: at most 2.4e-10); a wrong
      // curvature-pressure relation (a missing factor of lambda or 2) would be off by tens of
      // percent.
      EXPECT_NEAR(s.pressure_mpa * rho / (2.0 * tension), 1.0, 1e-8);
      EXPECT_NEAR(rho / s.pole_curvature_radius_mm, 1.0, 1e-8);
      EXPECT_NEAR(s.pole_tension_n_per_mm / tension, 1.0, 1e-12);
      test::record(fmt::format("{}_balloon_{:g}", name, l0),
                   std::abs(s.pressure_mpa * rho / (2.0 * tension) - 1.0));
    }
  }
}

TEST(InflationPole, FieldsStartEquibiaxialAtThePole) {
  for (const auto& [name, law] : laws()) {
    SCOPED_TRACE(name);
    const auto s = solved(membrane(law), 2.0);
    const auto& f = s.fields;
    ASSERT_GT(f.size(), 2u);
    EXPECT_EQ(f.reference_radius_mm.front(), 0.0);
    EXPECT_EQ(f.radial_stretch.front(), 2.0);
    EXPECT_EQ(f.hoop_stretch.front(), 2.0);
    EXPECT_NEAR(f.deflection_mm.front(), s.pole_height_mm, 1e-12);
    // The first integrated sample is within 1e-3 A of the pole, where lambda1 - lambda2 =
    // (a - b) R^2 ~ 1e-6: equal to the pole's stretch to that order.
    EXPECT_NEAR(f.radial_stretch[1], f.hoop_stretch[1], 1e-5);
    // Clamp: lambda2 = 1, r = A, z = 0.
    EXPECT_NEAR(f.hoop_stretch.back(), 1.0, 1e-8);
    EXPECT_NEAR(f.radius_mm.back(), 25.0, 25.0 * 1e-8);
    EXPECT_NEAR(f.deflection_mm.back(), 0.0, 1e-9);
  }
}

}  // namespace
}  // namespace puncture
