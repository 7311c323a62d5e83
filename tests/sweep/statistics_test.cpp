// Statistics of a sweep's output: percentiles and histogram of known values, the regression
// coefficients of a known-linear output (exact on an orthogonal grid, close to the analytic
// first-order Sobol indices on a Latin hypercube), and Monte Carlo percentiles of the solver's
// puncture force converging to their closed form, inside the corner band of puncture_band.
#include <gtest/gtest.h>

#include <boost/math/distributions/lognormal.hpp>
#include <cmath>
#include <cstdio>

#include "puncture/loading_curve.hpp"
#include "puncture/puncture_band.hpp"
#include "puncture/sweep.hpp"
#include "puncture/sweep_statistics.hpp"

namespace puncture {
namespace {

TEST(SweepStatistics, PercentilesHistogramAndFailuresOfKnownValues) {
  SweepStatistics stats({"x"}, "y");
  for (int k = 1; k <= 101; ++k) stats.add({static_cast<double>(k)}, static_cast<double>(k));
  stats.add({0.0}, std::nullopt);  // a failed point
  const OutputStatistics s = stats.result({0.0, 0.05, 0.5, 0.975, 1.0}, 10);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(s.points, 102u);
  EXPECT_EQ(s.found, 101u);
  EXPECT_DOUBLE_EQ(s.mean, 51.0);
  EXPECT_DOUBLE_EQ(s.sd, std::sqrt(101.0 * 102.0 / 12.0));  // n (n + 1) / 12 for 1..n
  EXPECT_DOUBLE_EQ(s.percentiles[0].value, 1.0);
  EXPECT_DOUBLE_EQ(s.percentiles[1].value, 6.0);  // position 0.05 * 100 = 5
  EXPECT_DOUBLE_EQ(s.percentiles[2].value, 51.0);
  EXPECT_DOUBLE_EQ(s.percentiles[3].value, 98.5);  // position 97.5: halfway 98 to 99
  EXPECT_DOUBLE_EQ(s.percentiles[4].value, 101.0);
  ASSERT_EQ(s.histogram.counts.size(), 10u);
  std::size_t total = 0;
  for (auto c : s.histogram.counts) total += c;
  EXPECT_EQ(total, 101u);
  EXPECT_EQ(s.histogram.counts.front(), 10u);  // 1..10 in [1, 11)
  EXPECT_EQ(s.histogram.counts.back(), 11u);   // 91..101 in [91, 101]
  EXPECT_NEAR(s.r_squared, 1.0, 1e-12);
}

TEST(SweepStatistics, TooFewValuesIsIncomplete) {
  SweepStatistics stats({"x"}, "y");
  stats.add({1.0}, 2.0);
  stats.add({2.0}, std::nullopt);
  EXPECT_EQ(stats.result().status, Status::Incomplete);
  EXPECT_THROW(stats.add({1.0, 2.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(stats.add({1.0}, std::nan("")), std::invalid_argument);
}

// y = 3 + 2 x1 - 0.5 x2 + 0 x3.  On a full grid the inputs are exactly uncorrelated, so the
// fit is exact and SRC_j^2 = a_j^2 var_j / sum_k a_k^2 var_k: the first-order Sobol indices of
// the linear output over the grid's points, which sum to 1.
TEST(SweepStatistics, KnownLinearOutputOnAGridGivesTheExactIndices) {
  SweepSpec spec;
  spec.parameters = {{"x1", evenly_spaced_levels(0.0, 1.0, 5), {}},
                     {"x2", evenly_spaced_levels(0.0, 4.0, 3), {}},
                     {"x3", evenly_spaced_levels(10.0, 12.0, 4), {}},
                     {"shape", {"a", "b"}, {}}};  // a word: left out of the fit
  SweepStatistics stats({"x1", "x2", "x3", "shape"}, "y");
  for (std::size_t i = 0; i < point_count(spec); ++i) {
    const SweepPoint p = sweep_point(spec, i);
    stats.add(p.values, 3.0 + 2.0 * p.values[0] - 0.5 * p.values[1] + 0.0 * p.values[2]);
  }
  const OutputStatistics s = stats.result();
  ASSERT_EQ(s.sensitivities.size(), 3u);
  // Population variances of the levels: {0,.25,.5,.75,1}: 0.125; {0,2,4}: 8/3; x3: 5/9.
  const double v1 = 4.0 * 0.125, v2 = 0.25 * 8.0 / 3.0;
  // Ranked by |SRC|: x2 (share 4/7), x1 (3/7), x3 (0).
  EXPECT_EQ(s.sensitivities[0].name, "x2");
  EXPECT_EQ(s.sensitivities[1].name, "x1");
  EXPECT_EQ(s.sensitivities[2].name, "x3");
  const InputSensitivity &x2 = s.sensitivities[0], &x1 = s.sensitivities[1];
  EXPECT_NEAR(x1.coefficient, 2.0, 1e-12);
  EXPECT_NEAR(x1.src, std::sqrt(v1 / (v1 + v2)), 1e-12);
  EXPECT_NEAR(x2.coefficient, -0.5, 1e-12);
  EXPECT_NEAR(x2.src, -std::sqrt(v2 / (v1 + v2)), 1e-12);
  EXPECT_NEAR(s.sensitivities[2].coefficient, 0.0, 1e-12);
  EXPECT_NEAR(s.sensitivities[2].src, 0.0, 1e-12);
  EXPECT_NEAR(s.r_squared, 1.0, 1e-12);
}

// The same output over continuous uniform inputs, sampled by a Latin hypercube: the slopes are
// exact, SRC^2 within 0.02 of the analytic first-order Sobol indices a_j^2 var_j / var_y
// (x1 on [0, 1]: 4/12; x2 on [0, 4]: 0.25 * 16/12; both 1/2).
TEST(SweepStatistics, KnownLinearOutputOnALatinHypercubeApproachesTheSobolIndices) {
  SweepSpec spec;
  spec.design = SweepDesign::LatinHypercube;
  spec.samples = 1024;
  spec.seed = 5;
  spec.parameters = {{"x1", {}, {DistributionKind::Uniform, 0.0, 1.0}},
                     {"x2", {}, {DistributionKind::Uniform, 0.0, 4.0}}};
  SweepStatistics stats({"x1", "x2"}, "y");
  for (std::size_t i = 0; i < spec.samples; ++i) {
    const SweepPoint p = sweep_point(spec, i);
    stats.add(p.values, 3.0 + 2.0 * p.values[0] - 0.5 * p.values[1]);
  }
  const OutputStatistics s = stats.result();
  ASSERT_EQ(s.sensitivities.size(), 2u);
  for (const InputSensitivity& in : s.sensitivities) {
    EXPECT_NEAR(in.coefficient, in.name == "x1" ? 2.0 : -0.5, 1e-10);
    EXPECT_NEAR(in.src * in.src, 0.5, 0.02) << in.name;
  }
}

Problem paper_with(double shear_modulus_mpa) {
  Problem p;
  p.material.shear_modulus_mpa = shear_modulus_mpa;
  return p;
}

double force_or_fail(const SweepRow& row) {
  if (!row.ok())
    throw std::runtime_error("point " + std::to_string(row.point.index) + ": " + row.message);
  return row.puncture->force_n;
}

// The puncture force is proportional to G (same normalised problem), so with G lognormal its
// percentiles are F(G0) / G0 times G's: Monte Carlo estimates converge to them as N grows.
TEST(SweepStatistics, MonteCarloPercentilesOfThePunctureForceConverge) {
  const double g0 = 0.06, mean = 0.06, sd = 0.012;
  const double f0 = predict_puncture(paper_with(g0)).force_n;
  const double sd_log = std::sqrt(std::log1p((sd / mean) * (sd / mean)));
  const boost::math::lognormal g_law(std::log(mean) - 0.5 * sd_log * sd_log, sd_log);
  const std::vector<double> probabilities = {0.05, 0.5, 0.95};
  std::vector<double> errors;
  for (const std::size_t n : {100u, 400u, 1600u}) {
    SweepSpec spec;
    spec.design = SweepDesign::MonteCarlo;
    spec.samples = n;
    spec.seed = 2026;
    spec.parameters = {{"shear-modulus", {}, {DistributionKind::LogNormal, 0, 0, mean, sd}}};
    SweepStatistics stats({"shear-modulus"}, "puncture_force_n");
    SweepOptions options;
    options.on_row = [&stats](const SweepRow& row) {
      stats.add(row.point.values, force_or_fail(row));
    };
    sweep(
        spec, [](const SweepPoint& p) { return paper_with(p.values[0]); }, options);
    const OutputStatistics s = stats.result(probabilities);
    double error = 0.0;
    for (const Percentile& p : s.percentiles) {
      const double exact = f0 / g0 * boost::math::quantile(g_law, p.probability);
      error = std::max(error, std::abs(p.value / exact - 1.0));
    }
    errors.push_back(error);
    // The force is exactly linear in G: R^2 = 1, G takes the whole variance.
    EXPECT_NEAR(s.r_squared, 1.0, 1e-9);
    EXPECT_NEAR(s.sensitivities[0].coefficient, f0 / g0, 1e-9 * f0 / g0);
  }
  std::printf(
      "largest relative error of the 5, 50, 95 %% percentiles: N 100 %.3g, 400 %.3g, 1600 %.3g\n",
      errors[0],
      errors[1],
      errors[2]);
  EXPECT_LT(errors[2], errors[0]);
  // The 5 % and 95 % percentiles' standard error at N = 1600 is ~1.5 % of the value here.
  EXPECT_LT(errors[2], 0.03);
}

// critical I1 and friction as truncated normals within mean +- 2 sd: every Monte Carlo force
// lies in the corner band of puncture_band over the same box (the documented monotone
// directions put the extremes at corners), and the 5-95 % interval holds the nominal force.
TEST(SweepStatistics, MonteCarloBandLiesInTheCornerBandAndHoldsTheNominalForce) {
  const Problem nominal;
  const double i1_sd = 4.8, mu_sd = 0.03;
  BandRanges ranges;
  ranges.critical_i1 = plus_minus(nominal.critical_i1, i1_sd, 2.0);
  ranges.friction = plus_minus(nominal.friction, mu_sd, 2.0);
  const PunctureBand band = puncture_band(nominal, ranges);
  ASSERT_TRUE(band.ok()) << band.message;
  SweepSpec spec;
  spec.design = SweepDesign::LatinHypercube;
  spec.samples = 200;
  spec.seed = 9;
  spec.parameters = {{"critical-i1",
                      {},
                      {DistributionKind::TruncatedNormal,
                       ranges.critical_i1->lower,
                       ranges.critical_i1->upper,
                       nominal.critical_i1,
                       i1_sd}},
                     {"friction",
                      {},
                      {DistributionKind::TruncatedNormal,
                       ranges.friction->lower,
                       ranges.friction->upper,
                       nominal.friction,
                       mu_sd}}};
  SweepStatistics stats({"critical-i1", "friction"}, "puncture_force_n");
  SweepOptions options;
  options.on_row = [&](const SweepRow& row) {
    const double f = force_or_fail(row);
    stats.add(row.point.values, f);
    EXPECT_GE(f, *band.force_min_n * (1.0 - 1e-9)) << row.point.index;
    EXPECT_LE(f, *band.force_max_n * (1.0 + 1e-9)) << row.point.index;
  };
  sweep(
      spec,
      [&](const SweepPoint& p) {
        Problem problem = nominal;
        problem.critical_i1 = p.values[0];
        problem.friction = p.values[1];
        return problem;
      },
      options);
  const OutputStatistics s = stats.result({0.05, 0.95});
  EXPECT_LT(s.percentiles[0].value, band.nominal.force_n);
  EXPECT_GT(s.percentiles[1].value, band.nominal.force_n);
  // The band's ranking: critical I1 moves the force most (puncture_band's dominant parameter).
  ASSERT_TRUE(band.dominant.has_value());
  EXPECT_EQ(*band.dominant, BandParameter::CriticalI1);
  EXPECT_EQ(s.sensitivities.front().name, "critical-i1");
}

}  // namespace
}  // namespace puncture
