// Fits of every law (uniaxial and equibiaxial): known parameters come back from exact data to
// 1e-8, and from noisy data inside the reported intervals as often as they should; the
// standard errors and correlations of a fit linear in its parameters (Yeoh) are the textbook
// sigma^2 (A^T A)^-1; AIC, AICc and BIC are the formulas computed by hand; Treloar's data give
// Ogden's published three-term fit back and prefer it to neo-Hookean.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "puncture/calibration.hpp"
#include "puncture/material_presets.hpp"
#include "seeded_noise.hpp"

namespace puncture {
namespace {

struct Case {
  FitLaw law;
  Material truth;
  std::vector<double> values;  // the fitted parameters in the order the fit reports them
  UniaxialFitOptions options{};
};

// The laws with parameters in their usual ranges, data to stretch 4 (uniaxial I1 = 18.5).
std::vector<Case> cases() {
  std::vector<Case> c;
  c.push_back({FitLaw::NeoHookean, {0.06, NeoHookean{}}, {0.06}});
  c.push_back({FitLaw::MooneyRivlin, {0.06, MooneyRivlin{0.15}}, {0.06, 0.15}});
  c.push_back({FitLaw::Gent, {0.06, Gent{40.0}}, {0.06, 40.0}});
  // Yeoh C10 = 0.03, C20 = 0.002, C30 = 1e-4 MPa: G = 2 C10.
  c.push_back({FitLaw::Yeoh, {0.06, Yeoh{0.002 / 0.06, 1e-4 / 0.06}}, {0.03, 0.002, 1e-4}});
  c.push_back({FitLaw::ArrudaBoyce, {0.06, ArrudaBoyce{8.0}}, {0.06, 8.0}});
  c.push_back({FitLaw::GentGent, {0.06, GentGent{40.0, 0.1}}, {0.06, 40.0, 0.1}});
  // Ogden with one, two and three terms, from exponents away from the truth.
  Case o1{FitLaw::Ogden, ogden_material({0.1}, {1.6}), {0.1, 1.6}};
  o1.options.ogden_alpha_start = {2.0};
  c.push_back(o1);
  Case o2{FitLaw::Ogden, ogden_material({0.05, -0.01}, {2.5, -1.5}), {0.05, -0.01, 2.5, -1.5}};
  o2.options.ogden_alpha_start = {3.0, -2.0};
  c.push_back(o2);
  Case o3{FitLaw::Ogden,
          ogden_material({0.6, 0.0012, -0.01}, {1.3, 5.0, -2.0}),
          {0.6, 0.0012, -0.01, 1.3, 5.0, -2.0}};
  o3.options.ogden_alpha_start = {1.5, 4.5, -1.5};
  c.push_back(o3);
  return c;
}

std::vector<UniaxialPoint> synthetic(const Material& m, StressTest test, double max_stretch,
                                     int n = 30, double noise_mpa = 0.0, unsigned seed = 1) {
  test::SeededNoise noise(seed, noise_mpa);
  std::vector<UniaxialPoint> points;
  for (int i = 1; i <= n; ++i) {
    const double l = 1.0 + (max_stretch - 1.0) * i / n;
    const double s =
        test == StressTest::Uniaxial ? uniaxial_stress(m.law, l) : equibiaxial_stress(m.law, l);
    points.push_back({l, m.shear_modulus_mpa * s + (noise_mpa > 0.0 ? noise() : 0.0)});
  }
  return points;
}

// Equibiaxial data to stretch 2.2 reach I1 - 3 = 6.7, uniaxial to 4 reach 15.5.
double top_stretch(StressTest test) { return test == StressTest::Uniaxial ? 4.0 : 2.2; }

TEST(LawFit, RecoversExactParametersOfEveryLawInBothTests) {
  for (const auto test : {StressTest::Uniaxial, StressTest::Equibiaxial}) {
    for (auto c : cases()) {
      c.options.test = test;
      const auto data = synthetic(c.truth, test, top_stretch(test));
      const auto fit = fit_uniaxial(data, c.law, c.options);
      const auto label = to_string(c.law) + " " + to_string(test);
      ASSERT_TRUE(fit.ok()) << label << ": " << fit.message;
      EXPECT_EQ(fit.test, test);
      ASSERT_EQ(fit.parameters.size(), c.values.size()) << label;
      for (std::size_t i = 0; i < c.values.size(); ++i) {
        ASSERT_TRUE(fit.parameters[i].value) << label << " " << fit.parameters[i].name;
        EXPECT_NEAR(*fit.parameters[i].value, c.values[i], 1e-8 * std::abs(c.values[i]))
            << label << " " << fit.parameters[i].name;
      }
      ASSERT_TRUE(fit.material) << label;
      EXPECT_NEAR(fit.material->shear_modulus_mpa,
                  c.truth.shear_modulus_mpa,
                  1e-8 * c.truth.shear_modulus_mpa)
          << label;
      EXPECT_LT(fit.rms_residual_mpa, 1e-10) << label;
    }
  }
}

TEST(LawFit, NoisyDataAreRecoveredInsideTheReportedIntervals) {
  // 30 points with 0.002 MPa noise, 40 seeds.  Some seeds put a weak parameter on its bound
  // (OnBound: Ogden's alpha_2 = -1, Gent-Gent's beta = 0): there the others' errors are
  // conditional on it and it has none, so the intervals are counted over the interior fits.
  // Each parameter's truth must lie within two standard errors in at least 80 % of them (95 %
  // expected: with 19 to 40 fits, below 80 % has probability ~1 % for honest errors), and at
  // least a quarter of the seeds must give an interior fit (the fewest: Ogden's two terms in
  // uniaxial tension, whose alpha_2 = -1.5 is near its edge -1: 19 of 40).
  const int seeds = 40;
  for (const auto test : {StressTest::Uniaxial, StressTest::Equibiaxial}) {
    for (auto c : cases()) {
      if (c.law == FitLaw::Ogden && c.values.size() == 6) continue;  // Ogden-3: Treloar's test
      c.options.test = test;
      int interior = 0;
      std::vector<int> inside(c.values.size(), 0);
      for (int seed = 1; seed <= seeds; ++seed) {
        const auto data =
            synthetic(c.truth, test, top_stretch(test), 30, 0.002, static_cast<unsigned>(seed));
        const auto fit = fit_uniaxial(data, c.law, c.options);
        const auto label =
            to_string(c.law) + " " + to_string(test) + " seed " + std::to_string(seed);
        ASSERT_TRUE(fit.ok() || fit.status == Status::OnBound) << label << ": " << fit.message;
        if (!fit.ok()) continue;
        ++interior;
        for (std::size_t i = 0; i < c.values.size(); ++i) {
          const auto& p = fit.parameters[i];
          ASSERT_TRUE(p.value && p.standard_error) << label << " " << p.name;
          inside[i] += std::abs(*p.value - c.values[i]) < 2.0 * *p.standard_error;
        }
      }
      const auto label = to_string(c.law) + " " + to_string(test);
      EXPECT_GE(interior, seeds / 4) << label;
      for (std::size_t i = 0; i < c.values.size(); ++i)
        EXPECT_GE(inside[i], 0.8 * interior) << label << " parameter " << i;
    }
  }
}

TEST(LawFit, YeohErrorsAndCorrelationAreThoseOfLinearLeastSquares) {
  // Yeoh's stress is linear in (C10, C20, C30): P = A c with rows 2 g (1, 2 x, 3 x^2), g =
  // lambda - lambda^-2, x = I1 - 3.  Its covariance is exactly s^2 (A^T A)^-1, s^2 = RSS/(n-3).
  const Material truth{0.06, Yeoh{0.002 / 0.06, 1e-4 / 0.06}};
  const auto data = synthetic(truth, StressTest::Uniaxial, 4.0, 30, 0.002, 7);
  const auto fit = fit_uniaxial(data, FitLaw::Yeoh);
  ASSERT_TRUE(fit.ok()) << fit.message;
  const auto n = static_cast<Eigen::Index>(data.size());
  Eigen::MatrixXd a(n, 3);
  Eigen::VectorXd p(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double l = data[static_cast<std::size_t>(i)].stretch;
    const double g = l - 1.0 / (l * l), x = l * l + 2.0 / l - 3.0;
    a.row(i) << 2.0 * g, 4.0 * g * x, 6.0 * g * x * x;
    p[i] = data[static_cast<std::size_t>(i)].nominal_stress_mpa;
  }
  const Eigen::Vector3d c = a.colPivHouseholderQr().solve(p);
  const double s2 = (a * c - p).squaredNorm() / static_cast<double>(n - 3);
  const Eigen::Matrix3d cov = s2 * (a.transpose() * a).inverse();
  ASSERT_EQ(fit.correlation.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(*fit.parameters[static_cast<std::size_t>(i)].value, c[i], 1e-7 * std::abs(c[i]));
    EXPECT_NEAR(*fit.parameters[static_cast<std::size_t>(i)].standard_error,
                std::sqrt(cov(i, i)),
                1e-6 * std::sqrt(cov(i, i)));
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(fit.correlation[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)],
                  cov(i, j) / std::sqrt(cov(i, i) * cov(j, j)),
                  1e-6);
  }
}

TEST(LawFit, GentCorrelationIsThatOfJLimNotOfItsInverse) {
  // The fit runs in c = 1/J_lim; J_lim falls as c rises, so corr(G, J_lim) = -corr(G, c).  The
  // closed-form and the law-model fit (equal in the uniaxial test) must agree on it.
  const auto data = synthetic({0.06, Gent{40.0}}, StressTest::Uniaxial, 4.0, 30, 0.002, 2);
  const auto fit = fit_uniaxial(data, FitLaw::Gent);
  ASSERT_TRUE(fit.ok());
  ASSERT_EQ(fit.correlation.size(), 2u);
  // Stiffer data raise G's estimate and c's together at the top: corr(G, c) < 0 (the model
  // G g / (1 - c k) trades one for the other), so corr(G, J_lim) > 0.
  EXPECT_GT(fit.correlation[0][1], 0.0);
  EXPECT_EQ(fit.correlation[0][1], fit.correlation[1][0]);
  EXPECT_EQ(fit.correlation[0][0], 1.0);
}

TEST(LawFit, InformationCriteriaAreTheFormulas) {
  // n = 10, a two-parameter law (k = 3 with the variance), RSS = 0.5 MPa^2, by hand:
  // n ln(RSS/n) = 10 ln 0.05 = -29.957322735539910; AIC = that + 6; AICc = AIC + 2*3*4/6;
  // BIC = that + 3 ln 10 = -29.957322735539910 + 6.907755278982137.
  const auto c = information_criteria(10, 2, 0.5);
  EXPECT_EQ(c.points, 10);
  EXPECT_EQ(c.parameters, 3);
  EXPECT_NEAR(c.aic, -23.957322735539910, 1e-12);
  ASSERT_TRUE(c.aicc);
  EXPECT_NEAR(*c.aicc, -19.957322735539910, 1e-12);
  EXPECT_NEAR(c.bic, -23.049567456557773, 1e-12);
  EXPECT_FALSE(information_criteria(4, 2, 0.5).aicc);  // n - k - 1 = 0
  EXPECT_THROW(information_criteria(10, 2, 0.0), std::invalid_argument);
  EXPECT_THROW(information_criteria(0, 2, 1.0), std::invalid_argument);

  // A fit's own: from its RSS = n rms^2 and its parameter count.
  const auto data = synthetic({0.06, Gent{40.0}}, StressTest::Uniaxial, 4.0, 30, 0.002, 4);
  const auto fit = fit_uniaxial(data, FitLaw::Gent);
  ASSERT_TRUE(fit.information);
  const double rss = 30.0 * fit.rms_residual_mpa * fit.rms_residual_mpa;
  EXPECT_NEAR(fit.information->rss_mpa2, rss, 1e-12 * rss);
  EXPECT_NEAR(fit.information->aic, 30.0 * std::log(rss / 30.0) + 6.0, 1e-9);
  EXPECT_NEAR(fit.information->bic, 30.0 * std::log(rss / 30.0) + 3.0 * std::log(30.0), 1e-9);
}

std::vector<UniaxialPoint> treloar() {
  std::ifstream in(PUNCTURE_TEST_DATA_DIR "/treloar_1944_uniaxial.csv");
  std::stringstream text;
  text << in.rdbuf();
  return uniaxial_points_from_table(parse_numeric_csv(text.str(), "treloar_1944_uniaxial.csv"),
                                    std::nullopt);
}

TEST(LawFit, TreloarsDataAndOgdensFit) {
  // Ogden (1972) fitted Treloar's data with mu = 6.3, 0.012, -0.1 kgf/cm^2 (0.618, 0.00118,
  // -0.00981 MPa) and alpha = 1.3, 5.0, -2.0 (docs/materials.md).  This tabulation lies below
  // his fit at small stretch (0.286 MPa at stretch 1.43 where his gives 0.355: 24 %) and rises
  // faster beyond stretch 7 (0.7 MPa above it at 7.51, where a least-squares fit runs a term to
  // alpha ~ 16 with mu ~ 1e-13 MPa), so his parameters cannot be expected back; the fit uses
  // the 16 points to stretch 7.  What must hold: the least-squares fit from his exponents is at
  // least as good as his on these data, keeps his structure (one exponent near 1.3, one near 5,
  // the same signs) and describes the data far better than neo-Hookean.  Measured: alpha =
  // 1.72, 5.81, -2.09; mu = 0.376, 0.000203, 0 MPa (OnBound: mu_3 = 0); RSS 0.0085 against his
  // 0.069 MPa^2.
  std::vector<UniaxialPoint> to_seven;
  for (const auto& p : treloar())
    if (p.stretch <= 7.0) to_seven.push_back(p);
  ASSERT_EQ(to_seven.size(), 16u);
  const auto ogden = fit_uniaxial(to_seven, FitLaw::Ogden);
  ASSERT_TRUE(ogden.ok() || ogden.status == Status::OnBound) << ogden.message;
  ASSERT_TRUE(ogden.information);
  const auto& published = material_preset("ogden-1972-treloar").material;
  double rss_published = 0.0;
  for (const auto& point : to_seven) {
    const double p = published.shear_modulus_mpa * uniaxial_stress(published.law, point.stretch);
    rss_published += (p - point.nominal_stress_mpa) * (p - point.nominal_stress_mpa);
  }
  EXPECT_LE(ogden.information->rss_mpa2, rss_published);
  EXPECT_NEAR(*ogden.parameters[3].value, 1.3, 0.5);    // alpha_1
  EXPECT_NEAR(*ogden.parameters[4].value, 5.0, 1.0);    // alpha_2
  EXPECT_LT(*ogden.parameters[5].value, -1.0 + 1e-12);  // alpha_3 < 0, as Ogden's
  const auto neo = fit_uniaxial(to_seven, FitLaw::NeoHookean);
  ASSERT_TRUE(neo.information);
  EXPECT_LT(ogden.information->aic, neo.information->aic - 50.0);
  EXPECT_LT(ogden.rms_residual_mpa, 0.1 * neo.rms_residual_mpa);

  // On every point too, Ogden (three terms) has a far lower AIC than neo-Hookean, and the
  // ranking puts neo-Hookean behind it.
  const auto data = treloar();
  ASSERT_EQ(data.size(), 21u);
  const auto ranked = compare_uniaxial_fits(data, {FitLaw::NeoHookean, FitLaw::Ogden});
  ASSERT_EQ(ranked.size(), 2u);
  EXPECT_EQ(ranked[0].law, FitLaw::Ogden) << ranked[0].message;
  EXPECT_EQ(ranked[1].law, FitLaw::NeoHookean);
  ASSERT_TRUE(ranked[0].information && ranked[1].information);
  EXPECT_LT(ranked[0].information->aic, ranked[1].information->aic - 50.0);
}

TEST(LawFit, CompareRanksEveryLawByAic) {
  const auto data = synthetic({0.06, Gent{40.0}}, StressTest::Uniaxial, 4.0, 30, 0.002, 5);
  const auto ranked = compare_uniaxial_fits(data, all_fit_laws());
  ASSERT_EQ(ranked.size(), all_fit_laws().size());
  for (std::size_t i = 1; i < ranked.size(); ++i)
    if (ranked[i].information && ranked[i].status != Status::NoConvergence) {
      ASSERT_TRUE(ranked[i - 1].information);
      EXPECT_LE(ranked[i - 1].information->aic, ranked[i].information->aic);
    }
  // Gent data: neo-Hookean and Mooney-Rivlin cannot stiffen and rank last among the converged.
  EXPECT_NE(ranked.front().law, FitLaw::NeoHookean);
  EXPECT_THROW(compare_uniaxial_fits(data, {}), std::invalid_argument);
}

TEST(LawFit, RefusesBadOgdenOptions) {
  const auto data = synthetic({0.06, NeoHookean{}}, StressTest::Uniaxial, 3.0);
  UniaxialFitOptions o;
  o.ogden_alpha_start = {0.5};  // |alpha| < 1
  EXPECT_THROW(fit_uniaxial(data, FitLaw::Ogden, o), std::invalid_argument);
  o.ogden_alpha_start = {2, 3, 4, 5};
  EXPECT_THROW(fit_uniaxial(data, FitLaw::Ogden, o), std::invalid_argument);
  o.ogden_alpha_start = {};
  o.ogden_terms = 0;
  EXPECT_THROW(fit_uniaxial(data, FitLaw::Ogden, o), std::invalid_argument);
  EXPECT_EQ(fit_law_of("arruda-boyce"), FitLaw::ArrudaBoyce);
  EXPECT_THROW(fit_law_of("rubber"), InvalidInput);
}

}  // namespace
}  // namespace puncture
