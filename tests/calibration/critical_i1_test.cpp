// Critical I1 from inflation tests: the paper's 95.2 +- 4.8 from four burst radii, the
// equibiaxial invariant and its inverse, and the inputs that are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "puncture/calibration.hpp"
#include "puncture/inflation.hpp"

namespace puncture {
namespace {

// Four radii of a 0.5 mm mark at burst, to the micrometre, chosen so that the tests give the
// paper's 95.2 +- 4.8 (§2.3): I1 = 89.57, 92.86, 98.84, 99.52.
const std::vector<double> kPaperBurstRadii{3.346, 3.407, 3.515, 3.527};

TEST(CriticalI1, ReproducesThePapersValueFromFourTests) {
  std::vector<BurstTest> tests;
  for (const double r : kPaperBurstRadii) tests.push_back({0.5, r});
  const auto e = critical_i1_from_inflation(tests);
  ASSERT_EQ(e.first_invariants.size(), 4u);
  // The radii are rounded to 1 um, which moves each I1 by up to 4 lambda^2 (0.5 um / r) ~ 0.03;
  // the paper prints one decimal, so agreement to 0.01 is the test.
  EXPECT_NEAR(e.mean, 95.2, 0.01);
  ASSERT_TRUE(e.standard_deviation);
  EXPECT_NEAR(*e.standard_deviation, 4.8, 0.01);
  EXPECT_NEAR(*e.standard_error, *e.standard_deviation / 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(e.stretches[0], 3.346 / 0.5);
}

TEST(CriticalI1, MeanAndSampleDeviationOfKnownValues) {
  // Burst stretches whose I1 are exactly 90, 95, 100 (inverted, then measured back).
  std::vector<BurstTest> tests;
  for (const double i1 : {90.0, 95.0, 100.0})
    tests.push_back({0.5, 0.5 * equibiaxial_stretch_for_first_invariant(i1)});
  const auto e = critical_i1_from_inflation(tests);
  EXPECT_NEAR(e.mean, 95.0, 1e-10);
  EXPECT_NEAR(*e.standard_deviation, 5.0, 1e-10);  // sqrt((25 + 0 + 25) / 2)
}

TEST(CriticalI1, OneTestHasNoDeviation) {
  const auto e = critical_i1_from_inflation({{0.5, 3.45}});
  EXPECT_NEAR(e.mean, equibiaxial_first_invariant(6.9), 1e-12);
  EXPECT_FALSE(e.standard_deviation);
  EXPECT_FALSE(e.standard_error);
}

TEST(CriticalI1, EquibiaxialInvariantAndItsInverse) {
  EXPECT_DOUBLE_EQ(equibiaxial_first_invariant(1.0), 3.0);
  EXPECT_DOUBLE_EQ(equibiaxial_first_invariant(2.0), 8.0 + 1.0 / 16.0);
  for (const double l : {1.0, 1.001, 1.3, 2.0, 6.9, 50.0})
    EXPECT_NEAR(
        equibiaxial_stretch_for_first_invariant(equibiaxial_first_invariant(l)), l, 1e-12 * l);
  EXPECT_THROW(equibiaxial_stretch_for_first_invariant(2.9), std::invalid_argument);
  EXPECT_THROW(equibiaxial_stretch_for_first_invariant(NAN), std::invalid_argument);
}

TEST(CriticalI1, RefusesImpossibleMeasurements) {
  EXPECT_THROW(critical_i1_from_inflation({}), std::invalid_argument);
  EXPECT_THROW(critical_i1_from_inflation({{0.0, 3.0}}), std::invalid_argument);
  EXPECT_THROW(critical_i1_from_inflation({{0.5, -3.0}}), std::invalid_argument);
  EXPECT_THROW(critical_i1_from_inflation({{0.5, INFINITY}}), std::invalid_argument);
  try {
    critical_i1_from_inflation({{0.5, 3.0}, {0.5, 0.4}});
    FAIL() << "a shrinking mark was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("test 2"), std::string::npos) << e.what();
  }
}

// With the membrane's law.  Gent (the paper's J_lim = 125) and neo-Hookean burst at the pole
// over the paper's tests: the estimate is the paper's to the bit.  Mooney-Rivlin (alpha = 0.1)
// bursts near the clamp: inflated to the critical I1 95.2 (inflation_burst), its pole stretch
// 6.4692 read back as a mark gives 95.2 again, not the pole's 83.7, at R / A = 0.9962 (scipy's
// collocation solver on other equations puts it at 95.2000009, R = 24.904 mm of 25, in
// python/tests/test_inflation.py).
TEST(CriticalI1, WithTheMembranesLawTheLargestI1WhereverItLies) {
  std::vector<BurstTest> tests;
  for (const double r : kPaperBurstRadii) tests.push_back({0.5, r});
  const auto paper = critical_i1_from_inflation(tests);
  EXPECT_FALSE(paper.from_membrane);
  for (const MaterialLaw& law : {MaterialLaw{Gent{125.0}}, MaterialLaw{NeoHookean{}}}) {
    const auto e = critical_i1_from_inflation(tests, law);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_TRUE(e.from_membrane);
    EXPECT_EQ(e.first_invariants, paper.first_invariants) << law_name(law);
    EXPECT_EQ(e.pole_first_invariants, paper.first_invariants) << law_name(law);
    EXPECT_EQ(e.largest_i1_radius_fractions, std::vector<double>(4, 0.0)) << law_name(law);
    EXPECT_EQ(e.mean, paper.mean);
  }
  InflationProblem mr;
  mr.material.law = MooneyRivlin{0.1};
  const InflationBurst burst = inflation_burst(mr);
  ASSERT_TRUE(burst.ok()) << burst.message;
  const double stretch = burst.state.pole_stretch;
  const auto e = critical_i1_from_inflation({{0.5, 0.5 * stretch}}, MooneyRivlin{0.1});
  ASSERT_TRUE(e.ok()) << e.message;
  // The burst is located to 1e-8 in I1 (InflationBurst.*); the mark's radius is exact.
  EXPECT_NEAR(e.mean, mr.critical_i1, 1e-6);
  EXPECT_NEAR(e.pole_first_invariants[0], equibiaxial_first_invariant(stretch), 1e-12);
  EXPECT_LT(e.pole_first_invariants[0], 84.0);
  EXPECT_NEAR(e.largest_i1_radius_fractions[0],
              burst.state.max_first_invariant_reference_radius_mm / mr.clamp_radius_mm,
              1e-6);
  EXPECT_GT(e.largest_i1_radius_fractions[0], 0.99);
}

TEST(CriticalI1, RefusesAMarkStretchedBeyondTheLawsLocking) {
  // A mark stretched 5 times (I1 = 50) and the paper's first test (I1 = 89.6, beyond a Gent
  // law locking at 63).
  try {
    critical_i1_from_inflation({{0.5, 2.5}, {0.5, 3.346}}, Gent{60.0});
    FAIL() << "a mark beyond the locking was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("test 2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("locking"), std::string::npos) << e.what();
  }
  EXPECT_THROW(critical_i1_from_inflation({{0.5, 3.0}}, MooneyRivlin{1.5}), InvalidInput);
}

TEST(CriticalI1, TestsFromATable) {
  const auto with_initial =
      parse_numeric_csv("initial_radius_mm,burst_radius_mm\n0.5,3.4\n0.6,4.0\n", "b.csv");
  const auto tests = burst_tests_from_table(with_initial, std::nullopt);
  ASSERT_EQ(tests.size(), 2u);
  EXPECT_EQ(tests[1].initial_radius_mm, 0.6);
  EXPECT_THROW(burst_tests_from_table(with_initial, 0.5), std::invalid_argument);

  const auto burst_only = parse_numeric_csv("burst_radius_mm\n3.4\n3.5\n", "b.csv");
  EXPECT_EQ(burst_tests_from_table(burst_only, 0.5)[1].initial_radius_mm, 0.5);
  EXPECT_THROW(burst_tests_from_table(burst_only, std::nullopt), std::invalid_argument);

  const auto shrunk = parse_numeric_csv("burst_radius_mm\n3.4\n\n0.3\n", "b.csv");
  try {
    burst_tests_from_table(shrunk, 0.5);
    FAIL() << "a shrinking mark was accepted";
  } catch (const CsvError& e) {
    EXPECT_EQ(e.line(), 4);
  }
  const auto negative = parse_numeric_csv("burst_radius_mm\n-3.4\n", "b.csv");
  try {
    burst_tests_from_table(negative, 0.5);
    FAIL() << "a negative radius was accepted";
  } catch (const CsvError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 1);
  }
  EXPECT_THROW(burst_tests_from_table(parse_numeric_csv("radius\n3\n", "b.csv"), 0.5), CsvError);
}

}  // namespace
}  // namespace puncture
