// Material laws: stresses against finite differences of W, the Jacobian against finite
// differences of the stresses, closed forms, and the inverse lambda1(s1, lambda2).
#include "puncture/material.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "puncture/loading_curve.hpp"
#include "puncture/problem.hpp"

namespace puncture {
namespace {

template <class Law>
double energy(const Law& law, double l1, double l2) {
  return strain_energy_density(law, l1, l2, first_invariant(l1, l2));
}

template <class Law>
class MaterialLawTest : public ::testing::Test {
 public:
  static Law law() {
    if constexpr (std::is_same_v<Law, Gent>) return Gent{125.0};
    if constexpr (std::is_same_v<Law, MooneyRivlin>) return MooneyRivlin{0.2};
    if constexpr (std::is_same_v<Law, Yeoh>) return Yeoh{0.05, 0.001};
    if constexpr (std::is_same_v<Law, Ogden>)  // Ogden's (1972) fit to Treloar, mu_p / G
      return std::get<Ogden>(ogden_material({0.63, 0.0012, -0.01}, {1.3, 5.0, -2.0}).law);
    if constexpr (std::is_same_v<Law, ArrudaBoyce>) return ArrudaBoyce{30.0};
    if constexpr (std::is_same_v<Law, GentGent>) return GentGent{125.0, 0.2};
    return Law{};
  }
};
using Laws = ::testing::Types<Gent, NeoHookean, MooneyRivlin, Yeoh, Ogden, ArrudaBoyce, GentGent>;
TYPED_TEST_SUITE(MaterialLawTest, Laws);

// Central differences with step h have error O(h^2 W''') ~ 1e-10 relative at h = 1e-5, plus
// round-off eps W / h ~ 1e-11: a 1e-7 relative tolerance has two orders of margin.
constexpr double kFdStep = 1e-5;
constexpr double kFdTol = 1e-7;

TYPED_TEST(MaterialLawTest, StressesAreDerivativesOfEnergy) {
  const auto law = TestFixture::law();
  for (double l1 : {0.8, 1.0, 1.3, 2.5, 5.0}) {
    for (double l2 : {0.9, 1.0, 1.7, 3.0}) {
      if (first_invariant(l1, l2) >= law.locking_i1() - 1.0) continue;
      const auto st = membrane_stress(law, l1, l2);
      const double h = kFdStep;
      const double s1 = (energy(law, l1 + h, l2) - energy(law, l1 - h, l2)) / (2 * h);
      const double s2 = (energy(law, l1, l2 + h) - energy(law, l1, l2 - h)) / (2 * h);
      EXPECT_NEAR(st.s1, s1, kFdTol * (1.0 + std::abs(s1))) << l1 << " " << l2;
      EXPECT_NEAR(st.s2, s2, kFdTol * (1.0 + std::abs(s2))) << l1 << " " << l2;
    }
  }
}

TYPED_TEST(MaterialLawTest, JacobianMatchesFiniteDifferences) {
  const auto law = TestFixture::law();
  for (double l1 : {0.8, 1.0, 1.3, 2.5, 5.0}) {
    for (double l2 : {0.9, 1.0, 1.7, 3.0}) {
      if (first_invariant(l1, l2) >= law.locking_i1() - 1.0) continue;
      const auto st = membrane_stress(law, l1, l2);
      const double h = kFdStep;
      const auto p1 = membrane_stress(law, l1 + h, l2), m1 = membrane_stress(law, l1 - h, l2);
      const auto p2 = membrane_stress(law, l1, l2 + h), m2 = membrane_stress(law, l1, l2 - h);
      const double d11 = (p1.s1 - m1.s1) / (2 * h), d12 = (p2.s1 - m2.s1) / (2 * h);
      const double d21 = (p1.s2 - m1.s2) / (2 * h), d22 = (p2.s2 - m2.s2) / (2 * h);
      EXPECT_NEAR(st.ds1_dl1, d11, kFdTol * (1.0 + std::abs(d11)));
      EXPECT_NEAR(st.ds1_dl2, d12, kFdTol * (1.0 + std::abs(d12)));
      EXPECT_NEAR(st.ds1_dl2, d21, kFdTol * (1.0 + std::abs(d21)));  // symmetry of the Hessian
      EXPECT_NEAR(st.ds2_dl2, d22, kFdTol * (1.0 + std::abs(d22)));
    }
  }
}

// The Jacobian straight from the energy: second central differences of W with step h = 1e-4
// have error O(h^2 W'''') ~ 1e-8 relative plus round-off eps W / h^2 ~ 2e-8 W, so 1e-6 relative
// (W, its derivatives O(1) to O(100) on this grid) has an order of margin.
TYPED_TEST(MaterialLawTest, JacobianIsTheEnergysSecondDerivative) {
  const auto law = TestFixture::law();
  const double h = 1e-4;
  for (double l1 : {0.8, 1.0, 1.3, 2.5, 5.0}) {
    for (double l2 : {0.9, 1.0, 1.7, 3.0}) {
      if (first_invariant(l1 + h, l2 + h) >= law.locking_i1() - 1.0) continue;
      const auto st = membrane_stress(law, l1, l2);
      const auto w = [&](double a, double b) { return energy(law, a, b); };
      const double w0 = w(l1, l2);
      const double d11 = (w(l1 + h, l2) - 2.0 * w0 + w(l1 - h, l2)) / (h * h);
      const double d22 = (w(l1, l2 + h) - 2.0 * w0 + w(l1, l2 - h)) / (h * h);
      const double d12 =
          (w(l1 + h, l2 + h) - w(l1 + h, l2 - h) - w(l1 - h, l2 + h) + w(l1 - h, l2 - h)) /
          (4.0 * h * h);
      const double tol = 1e-6 * (1.0 + std::abs(w0));
      EXPECT_NEAR(st.ds1_dl1, d11, tol * (1.0 + std::abs(d11))) << l1 << " " << l2;
      EXPECT_NEAR(st.ds1_dl2, d12, tol * (1.0 + std::abs(d12))) << l1 << " " << l2;
      EXPECT_NEAR(st.ds2_dl2, d22, tol * (1.0 + std::abs(d22))) << l1 << " " << l2;
    }
  }
}

TYPED_TEST(MaterialLawTest, UndeformedStateIsStressFreeWithShearModulusOne) {
  const auto law = TestFixture::law();
  const auto st = membrane_stress(law, 1.0, 1.0);
  EXPECT_NEAR(st.s1, 0.0, 1e-15);
  EXPECT_NEAR(st.s2, 0.0, 1e-15);
  // Small uniaxial strain e: s = E e with E = 3 G (incompressible), G = 1 here.
  const double e = 1e-6;
  EXPECT_NEAR(uniaxial_stress(MaterialLaw{law}, 1.0 + e) / e, 3.0, 1e-5);
}

TYPED_TEST(MaterialLawTest, InverseRoundTrip) {
  const MaterialLaw law{TestFixture::law()};
  for (double l2 : {0.8, 1.0, 2.0, 4.0}) {
    for (double s1 : {0.0, 1e-6, 0.3, 2.0, 10.0, 1e3}) {
      const auto l1 = radial_stretch_for_stress(law, s1, l2);
      ASSERT_TRUE(l1.has_value()) << s1 << " " << l2;
      EXPECT_LT(first_invariant(*l1, l2), locking_first_invariant(law));
      EXPECT_NEAR(membrane_stress(law, *l1, l2).s1, s1, 1e-12 * (1.0 + s1)) << s1 << " " << l2;
    }
  }
  EXPECT_FALSE(radial_stretch_for_stress(law, -0.1, 1.0).has_value());
  EXPECT_FALSE(radial_stretch_for_stress(law, std::nan(""), 1.0).has_value());
}

TEST(GentClosedForm, MatchesPaperEquationsFiveAndSix) {
  const Gent law{125.0};
  for (double l1 : {1.2, 3.0, 7.0}) {
    for (double l2 : {1.0, 2.0}) {
      const double l3 = 1.0 / (l1 * l2);
      const double den = 1.0 - (l1 * l1 + l2 * l2 + l3 * l3 - 3.0) / 125.0;
      const auto st = membrane_stress(law, l1, l2);
      EXPECT_NEAR(st.s1, (l1 * l1 - l3 * l3) / (l1 * den), 1e-12 * st.s1);
      EXPECT_NEAR(st.s2, (l2 * l2 - l3 * l3) / (l2 * den), 1e-12 * std::abs(st.s2) + 1e-15);
    }
  }
}

TEST(GentClosedForm, InverseApproachesTheLockingStretch) {
  const MaterialLaw law{Gent{125.0}};
  const double lock = locking_radial_stretch(Gent{125.0}, 1.0);
  const auto l1 = radial_stretch_for_stress(law, 1e8, 1.0);
  ASSERT_TRUE(l1.has_value());
  EXPECT_LT(*l1, lock);
  EXPECT_GT(*l1, lock * (1.0 - 1e-6));
}

TEST(NeoHookeanClosedForm, EquibiaxialStress) {
  for (double l : {1.1, 2.0, 5.0})
    EXPECT_NEAR(equibiaxial_stress(NeoHookean{}, l), l - std::pow(l, -5.0), 1e-12 * l);
}

// Uniaxial (lambda2 = lambda3 = l^-1/2) and equibiaxial (lambda1 = lambda2 = l) nominal stresses
// of every law in closed form, P = 2 (dW/dI1 + ...) dI/dl written out by hand:
//   neo-Hookean   uni  l - l^-2                 equi  l - l^-5
//   Gent          uni  (l - l^-2) / (1 - (l^2 + 2/l - 3) / J)
//                 equi (l - l^-5) / (1 - (2 l^2 + l^-4 - 3) / J)
//   Mooney-Rivlin uni  (l - l^-2) (1 - alpha + alpha / l)
//                 equi (l - l^-5) (1 - alpha + alpha l^2)
// The library computes them through membrane_stress (general invariant derivatives): agreement to
// rounding, 1e-12 relative.
TEST(ClosedForms, UniaxialAndEquibiaxialStressOfEveryLaw) {
  const double j = 125.0, alpha = 0.2;
  for (double l : {1.05, 1.5, 3.0, 6.0}) {
    const double uni = l - std::pow(l, -2.0), equi = l - std::pow(l, -5.0);
    const double tol = 1e-12 * std::max(1.0, equi);
    EXPECT_NEAR(uniaxial_stress(NeoHookean{}, l), uni, tol);
    EXPECT_NEAR(uniaxial_stress(Gent{j}, l), uni / (1.0 - (l * l + 2.0 / l - 3.0) / j), tol * 10.0);
    EXPECT_NEAR(equibiaxial_stress(Gent{j}, l),
                equi / (1.0 - (2.0 * l * l + std::pow(l, -4.0) - 3.0) / j),
                tol * 10.0);
    EXPECT_NEAR(uniaxial_stress(MooneyRivlin{alpha}, l), uni * (1.0 - alpha + alpha / l), tol);
    EXPECT_NEAR(equibiaxial_stress(MooneyRivlin{alpha}, l),
                equi * (1.0 - alpha + alpha * l * l),
                tol * l * l);
    // Yeoh: s = 2 dW/dI1 (l - l^-2) uniaxially, (l - l^-5) equibiaxially, with
    // dW/dI1 / G = 1/2 + 2 c2 x + 3 c3 x^2 (x = I1 - 3).
    const double c2 = 0.05, c3 = 0.001;
    const auto w1 = [&](double x) { return 0.5 + 2.0 * c2 * x + 3.0 * c3 * x * x; };
    const double x_uni = l * l + 2.0 / l - 3.0, x_equi = 2.0 * l * l + std::pow(l, -4.0) - 3.0;
    EXPECT_NEAR(uniaxial_stress(Yeoh{c2, c3}, l), 2.0 * w1(x_uni) * uni, tol * w1(x_uni));
    EXPECT_NEAR(equibiaxial_stress(Yeoh{c2, c3}, l), 2.0 * w1(x_equi) * equi, tol * w1(x_equi));
  }
}

// Arruda-Boyce (N = 30) against an independent evaluation: mpmath at 40 digits, its own inverse
// Langevin by findroot and the stress as mpmath's derivative of W/G = (3 N / g0)(h(x) - h(x0)).
// Agreement to 1e-13 relative (the library's Newton and series are exact to rounding).
TEST(ArrudaBoyceClosedForm, MatchesAnIndependentHighPrecisionEvaluation) {
  const ArrudaBoyce law{30.0};
  EXPECT_NEAR(strain_energy_density(MaterialLaw{law}, 2.0, 1.5), 1.7007219850528718269, 1e-13);
  EXPECT_NEAR(uniaxial_stress(law, 3.0), 3.033637094252964937, 3e-13);
  EXPECT_NEAR(equibiaxial_stress(law, 4.0), 5.2003796977193492661, 5e-13);
}

TEST(ArrudaBoyceClosedForm, InverseApproachesTheLockingStretch) {
  const MaterialLaw law{ArrudaBoyce{30.0}};
  const double lock = locking_radial_stretch(ArrudaBoyce{30.0}, 1.0);
  EXPECT_NEAR(first_invariant(lock, 1.0), 90.0, 1e-12);
  const auto l1 = radial_stretch_for_stress(law, 1e8, 1.0);
  ASSERT_TRUE(l1.has_value());
  EXPECT_LT(*l1, lock);
  EXPECT_GT(*l1, lock * (1.0 - 1e-6));
}

// Ogden's uniaxial stress in closed form, s = sum_p m_p (l^(alpha_p - 1) - l^(-alpha_p/2 - 1)),
// and Gent-Gent's, s = 2 (l - l^-2)(W1 + W2 / l) with W1 = (1 - beta) / (2 (1 - (I1 - 3) / J)),
// W2 = 3 beta / (2 I2), I1 = l^2 + 2 / l, I2 = 2 l + l^-2: to 1e-12 relative.
TEST(ClosedForms, OgdenAndGentGentUniaxialStress) {
  const Ogden ogden = std::get<Ogden>(ogden_material({0.63, 0.0012, -0.01}, {1.3, 5.0, -2.0}).law);
  const GentGent gg{125.0, 0.2};
  for (double l : {1.05, 1.5, 3.0, 6.0}) {
    double s = 0.0;
    for (std::size_t p = 0; p < 3; ++p)
      s += ogden.mu[p] *
           (std::pow(l, ogden.alpha[p] - 1.0) - std::pow(l, -0.5 * ogden.alpha[p] - 1.0));
    EXPECT_NEAR(uniaxial_stress(ogden, l), s, 1e-12 * std::abs(s)) << l;
    const double i1 = l * l + 2.0 / l, i2 = 2.0 * l + 1.0 / (l * l);
    const double w1 = 0.8 / (2.0 * (1.0 - (i1 - 3.0) / 125.0)), w2 = 0.3 / i2;
    const double sg = 2.0 * (l - 1.0 / (l * l)) * (w1 + w2 / l);
    EXPECT_NEAR(uniaxial_stress(gg, l), sg, 1e-12 * sg) << l;
  }
}

// Yeoh without its higher terms is neo-Hookean: the same stresses to the bit, so the same
// solutions (here the whole puncture prediction).
TEST(Reductions, YeohWithoutHigherTermsIsNeoHookean) {
  for (double l1 : {0.9, 1.0, 1.5, 4.0})
    for (double l2 : {0.8, 1.0, 2.5}) {
      const auto y = membrane_stress(Yeoh{}, l1, l2), n = membrane_stress(NeoHookean{}, l1, l2);
      EXPECT_EQ(y.s1, n.s1);
      EXPECT_EQ(y.s2, n.s2);
      EXPECT_EQ(y.ds1_dl1, n.ds1_dl1);
      EXPECT_EQ(y.ds1_dl2, n.ds1_dl2);
      EXPECT_EQ(y.ds2_dl2, n.ds2_dl2);
    }
  Problem yeoh, neo;
  yeoh.material.law = Yeoh{};
  neo.material.law = NeoHookean{};
  const auto a = predict_puncture(yeoh), b = predict_puncture(neo);
  ASSERT_TRUE(a.ok()) << a.message;
  ASSERT_TRUE(b.ok()) << b.message;
  EXPECT_NEAR(a.force_n, b.force_n, 1e-10 * b.force_n);
  EXPECT_NEAR(a.depth_mm, b.depth_mm, 1e-10 * b.depth_mm);
  EXPECT_NEAR(a.part_three_stretch, b.part_three_stretch, 1e-10 * b.part_three_stretch);
}

TEST(Validation, YeohCoefficientsMustNotBeNegative) {
  Problem p;
  p.material.law = Yeoh{-0.01, 0.001};
  auto errors = validation_errors(p);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].parameter, "material.law.c2");
  p.material.law = Yeoh{0.01, std::nan("")};
  errors = validation_errors(p);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].parameter, "material.law.c3");
  p.material.law = Yeoh{0.0, 0.0};
  EXPECT_TRUE(validation_errors(p).empty());
}

}  // namespace
}  // namespace puncture
