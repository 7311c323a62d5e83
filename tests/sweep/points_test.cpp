// The point list: grid order and count, Latin hypercube strata, the published Sobol points,
// the distributions' quantiles, and point i depending on the spec and i alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <numeric>
#include <set>

#include "puncture/sweep.hpp"
#include "sweep/point_hash.hpp"

namespace puncture {
namespace {

SweepParameter uniform(const std::string& name, double lower, double upper) {
  SweepParameter p;
  p.name = name;
  p.distribution = {DistributionKind::Uniform, lower, upper};
  return p;
}

SweepSpec sampled(SweepDesign design, std::size_t samples, std::size_t dimensions,
                  std::uint64_t seed = 7) {
  SweepSpec spec;
  spec.design = design;
  spec.samples = samples;
  spec.seed = seed;
  for (std::size_t j = 0; j < dimensions; ++j)
    spec.parameters.push_back(uniform("u" + std::to_string(j), 0.0, 1.0));
  return spec;
}

TEST(SweepGrid, CountsEveryCombinationLastParameterFastest) {
  SweepSpec spec;
  spec.parameters = {{"indenter", {"flat", "sphere-tipped"}, {}},
                     {"thickness", evenly_spaced_levels(0.1, 0.3, 3), {}},
                     {"friction", {"0", "0.5"}, {}}};
  ASSERT_TRUE(validation_errors(spec).empty());
  ASSERT_EQ(point_count(spec), 12u);
  const SweepPoint p = sweep_point(spec, 9);  // 9 = 1*6 + 1*2 + 1
  EXPECT_EQ(p.texts, (std::vector<std::string>{"sphere-tipped", "0.2", "0.5"}));
  EXPECT_TRUE(std::isnan(p.values[0]));
  EXPECT_EQ(p.values[1], 0.2);
  EXPECT_EQ(p.values[2], 0.5);
  std::set<std::vector<std::string>> seen;
  for (std::size_t i = 0; i < 12; ++i) seen.insert(sweep_point(spec, i).texts);
  EXPECT_EQ(seen.size(), 12u);
  EXPECT_THROW(sweep_point(spec, 12), std::invalid_argument);
}

TEST(SweepGrid, EvenlySpacedLevelsHitBothEndsAndReadBackExactly) {
  const auto levels = evenly_spaced_levels(0.1, 0.3, 5);
  ASSERT_EQ(levels.size(), 5u);
  EXPECT_EQ(levels.front(), "0.1");
  EXPECT_EQ(levels.back(), "0.3");
  for (int k = 0; k < 5; ++k) EXPECT_EQ(std::stod(levels[k]), 0.1 + (k / 4.0) * (0.3 - 0.1)) << k;
  EXPECT_THROW(evenly_spaced_levels(1.0, 0.0, 3), std::invalid_argument);
  EXPECT_THROW(evenly_spaced_levels(0.0, 1.0, 1), std::invalid_argument);
}

// Exactly one point in each of the n strata [k/n, (k+1)/n) of every parameter, for sizes that
// are and are not powers of two (the permutation walks its cycle below n).
TEST(SweepLatinHypercube, OnePointPerStratumPerParameter) {
  for (const std::size_t n : {1u, 2u, 7u, 64u, 97u, 1000u}) {
    for (const std::uint64_t seed : {0u, 1u, 20261125u}) {
      const SweepSpec spec = sampled(SweepDesign::LatinHypercube, n, 4, seed);
      std::vector<std::vector<int>> hits(4, std::vector<int>(n, 0));
      for (std::size_t i = 0; i < n; ++i) {
        const SweepPoint p = sweep_point(spec, i);
        for (std::size_t j = 0; j < 4; ++j) {
          ASSERT_GT(p.values[j], 0.0);
          ASSERT_LT(p.values[j], 1.0);
          ++hits[j][static_cast<std::size_t>(std::floor(p.values[j] * n))];
        }
      }
      for (std::size_t j = 0; j < 4; ++j)
        EXPECT_EQ(std::count(hits[j].begin(), hits[j].end(), 1), static_cast<long>(n))
            << "n " << n << " seed " << seed << " parameter " << j;
    }
  }
}

TEST(SweepLatinHypercube, ParametersAndSeedsArePermutedIndependently) {
  const std::size_t n = 50;
  const SweepSpec a = sampled(SweepDesign::LatinHypercube, n, 2, 1);
  const SweepSpec b = sampled(SweepDesign::LatinHypercube, n, 2, 2);
  int same_strata_between_parameters = 0, same_point_between_seeds = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto pa = sweep_point(a, i), pb = sweep_point(b, i);
    same_strata_between_parameters += std::floor(pa.values[0] * n) == std::floor(pa.values[1] * n);
    same_point_between_seeds += pa.values[0] == pb.values[0];
  }
  // Two independent random permutations share ~1 fixed point on average.
  EXPECT_LT(same_strata_between_parameters, 6);
  EXPECT_EQ(same_point_between_seeds, 0);
}

TEST(SweepPermutation, IsABijectionForEverySize) {
  for (std::size_t n = 1; n < 300; n += 13) {
    const detail::IndexPermutation perm(n, 42);
    std::vector<std::size_t> image(n);
    for (std::size_t i = 0; i < n; ++i) image[i] = perm(i);
    std::sort(image.begin(), image.end());
    std::vector<std::size_t> identity(n);
    std::iota(identity.begin(), identity.end(), 0);
    EXPECT_EQ(image, identity) << n;
  }
}

// The unscrambled Sobol sequence with Joe and Kuo's direction numbers (new-joe-kuo-6.21201),
// its zero point skipped: the published first points of its first three dimensions (as given
// by e.g. scipy.stats.qmc.Sobol(3, scramble=False) after its first point).
TEST(SweepSobol, FirstPointsAreThePublishedSequence) {
  const double published[7][3] = {{0.5, 0.5, 0.5},
                                  {0.75, 0.25, 0.25},
                                  {0.25, 0.75, 0.75},
                                  {0.375, 0.375, 0.625},
                                  {0.875, 0.875, 0.125},
                                  {0.625, 0.125, 0.875},
                                  {0.125, 0.625, 0.375}};
  const SweepSpec spec = sampled(SweepDesign::Sobol, 7, 3);
  for (std::size_t i = 0; i < 7; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      EXPECT_EQ(sweep_point(spec, i).values[j], published[i][j]) << "point " << i << " dim " << j;
}

// The first 2^m points (and the zero) of each dimension fill the 2^m dyadic cells once each.
TEST(SweepSobol, EachDimensionIsStratifiedAtPowersOfTwo) {
  const std::size_t n = 255;  // 2^8 - 1 points after the zero
  const SweepSpec spec = sampled(SweepDesign::Sobol, n, 5);
  std::vector<std::set<int>> cells(5);
  for (std::size_t i = 0; i < n; ++i) {
    const SweepPoint p = sweep_point(spec, i);
    for (std::size_t j = 0; j < 5; ++j) cells[j].insert(static_cast<int>(p.values[j] * 256));
  }
  for (std::size_t j = 0; j < 5; ++j) {
    EXPECT_EQ(cells[j].size(), n);
    EXPECT_EQ(cells[j].count(0), 0u);  // the zero point's cell
  }
}

TEST(SweepMonteCarlo, PointDependsOnTheSpecAndItsIndexAlone) {
  const SweepSpec spec = sampled(SweepDesign::MonteCarlo, 1000, 3, 99);
  const SweepPoint late = sweep_point(spec, 777);
  for (std::size_t i = 0; i < 777; i += 111) sweep_point(spec, i);
  const SweepPoint again = sweep_point(spec, 777);
  EXPECT_EQ(late.values, again.values);
  EXPECT_EQ(late.texts, again.texts);
  EXPECT_EQ(late.seed, again.seed);
  EXPECT_NE(late.seed, sweep_point(spec, 776).seed);
  // A larger sweep of the same seed holds the same points.
  SweepSpec bigger = spec;
  bigger.samples = 5000;
  EXPECT_EQ(sweep_point(bigger, 777).values, late.values);
  // The text is the value's shortest exact form: it reads back to the same double.
  for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(std::stod(late.texts[j]), late.values[j]);
}

// Sample moments of each distribution against its parameters: the mean within 4 standard
// errors, the sd within 4 % (n = 20000 independent points).
TEST(SweepDistributions, MonteCarloSamplesHaveTheirDistributionsMoments) {
  struct Case {
    Distribution d;
    double mean, sd;
  };
  // Truncated normal on [mean - sd, mean + 2 sd] of normal(0, 1): its moments in closed form.
  const boost::math::normal z;
  const double a = -1.0, b = 2.0;
  const double mass = boost::math::cdf(z, b) - boost::math::cdf(z, a);
  const double pa = boost::math::pdf(z, a), pb = boost::math::pdf(z, b);
  const double t_mean = (pa - pb) / mass;
  const double t_var = 1.0 + (a * pa - b * pb) / mass - t_mean * t_mean;
  const std::vector<Case> cases = {
      {{DistributionKind::Uniform, 2.0, 5.0}, 3.5, 3.0 / std::sqrt(12.0)},
      {{DistributionKind::Normal, 0, 0, 95.2, 3.0}, 95.2, 3.0},
      {{DistributionKind::LogNormal, 0, 0, 0.06, 0.012}, 0.06, 0.012},
      {{DistributionKind::TruncatedNormal, 10.0 + a * 0.5, 10.0 + b * 0.5, 10.0, 0.5},
       10.0 + 0.5 * t_mean,
       0.5 * std::sqrt(t_var)},
  };
  for (const Case& c : cases) {
    SweepSpec spec;
    spec.design = SweepDesign::MonteCarlo;
    spec.samples = 20000;
    spec.seed = 3;
    spec.parameters = {{"x", {}, c.d}};
    double sum = 0, sum2 = 0, lo = 1e300, hi = -1e300;
    for (std::size_t i = 0; i < spec.samples; ++i) {
      const double x = sweep_point(spec, i).values[0];
      sum += x;
      sum2 += x * x;
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    const double n = static_cast<double>(spec.samples);
    const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
    EXPECT_NEAR(mean, c.mean, 4.0 * c.sd / std::sqrt(n)) << to_token(c.d.kind);
    EXPECT_NEAR(sd / c.sd, 1.0, 0.04) << to_token(c.d.kind);
    if (c.d.kind == DistributionKind::Uniform || c.d.kind == DistributionKind::TruncatedNormal) {
      EXPECT_GE(lo, c.d.lower);
      EXPECT_LE(hi, c.d.upper);
    }
    if (c.d.kind == DistributionKind::LogNormal) EXPECT_GT(lo, 0.0);
  }
}

TEST(SweepSpecChecks, EachProblemNamesItsParameter) {
  SweepSpec grid;
  grid.parameters = {{"thickness", {}, {}}};
  auto errors = validation_errors(grid);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].parameter, "thickness");

  SweepSpec lhs = sampled(SweepDesign::LatinHypercube, 0, 1);
  lhs.parameters.push_back(lhs.parameters[0]);                                             // twice
  lhs.parameters.push_back({"friction", {}, {DistributionKind::Normal, 0, 0, 0.2, 0.0}});  // sd 0
  std::set<std::string> named;
  for (const auto& e : validation_errors(lhs)) named.insert(e.parameter);
  EXPECT_EQ(named, (std::set<std::string>{"samples", "u0", "friction"}));
  EXPECT_THROW(sweep_point(lhs, 0), std::invalid_argument);
}

}  // namespace
}  // namespace puncture
