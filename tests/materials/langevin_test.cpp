// The Langevin function behind Arruda-Boyce (materials/langevin.hpp): its series and closed form
// meet at b = 1/2, its derivative and the log of sinh(b)/b against differences of the closed
// forms, and the inverse by a round trip and against known values.
#include "puncture/materials/langevin.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace puncture {
namespace {

// Where the closed forms are exact to a few ulp (b >= 1/2) the series must give the same
// values just below the switch: continuity to 1e-15 relative.
TEST(Langevin, SeriesAndClosedFormAgreeAtTheSwitch) {
  const double below = std::nextafter(langevin::kSeriesBelow, 0.0), at = langevin::kSeriesBelow;
  EXPECT_NEAR(langevin::function(below), langevin::function(at), 1e-15);
  EXPECT_NEAR(langevin::derivative(below), langevin::derivative(at), 1e-15);
  EXPECT_NEAR(langevin::log_sinh_over(below), langevin::log_sinh_over(at), 1e-15);
  // At b = 0.5 by the closed forms computed here, independent of the library's branch choice.
  const double b = 0.5;
  EXPECT_NEAR(langevin::function(b), 1.0 / std::tanh(b) - 1.0 / b, 1e-15);
  EXPECT_NEAR(langevin::log_sinh_over(b), std::log(std::sinh(b) / b), 1e-15);
}

// L' and d/db ln(sinh b / b) = L(b) by central differences (h = 1e-5: error ~1e-10).
TEST(Langevin, DerivativesMatchDifferences) {
  const double h = 1e-5;
  for (double b : {0.01, 0.3, 0.49, 0.51, 1.0, 3.0, 20.0}) {
    const double dl = (langevin::function(b + h) - langevin::function(b - h)) / (2.0 * h);
    EXPECT_NEAR(langevin::derivative(b), dl, 1e-9) << b;
    const double dg = (langevin::log_sinh_over(b + h) - langevin::log_sinh_over(b - h)) / (2.0 * h);
    EXPECT_NEAR(langevin::function(b), dg, 1e-9) << b;
  }
}

// The inverse to rounding over the whole range, up to x = 1 - 1e-9 (b ~ 1e9), and against
// values computed with mpmath to 30 digits: L^-1(0.5) = 1.796755984723713041,
// L^-1(0.001) = 0.003000001800001697145 (= 3 x + 9 x^3 / 5 + 297 x^5 / 175 + ...).
TEST(Langevin, InverseRoundTrip) {
  for (double x : {1e-8, 1e-4, 0.01, 0.1, 0.16, 0.17, 0.5, 0.9, 0.99, 0.999999, 1.0 - 1e-9}) {
    const double b = langevin::inverse(x);
    EXPECT_NEAR(langevin::function(b), x, 1e-14 * x) << x;  // the closed form: ~13 ulp
  }
  EXPECT_NEAR(langevin::inverse(0.5), 1.796755984723713041, 4e-15);
  EXPECT_NEAR(langevin::inverse(1e-3), 0.003000001800001697145, 2e-18);
  EXPECT_EQ(langevin::inverse(0.0), 0.0);
  EXPECT_TRUE(std::isnan(langevin::inverse(1.0)));
  EXPECT_TRUE(std::isnan(langevin::inverse(-0.1)));
}

}  // namespace
}  // namespace puncture
