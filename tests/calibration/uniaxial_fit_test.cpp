// Uniaxial fit: stresses made with uniaxial_stress() and known parameters must give them back;
// with seeded noise the standard errors must describe the scatter; data that never reach the
// Gent stiffening must be reported as not determining J_lim; bad data are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "puncture/calibration.hpp"
#include "seeded_noise.hpp"

namespace puncture {
namespace {

constexpr double kG = 0.06;  // MPa, the paper's

// n + 1 equally spaced stretches from 1 to `max_stretch`, stress G s_uni(law) plus noise.
std::vector<UniaxialPoint> synthetic(const MaterialLaw& law, double max_stretch, int n = 30,
                                     double noise_mpa = 0.0, unsigned seed = 1) {
  test::SeededNoise noise(seed, noise_mpa);
  std::vector<UniaxialPoint> points;
  for (int i = 0; i <= n; ++i) {
    const double l = 1.0 + (max_stretch - 1.0) * i / n;
    points.push_back({l, kG * uniaxial_stress(law, l) + (noise_mpa > 0.0 ? noise() : 0.0)});
  }
  return points;
}

const FittedParameter& parameter(const UniaxialFit& fit, const std::string& name) {
  for (const auto& p : fit.parameters)
    if (p.name == name) return p;
  throw std::logic_error("no parameter " + name);
}

// Exact data: the optimum is the truth and the residual vanishes, up to the optimiser's
// tolerances (xtol 1e-12) and round-off in the stresses (1e-16 MPa): 1e-9 relative.
TEST(UniaxialFit, RecoversExactParametersOfEachLaw) {
  const auto gent = fit_uniaxial(synthetic(Gent{125.0}, 4.0), FitLaw::Gent);
  ASSERT_TRUE(gent.ok()) << gent.message;
  EXPECT_NEAR(*parameter(gent, "G").value, kG, 1e-9 * kG);
  EXPECT_NEAR(*parameter(gent, "J_lim").value, 125.0, 1e-9 * 125.0);
  EXPECT_TRUE(parameter(gent, "J_lim").identifiable);
  EXPECT_LT(gent.rms_residual_mpa, 1e-12);
  ASSERT_TRUE(gent.material);
  EXPECT_NEAR(std::get<Gent>(gent.material->law).j_lim, 125.0, 1e-7);
  EXPECT_NEAR(gent.max_i1_minus_3, 16.0 + 0.5 - 3.0, 1e-12);

  const auto neo = fit_uniaxial(synthetic(NeoHookean{}, 3.0), FitLaw::NeoHookean);
  ASSERT_TRUE(neo.ok());
  ASSERT_EQ(neo.parameters.size(), 1u);
  EXPECT_NEAR(*neo.parameters[0].value, kG, 1e-12);

  const auto mr = fit_uniaxial(synthetic(MooneyRivlin{0.1}, 3.0), FitLaw::MooneyRivlin);
  ASSERT_TRUE(mr.ok());
  EXPECT_NEAR(*parameter(mr, "G").value, kG, 1e-9 * kG);
  EXPECT_NEAR(*parameter(mr, "alpha").value, 0.1, 1e-9);
  ASSERT_TRUE(mr.material);
}

TEST(UniaxialFit, NoisyFitIsAStationaryPointOfTheCost) {
  // At an interior least-squares optimum the cost's gradient J^T r vanishes: each column of
  // J = d(model)/d(G, c) is orthogonal to the residuals.  The derivatives are written out here
  // (model G g / (1 - c k)), not taken from the fit.  The old stop on the cost's decrease was
  // 1e-8 short in c (|J_c . r| / (|J_c| |r|) ~ 1e-6); stopping on the step leaves round-off.
  const auto data = synthetic(Gent{125.0}, 4.0, 30, 0.002, 1);
  const auto fit = fit_uniaxial(data, FitLaw::Gent);
  ASSERT_TRUE(fit.ok()) << fit.message;
  const double G = *parameter(fit, "G").value, c = *fit.inverse_j_lim;
  double jg_r = 0.0, jc_r = 0.0, jg2 = 0.0, jc2 = 0.0, r2 = 0.0;
  for (const auto& p : data) {
    const double l = p.stretch, g = l - 1.0 / (l * l), k = l * l + 2.0 / l - 3.0;
    const double r = G * g / (1.0 - c * k) - p.nominal_stress_mpa;
    const double jg = g / (1.0 - c * k), jc = G * g * k / ((1.0 - c * k) * (1.0 - c * k));
    jg_r += jg * r, jc_r += jc * r, jg2 += jg * jg, jc2 += jc * jc, r2 += r * r;
  }
  EXPECT_LT(std::abs(jg_r), 1e-9 * std::sqrt(jg2 * r2));
  EXPECT_LT(std::abs(jc_r), 1e-9 * std::sqrt(jc2 * r2));
}

TEST(UniaxialFit, FittedStressesAreTheLibrarysUniaxialStress) {
  // A fit of slightly perturbed data: its fitted stresses must be G s_uni(fitted law).
  for (const auto& [law, truth] :
       {std::pair{FitLaw::Gent, MaterialLaw(Gent{60.0})},
        std::pair{FitLaw::NeoHookean, MaterialLaw(NeoHookean{})},
        std::pair{FitLaw::MooneyRivlin, MaterialLaw(MooneyRivlin{0.2})}}) {
    const auto data = synthetic(truth, 3.5, 20, 0.002, 3);
    const auto fit = fit_uniaxial(data, law);
    ASSERT_TRUE(fit.ok() && fit.material) << to_string(law);
    for (std::size_t i = 0; i < data.size(); ++i)
      EXPECT_NEAR(
          fit.fitted_stress_mpa[i],
          fit.material->shear_modulus_mpa * uniaxial_stress(fit.material->law, data[i].stretch),
          1e-13)
          << to_string(law) << " point " << i;
  }
}

TEST(UniaxialFit, NoisyDataAreRecoveredWithinTheirStandardErrors) {
  // 31 points to stretch 4 with 0.002 MPa noise (1-4 % of the stresses): J_lim is well
  // determined.  Over 200 seeds the truth must lie within two standard errors about 95 % of the
  // time (binomial sd 1.5 %): [88 %, 99.5 %] fails only if the errors are wrong.
  int g_inside = 0, c_inside = 0;
  const int seeds = 200;
  for (int seed = 1; seed <= seeds; ++seed) {
    const auto fit = fit_uniaxial(synthetic(Gent{125.0}, 4.0, 30, 0.002, seed), FitLaw::Gent);
    ASSERT_TRUE(fit.ok());
    const auto& g = parameter(fit, "G");
    g_inside += std::abs(*g.value - kG) < 2.0 * *g.standard_error;
    c_inside += std::abs(*fit.inverse_j_lim - 1.0 / 125.0) < 2.0 * *fit.inverse_j_lim_se;
    if (seed == 1) {
      EXPECT_TRUE(g.identifiable);
      EXPECT_TRUE(parameter(fit, "J_lim").identifiable);
      EXPECT_NEAR(fit.residual_sd_mpa, 0.002, 0.0006);  // sigma estimated from 29 dof
    }
  }
  EXPECT_GE(g_inside, 176);
  EXPECT_LE(g_inside, 199);
  EXPECT_GE(c_inside, 176);
  EXPECT_LE(c_inside, 199);
}

TEST(UniaxialFit, DataShortOfTheStiffeningDoNotDetermineJLim) {
  // The paper's situation (§4.1): specimens fail before the stiffening.  To stretch 1.5,
  // I1 - 3 = 0.58 and Gent with J_lim = 125 is 0.5 % stiffer than neo-Hookean; with 0.002 MPa
  // noise the standard error of 1/J_lim is ~0.05, six times its true value 0.008.  (Seed 3 gives
  // a best 1/J_lim of 0.017 > 0; about a third of the seeds give one below 0, on the bound 0, as
  // NeoHookeanDataShowNoStiffening checks.)
  const auto fit = fit_uniaxial(synthetic(Gent{125.0}, 1.5, 30, 0.002, 3), FitLaw::Gent);
  ASSERT_TRUE(fit.ok());
  const auto& j = parameter(fit, "J_lim");
  EXPECT_FALSE(j.identifiable);
  EXPECT_NE(j.note.find("not identifiable"), std::string::npos) << j.note;
  ASSERT_TRUE(fit.inverse_j_lim_se);
  EXPECT_GT(*fit.inverse_j_lim_se, 4.0 / 125.0);
  // G is still determined, within a few standard errors of the truth.
  const auto& g = parameter(fit, "G");
  EXPECT_TRUE(g.identifiable);
  EXPECT_LT(std::abs(*g.value - kG), 3.0 * *g.standard_error);
  ASSERT_TRUE(fit.stiffening_at_largest_stretch);
  EXPECT_LT(std::abs(*fit.stiffening_at_largest_stretch - 1.0), 0.2);
}

// The least-squares G of P = G (lambda - lambda^-2), in closed form: what a two-parameter fit
// whose second parameter sits on its neo-Hookean bound (Gent c = 0, Mooney-Rivlin alpha = 0)
// must give.
double neo_hookean_g(const std::vector<UniaxialPoint>& data) {
  double gp = 0.0, gg = 0.0;
  for (const auto& p : data) {
    const double g = p.stretch - 1.0 / (p.stretch * p.stretch);
    gp += g * p.nominal_stress_mpa;
    gg += g * g;
  }
  return gp / gg;
}

TEST(UniaxialFit, NeoHookeanDataShowNoStiffening) {
  // Fitted with Gent, neo-Hookean data give c = 1/J_lim scattered about 0.  The best c below 0
  // (softer than neo-Hookean) is outside the law: the fit ends on the bound c = 0 (OnBound, no
  // J_lim, no material) with the neo-Hookean G.  A positive c is called determined only beyond
  // two standard errors, which noise does about 2.3 % of the time: over 20 seeds at most 2
  // (binomial: P(> 2) ~ 1 %).
  int on_bound = 0, determined = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const auto data = synthetic(NeoHookean{}, 3.0, 30, 0.002, seed);
    const auto fit = fit_uniaxial(data, FitLaw::Gent);
    ASSERT_TRUE(fit.ok() || fit.status == Status::OnBound) << fit.message;
    const auto& j = parameter(fit, "J_lim");
    determined += j.identifiable;
    if (fit.status == Status::OnBound) {
      ++on_bound;
      EXPECT_EQ(*fit.inverse_j_lim, 0.0);
      EXPECT_NEAR(*parameter(fit, "G").value, neo_hookean_g(data), 1e-9 * kG);
      EXPECT_EQ(fit.failure_kind(), FailureKind::Physical);
      EXPECT_NE(fit.message.find("1/J_lim = 0"), std::string::npos) << fit.message;
      EXPECT_FALSE(j.identifiable);
      EXPECT_FALSE(j.value);
      EXPECT_FALSE(fit.material);
      EXPECT_NE(j.note.find("no Gent stiffening"), std::string::npos) << j.note;
    } else if (!j.identifiable) {
      EXPECT_NE(j.note.find("within two standard errors"), std::string::npos) << j.note;
    }
  }
  EXPECT_LE(determined, 2);
  EXPECT_GT(on_bound, 0);  // the seeds give both signs
  EXPECT_LT(on_bound, 20);
}

TEST(UniaxialFit, MooneyRivlinStopsOnTheEdgeOfItsRange) {
  // Data stiffening with the stretch like alpha = -0.2 (the formula extends there): the best
  // Mooney-Rivlin fit in 0 <= alpha <= 1 is alpha = 0 with the neo-Hookean G, reported OnBound.
  const auto data = synthetic(MooneyRivlin{-0.2}, 3.0);
  const auto fit = fit_uniaxial(data, FitLaw::MooneyRivlin);
  EXPECT_EQ(fit.status, Status::OnBound) << fit.message;
  EXPECT_EQ(*parameter(fit, "alpha").value, 0.0);
  EXPECT_NEAR(*parameter(fit, "G").value, neo_hookean_g(data), 1e-9 * kG);
  EXPECT_NE(fit.message.find("alpha = 0"), std::string::npos) << fit.message;
  // Softening beyond alpha = 1 (the formula with alpha = 1.5): the other edge.
  const auto soft = fit_uniaxial(synthetic(MooneyRivlin{1.5}, 3.0), FitLaw::MooneyRivlin);
  EXPECT_EQ(soft.status, Status::OnBound) << soft.message;
  EXPECT_EQ(*parameter(soft, "alpha").value, 1.0);
  EXPECT_NE(soft.message.find("alpha = 1"), std::string::npos) << soft.message;
}

TEST(UniaxialFit, MooneyRivlinOnGentDataDoesNotRunAway) {
  // Strongly stiffening Gent data (J_lim = 20 to stretch 4: 2.7 x neo-Hookean at the end) fitted
  // with Mooney-Rivlin ran to alpha = -5e4, G = 1e-5 MPa unbounded and was called converged.
  const auto data = synthetic(Gent{20.0}, 4.0);
  const auto fit = fit_uniaxial(data, FitLaw::MooneyRivlin);
  EXPECT_EQ(fit.status, Status::OnBound) << fit.message;
  EXPECT_EQ(*parameter(fit, "alpha").value, 0.0);
  EXPECT_NEAR(*parameter(fit, "G").value, neo_hookean_g(data), 1e-9 * kG);
  EXPECT_LT(fit.iterations, 100);
}

TEST(UniaxialFit, DataStifferThanGentStopAtLocking) {
  // A last point 1e6 times the Gent stress: the best c is at 1/(I1 - 3) of the last point, the
  // edge of the Gent law's range (the data lock there).
  auto data = synthetic(Gent{125.0}, 4.0);
  data.back().nominal_stress_mpa *= 1e6;
  const auto fit = fit_uniaxial(data, FitLaw::Gent);
  EXPECT_EQ(fit.status, Status::OnBound) << fit.message;
  const double k_max = 16.0 + 0.5 - 3.0;
  EXPECT_NEAR(*fit.inverse_j_lim, 1.0 / k_max, 1e-5 / k_max);
  EXPECT_NE(fit.message.find("stiffen faster than a Gent material"), std::string::npos)
      << fit.message;
}

TEST(UniaxialFit, ForceAndDisplacementData) {
  const SpecimenGeometry specimen{10.0, 0.2, 60.0};
  const auto points = uniaxial_points({0.0, 0.1, 0.3}, {0.0, 6.0, 30.0}, specimen);
  ASSERT_EQ(points.size(), 3u);
  EXPECT_DOUBLE_EQ(points[1].stretch, 1.1);
  EXPECT_DOUBLE_EQ(points[2].nominal_stress_mpa, 0.15);  // 0.3 N / 2 mm^2
  EXPECT_THROW(uniaxial_points({1.0}, {1.0}, {0.0, 0.2, 60.0}), std::invalid_argument);

  const auto table = parse_numeric_csv("displacement_mm,force_n\n0,0\n6,0.1\n30,0.3\n", "t.csv");
  EXPECT_EQ(uniaxial_points_from_table(table, specimen)[2].stretch, 1.5);
  EXPECT_THROW(uniaxial_points_from_table(table, std::nullopt), std::invalid_argument);
  const auto stress = parse_numeric_csv("stretch,nominal_stress_mpa\n1,0\n2,0.1\n", "t.csv");
  EXPECT_EQ(uniaxial_points_from_table(stress, std::nullopt)[1].nominal_stress_mpa, 0.1);
  EXPECT_THROW(uniaxial_points_from_table(stress, specimen), std::invalid_argument);
  const auto both =
      parse_numeric_csv("stretch,nominal_stress_mpa,force_n,displacement_mm\n1,0,0,0\n", "t.csv");
  EXPECT_THROW(uniaxial_points_from_table(both, std::nullopt), CsvError);
  const auto neither = parse_numeric_csv("stretch,force_n\n1,0\n", "t.csv");
  EXPECT_THROW(uniaxial_points_from_table(neither, std::nullopt), CsvError);
  const auto torn = parse_numeric_csv("displacement_mm,force_n\n0,0\n-60,0\n", "t.csv");
  try {
    uniaxial_points_from_table(torn, specimen);
    FAIL() << "a stretch of 0 was accepted";
  } catch (const CsvError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.column(), 1);
  }
}

TEST(UniaxialFit, RefusesDataThatCannotBeFitted) {
  const std::vector<UniaxialPoint> two{{1.0, 0.0}, {2.0, 0.1}};
  EXPECT_THROW(fit_uniaxial(two, FitLaw::Gent), std::invalid_argument);  // 2 parameters
  EXPECT_NO_THROW(fit_uniaxial(two, FitLaw::NeoHookean));
  EXPECT_THROW(fit_uniaxial({{1.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}}, FitLaw::NeoHookean),
               std::invalid_argument);
  EXPECT_THROW(fit_uniaxial({{1.0, 0.0}, {2.0, -0.1}, {3.0, -0.2}}, FitLaw::Gent),
               std::invalid_argument);
  EXPECT_THROW(fit_uniaxial({{1.0, 0.0}, {-2.0, 0.1}, {3.0, 0.2}}, FitLaw::Gent),
               std::invalid_argument);
  EXPECT_THROW(fit_uniaxial({{1.0, 0.0}, {2.0, NAN}, {3.0, 0.2}}, FitLaw::Gent),
               std::invalid_argument);
}

}  // namespace
}  // namespace puncture
