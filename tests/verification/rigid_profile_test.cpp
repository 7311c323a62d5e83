// The smooth probe's profile as the finite elements see it (fe/rigid_profile.hpp): the
// sphere-tipped profile's derivatives, gap and closest point, and the exact gradient and Hessian
// of an element lying on it (the chain rule through rho(s)) against finite differences.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "fe/element_energy.hpp"
#include "fe/sphere_tipped_profile.hpp"
#include "puncture/materials/gent.hpp"

namespace puncture {
namespace rigid_profile_test {

constexpr double kA = 0.08;  // the paper's 2 mm probe over the 25 mm clamp radius

// rho', rho'' and height' against central differences (h = 1e-5 a: truncation ~1e-10, rounding
// ~1e-11 relative), on the hemisphere and on the cylinder.
TEST(SphereTippedProfile, DerivativesMatchFiniteDifferences) {
  const fe::SphereTippedProfile profile(kA);
  const double h = 1e-5 * kA;
  for (double s : {0.1 * kA, 0.7 * kA, 1.5 * kA, 2.0 * kA, 3.0 * kA}) {
    EXPECT_NEAR(
        (profile.radius(s + h) - profile.radius(s - h)) / (2 * h), profile.radius_slope(s), 1e-8);
    EXPECT_NEAR((profile.radius_slope(s + h) - profile.radius_slope(s - h)) / (2 * h),
                profile.radius_curvature(s),
                1e-8 / kA);
    EXPECT_NEAR(
        (profile.height(s + h) - profile.height(s - h)) / (2 * h), profile.height_slope(s), 1e-8);
    // Unit speed: s is the arclength.
    EXPECT_NEAR(std::hypot(profile.radius_slope(s), profile.height_slope(s)), 1.0, 1e-15);
  }
}

// A point of the profile has gap 0 and is its own closest point; a point a distance d along the
// outward normal has gap d.
TEST(SphereTippedProfile, GapAndClosestPointAreConsistent) {
  const fe::SphereTippedProfile profile(kA);
  for (double s : {0.2 * kA, 1.0 * kA, 1.4 * kA, 2.5 * kA}) {
    const double r = profile.radius(s), y = profile.height(s);
    EXPECT_NEAR(profile.gap(r, y), 0.0, 1e-15);
    EXPECT_NEAR(profile.closest_arclength(r, y), s, 1e-14);
    double nr, ny;
    fe::outward_normal(profile, s, nr, ny);
    for (double d : {-0.01 * kA, 0.05 * kA}) {
      EXPECT_NEAR(profile.gap(r + d * nr, y + d * ny), d, 1e-15);
      EXPECT_NEAR(profile.closest_arclength(r + d * nr, y + d * ny), s, 1e-14);
    }
  }
  EXPECT_LT(profile.gap(0.0, 0.5 * kA), 0.0);   // on the axis inside the ball
  EXPECT_GT(profile.gap(0.0, -0.1 * kA), 0.0);  // below the pole
}

// An element on the profile across the pole's neighbourhood: gradient and Hessian of its energy
// (nested forward differentiation through rho(s)) against central differences of the energy and
// of the gradient (h = 1e-6: truncation ~1e-12, rounding ~1e-10 of the entries).
TEST(SphereTippedProfile, ElementOnTheProfileHasExactDerivatives) {
  const fe::SphereTippedProfile profile(kA);
  const MaterialLaw law = Gent{125.0};
  fe::ElementPlace place{2, false, 0.25, 0.25, &profile};
  // Arclengths at the three nodes, then the reference radii of the part's ends.
  std::array<double, fe::kMaxLocal> values{};
  values[fe::local_r(0)] = 0.30 * kA;
  values[fe::local_r(1)] = 0.42 * kA;
  values[fe::local_r(2)] = 0.55 * kA;
  values[fe::local_start_radius(2)] = 0.0;
  values[fe::local_end_radius(2)] = 0.6 * kA;
  const fe::ElementResult exact = fe::element_energy(law, place, values);
  ASSERT_TRUE(exact.admissible);
  EXPECT_DOUBLE_EQ(exact.energy, fe::element_energy_value(law, place, values));
  const double h = 1e-6 * kA;
  for (int k : {fe::local_r(0), fe::local_r(1), fe::local_r(2), fe::local_end_radius(2)}) {
    auto plus = values, minus = values;
    plus[k] += h;
    minus[k] -= h;
    const double gradient =
        (fe::element_energy_value(law, place, plus) - fe::element_energy_value(law, place, minus)) /
        (2 * h);
    EXPECT_NEAR(exact.gradient[k], gradient, 1e-7 * std::abs(gradient) + 1e-12) << "k " << k;
    const fe::Vector column = (fe::element_energy(law, place, plus).gradient -
                               fe::element_energy(law, place, minus).gradient) /
                              (2 * h);
    for (int j : {fe::local_r(0), fe::local_r(1), fe::local_r(2), fe::local_end_radius(2)})
      EXPECT_NEAR(exact.hessian(j, k), column[j], 1e-6 * exact.hessian.cwiseAbs().maxCoeff())
          << "j " << j << " k " << k;
  }
}

}  // namespace rigid_profile_test
}  // namespace puncture
