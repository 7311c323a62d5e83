// The profiles of the filleted flat punch, the cone and the ball (fe/piecewise_profile.hpp,
// fe/probe_profiles.cpp): a sphere with its cylinder built from pieces is the sphere-tipped
// profile; each profile's derivatives, curvature breaks, contact end, gap and closest point.
#include "fe/piecewise_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

#include "fe/probe_profiles.hpp"
#include "fe/sphere_tipped_profile.hpp"

namespace puncture {
namespace piecewise_profile_test {

constexpr double kClamp = 25.0;  // lengths over the paper's 25 mm clamp radius
constexpr double kHalfPi = 0.5 * std::numbers::pi;

// The hemisphere and its cylinder as two pieces: the same profile as SphereTippedProfile's
// closed forms, to rounding.
TEST(PiecewiseProfile, ReproducesTheSphereTippedProfile) {
  const double a = 2.0 / kClamp;
  const fe::SphereTippedProfile sphere(a);
  const fe::PiecewiseProfile pieces(
      {{1.0 / a, 0.0, kHalfPi * a, MembranePart::Tip}, {0.0, kHalfPi, 0.0, MembranePart::Side}},
      std::numeric_limits<double>::infinity(),
      "");
  ASSERT_EQ(pieces.curvature_breaks().size(), 1u);
  EXPECT_NEAR(pieces.curvature_breaks()[0], sphere.curvature_breaks()[0], 1e-16);
  for (double s : {0.0, 0.1 * a, 0.9 * a, 1.5 * a, 1.6 * a, 3.0 * a}) {
    EXPECT_NEAR(pieces.radius(s), sphere.radius(s), 1e-16) << s;
    EXPECT_NEAR(pieces.height(s), sphere.height(s), 1e-16) << s;
    EXPECT_NEAR(pieces.radius_slope(s), sphere.radius_slope(s), 1e-15) << s;
    EXPECT_NEAR(pieces.height_slope(s), sphere.height_slope(s), 1e-15) << s;
    EXPECT_NEAR(pieces.radius_curvature(s), sphere.radius_curvature(s), 1e-13) << s;
  }
  for (double r : {0.0, 0.5 * a, 1.2 * a})
    for (double y : {-0.1 * a, 0.3 * a, 0.9 * a, 2.0 * a}) {
      EXPECT_NEAR(pieces.gap(r, y), sphere.gap(r, y), 1e-16) << r << " " << y;
      EXPECT_NEAR(pieces.closest_arclength(r, y), sphere.closest_arclength(r, y), 1e-15);
    }
}

struct Shape {
  Indenter indenter;
  std::vector<double> breaks_mm;  // the curvature breaks, by hand
  double contact_end_mm;          // infinity: none
};

// a = 2, rho = 0.5: face to 1.5, fillet of length pi/4, side.  Cone a = 2, alpha = 30 deg,
// RT = 0.5: sphere to polar angle pi/3 (length pi/6), cone from r = 0.5 sin 60 deg to 2 (length
// (2 - 0.25 sqrt 3) / cos 60 deg), kink.  Ball RB = 2 on a rod a = 1: sphere to
// pi - asin(1/2) (length 2 * 5 pi / 6), contact end at the equator (length pi).
const std::vector<Shape> kShapes{
    {FlatPunch{2.0, 0.5},
     {1.5, 1.5 + 0.25 * std::numbers::pi},
     std::numeric_limits<double>::infinity()},
    {Cone{2.0, 30.0, 0.5},
     {std::numbers::pi / 6.0, std::numbers::pi / 6.0 + 2.0 * (2.0 - 0.25 * std::sqrt(3.0))},
     std::numbers::pi / 6.0 + 2.0 * (2.0 - 0.25 * std::sqrt(3.0))},
    {Ball{1.0, 2.0}, {5.0 * std::numbers::pi / 3.0}, std::numbers::pi}};

TEST(ProbeProfiles, BreaksEndsDerivativesGapAndClosestPoint) {
  for (const Shape& shape : kShapes) {
    const auto profile = fe::smooth_profile(shape.indenter, kClamp);
    ASSERT_TRUE(profile);
    const std::vector<double> breaks = profile->curvature_breaks();
    ASSERT_EQ(breaks.size(), shape.breaks_mm.size()) << describe(shape.indenter);
    for (std::size_t k = 0; k < breaks.size(); ++k)
      EXPECT_NEAR(breaks[k] * kClamp, shape.breaks_mm[k], 1e-14) << describe(shape.indenter);
    if (std::isfinite(shape.contact_end_mm))
      EXPECT_NEAR(profile->contact_end() * kClamp, shape.contact_end_mm, 1e-14);
    else
      EXPECT_FALSE(std::isfinite(profile->contact_end()));
    // Between the breaks: unit speed, derivatives against central differences (h = 1e-6 of the
    // clamp radius: truncation ~1e-12, rounding ~1e-10), gap and closest point on the normal.
    std::vector<double> ends{0.0};
    for (double b : breaks) ends.push_back(b);
    ends.push_back(ends.back() + 0.1);
    for (std::size_t k = 0; k + 1 < ends.size(); ++k)
      for (double t : {0.2, 0.5, 0.8}) {
        const double s = ends[k] + t * (ends[k + 1] - ends[k]), h = 1e-6;
        EXPECT_NEAR(std::hypot(profile->radius_slope(s), profile->height_slope(s)), 1.0, 1e-15);
        EXPECT_NEAR((profile->radius(s + h) - profile->radius(s - h)) / (2 * h),
                    profile->radius_slope(s),
                    1e-8);
        EXPECT_NEAR((profile->height(s + h) - profile->height(s - h)) / (2 * h),
                    profile->height_slope(s),
                    1e-8);
        EXPECT_NEAR((profile->radius_slope(s + h) - profile->radius_slope(s - h)) / (2 * h),
                    profile->radius_curvature(s),
                    1e-6 * std::max(1.0, std::abs(profile->radius_curvature(s))));
        const double r = profile->radius(s), y = profile->height(s);
        EXPECT_NEAR(profile->gap(r, y), 0.0, 1e-15);
        EXPECT_NEAR(profile->closest_arclength(r, y), s, 1e-13);
        double nr, ny;
        fe::outward_normal(*profile, s, nr, ny);
        const double d = 1e-3;  // well inside the smallest radius of curvature (0.02)
        EXPECT_NEAR(profile->gap(r + d * nr, y + d * ny), d, 1e-15);
        EXPECT_NEAR(profile->gap(r - d * nr, y - d * ny), -d, 1e-15);
      }
    // Continuous across the breaks (the cone's kink too: only its slope jumps).
    for (double b : breaks) {
      EXPECT_NEAR(profile->radius(b * (1 - 1e-12)), profile->radius(b), 1e-12);
      EXPECT_NEAR(profile->height(b * (1 - 1e-12)), profile->height(b), 1e-12);
    }
  }
}

// The flat face: the radius is the arclength, the height 0, the gap below it the distance.
TEST(ProbeProfiles, FlatFaceIsStraight) {
  const auto profile = fe::smooth_profile(FlatPunch{2.0, 0.5}, kClamp);
  for (double s : {0.0, 0.02, 0.05}) {
    EXPECT_EQ(profile->radius(s), s);
    EXPECT_EQ(profile->height(s), 0.0);
    EXPECT_EQ(profile->radius_curvature(s), 0.0);
    EXPECT_NEAR(profile->gap(s, -0.01), 0.01, 1e-16);
  }
  EXPECT_NEAR(profile->rise_start() * kClamp, 1.5, 1e-14);  // the edge moves from the face's end
  EXPECT_EQ(fe::smooth_profile(Cone{2.0, 30.0, 0.5}, kClamp)->rise_start(), 0.0);
  EXPECT_EQ(fe::smooth_profile(Ball{1.0, 2.0}, kClamp)->rise_start(), 0.0);
  EXPECT_FALSE(fe::smooth_profile(FlatPunch{2.0, 0.0}, kClamp));  // the sharp corner: none
}

}  // namespace piecewise_profile_test
}  // namespace puncture
