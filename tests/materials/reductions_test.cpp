// Each new law reduces to an older one, in its stresses and through the whole solver (a full
// puncture prediction of the paper's membrane):
//   Ogden, one term alpha = 2                 = neo-Hookean      (rounding: 1e-10)
//   Ogden, alpha = 2, -2, mu = 1 - a, -a      = Mooney-Rivlin(a) (rounding: 1e-10)
//   Gent-Gent without its I2 term (beta = 0)  = Gent             (to the bit)
//   Arruda-Boyce as N -> infinity            -> neo-Hookean, at rate 1/N: W1 / (1/2) =
//       g(x) / g(x0) = 1 + (I1 - 3) / (5 N) + O(N^-2)  (g = L^-1(x) / x = 3 + 9 x^2 / 5 + ...)
#include <gtest/gtest.h>

#include <cmath>

#include "puncture/loading_curve.hpp"
#include "puncture/material.hpp"
#include "puncture/problem.hpp"

namespace puncture {
namespace {

constexpr double kRounding = 1e-10;

void expect_same_stresses(const MaterialLaw& a, const MaterialLaw& b, double tolerance) {
  for (double l1 : {0.9, 1.0, 1.5, 4.0, 8.0})
    for (double l2 : {0.8, 1.0, 2.5, 6.0}) {
      const auto x = membrane_stress(a, l1, l2), y = membrane_stress(b, l1, l2);
      const double scale = 1.0 + std::abs(y.ds1_dl1) + std::abs(y.s1) + std::abs(y.s2);
      EXPECT_NEAR(x.s1, y.s1, tolerance * scale) << l1 << " " << l2;
      EXPECT_NEAR(x.s2, y.s2, tolerance * scale) << l1 << " " << l2;
      EXPECT_NEAR(x.ds1_dl1, y.ds1_dl1, tolerance * scale) << l1 << " " << l2;
      EXPECT_NEAR(x.ds1_dl2, y.ds1_dl2, tolerance * scale) << l1 << " " << l2;
      EXPECT_NEAR(x.ds2_dl2, y.ds2_dl2, tolerance * scale) << l1 << " " << l2;
      EXPECT_NEAR(strain_energy_density(a, l1, l2),
                  strain_energy_density(b, l1, l2),
                  tolerance * (1.0 + std::abs(strain_energy_density(b, l1, l2))));
    }
}

PuncturePrediction puncture_of(const MaterialLaw& law) {
  Problem p;
  p.material.law = law;
  return predict_puncture(p);
}

void expect_same_puncture(const MaterialLaw& a, const MaterialLaw& b, double tolerance) {
  const auto x = puncture_of(a), y = puncture_of(b);
  ASSERT_TRUE(x.ok()) << x.message;
  ASSERT_TRUE(y.ok()) << y.message;
  EXPECT_NEAR(x.force_n, y.force_n, tolerance * y.force_n);
  EXPECT_NEAR(x.depth_mm, y.depth_mm, tolerance * y.depth_mm);
  EXPECT_NEAR(x.part_three_stretch, y.part_three_stretch, tolerance * y.part_three_stretch);
}

TEST(Reductions, OgdenWithOneTermOfExponentTwoIsNeoHookean) {
  const MaterialLaw ogden = Ogden{{1.0}, {2.0}};
  expect_same_stresses(ogden, NeoHookean{}, kRounding);
  expect_same_puncture(ogden, NeoHookean{}, kRounding);
}

// W = (mu1 / 2)(I1 - 3) - (mu2 / 2)(lambda1^-2 + lambda2^-2 + lambda3^-2 - 3), and the last sum is
// I2 (lambda1 lambda2 lambda3 = 1): Mooney-Rivlin with (1 - a) / 2 = mu1 / 2, a / 2 = -mu2 / 2.
TEST(Reductions, OgdenWithExponentsTwoAndMinusTwoIsMooneyRivlin) {
  const double a = 0.2;
  const MaterialLaw ogden = Ogden{{1.0 - a, -a}, {2.0, -2.0}};
  expect_same_stresses(ogden, MooneyRivlin{a}, kRounding);
  expect_same_puncture(ogden, MooneyRivlin{a}, kRounding);
  // The same law from MPa values: G = 0.06 MPa
  const Material m = ogden_material({0.06 * (1.0 - a), -0.06 * a}, {2.0, -2.0});
  EXPECT_NEAR(m.shear_modulus_mpa, 0.06, 1e-17);
  expect_same_stresses(m.law, MooneyRivlin{a}, kRounding);
}

TEST(Reductions, GentGentWithoutItsSecondInvariantTermIsGent) {
  for (double l1 : {0.9, 1.0, 1.5, 4.0, 8.0})
    for (double l2 : {0.8, 1.0, 2.5, 6.0}) {
      const auto g = membrane_stress(GentGent{125.0, 0.0}, l1, l2);
      const auto h = membrane_stress(Gent{125.0}, l1, l2);
      EXPECT_EQ(g.s1, h.s1);
      EXPECT_EQ(g.s2, h.s2);
      EXPECT_EQ(g.ds1_dl1, h.ds1_dl1);
      EXPECT_EQ(g.ds1_dl2, h.ds1_dl2);
      EXPECT_EQ(g.ds2_dl2, h.ds2_dl2);
    }
  const auto x = puncture_of(GentGent{125.0, 0.0}), y = puncture_of(Gent{125.0});
  ASSERT_TRUE(x.ok()) << x.message;
  EXPECT_EQ(x.force_n, y.force_n);
  EXPECT_EQ(x.depth_mm, y.depth_mm);
}

// N (s1_AB / s1_NH - 1) -> (I1 - 3) / 5; the next term is O(I1^2 / N), so at N = 1e6 the
// leading coefficient holds to 1e-4 relative on this grid (I1 <= 75).
TEST(Reductions, ArrudaBoyceTendsToNeoHookeanAtRateOneOverN) {
  const double n = 1e6;
  for (double l1 : {1.5, 4.0, 8.0})
    for (double l2 : {1.0, 2.5}) {
      const double i1 = first_invariant(l1, l2);
      const double ratio =
          membrane_stress(ArrudaBoyce{n}, l1, l2).s1 / membrane_stress(NeoHookean{}, l1, l2).s1;
      EXPECT_NEAR(n * (ratio - 1.0), (i1 - 3.0) / 5.0, 1e-4 * (i1 - 3.0) / 5.0) << l1 << " " << l2;
    }
  // At N = 1e12 the difference, (I1 - 3) / (5 N) < 2e-11, is below the tolerance of a reduction.
  expect_same_stresses(ArrudaBoyce{1e12}, NeoHookean{}, kRounding);
  expect_same_puncture(ArrudaBoyce{1e12}, NeoHookean{}, kRounding);
  // The puncture force converges at the same rate: its error shrinks tenfold from N = 1e4 to 1e5.
  const double neo = puncture_of(NeoHookean{}).force_n;
  const double e4 = puncture_of(ArrudaBoyce{1e4}).force_n / neo - 1.0;
  const double e5 = puncture_of(ArrudaBoyce{1e5}).force_n / neo - 1.0;
  EXPECT_GT(e4, 0.0);  // the chains stiffen the membrane
  EXPECT_NEAR(e4 / e5, 10.0, 0.1);
}

}  // namespace
}  // namespace puncture
