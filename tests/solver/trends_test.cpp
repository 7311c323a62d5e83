// Trends the paper reports (§4.2-4.3, Figs. 12-13): the puncture force grows with the indenter's
// radius and with friction, the stretch under the tip falls as friction grows, and Part II forms
// on a lubricated indenter at large load only.  Each difference checked is far larger than the
// solver's 1e-8 relative accuracy, so the comparisons are strict; each test also requires the
// change to exceed 1e-6 relative (a hundred times that accuracy), so that a trend is not read
// from round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

constexpr double kResolved = 1e-6;  // smallest relative change taken as a trend

// Fig. 13(a)-(d): indenters of radius 1, 2, 3 and 4 mm on the lubricated membrane.
TEST(Trends, PunctureForceRisesWithIndenterRadius) {
  std::vector<double> forces;
  for (double a : {1.0, 2.0, 3.0, 4.0}) {
    Problem p = paper_problem();
    p.indenter = FlatPunch{a};
    const auto punct = predict_puncture(p);
    ASSERT_TRUE(punct.ok()) << "a = " << a << " mm: " << punct.message;
    forces.push_back(punct.force_n);
  }
  double smallest_step = 1e300;
  for (std::size_t k = 1; k < forces.size(); ++k) {
    EXPECT_GT(forces[k], forces[k - 1] * (1.0 + kResolved)) << "radius index " << k;
    smallest_step = std::min(smallest_step, forces[k] / forces[k - 1] - 1.0);
  }
  record("smallest_relative_rise", smallest_step);
  for (std::size_t k = 0; k < forces.size(); ++k)
    record("puncture_force_n_a" + std::to_string(k + 1) + "mm", forces[k]);
}

// §4.3: lubricated (mu' = 0.18) against dry (mu' = 1.95), 2 mm indenter.
TEST(Trends, PunctureForceRisesWithFriction) {
  const auto lubricated = predict_puncture(paper_problem(Gent{125.0}, 0.18));
  const auto dry = predict_puncture(paper_problem(Gent{125.0}, 1.95));
  ASSERT_TRUE(lubricated.ok()) << lubricated.message;
  ASSERT_TRUE(dry.ok()) << dry.message;
  EXPECT_GT(dry.force_n, lubricated.force_n * (1.0 + kResolved));
  record("lubricated_force_n", lubricated.force_n);
  record("dry_force_n", dry.force_n);
}

// Fig. 12(b): at F / (2 pi G H A) = 1 and a / A = 0.08, the equibiaxial stretch under the tip
// falls as the friction coefficient grows (the corner holds the membrane back).
TEST(Trends, PartThreeStretchFallsWithFriction) {
  Problem p = paper_problem();
  ASSERT_DOUBLE_EQ(radius_mm(p.indenter) / p.geometry.clamp_radius_mm, 0.08);
  std::vector<double> stretch;
  const std::vector<double> frictions = {0.0, 0.18, 0.5, 1.0, 1.95, 3.0};
  for (double mu : frictions) {
    p.friction = mu;
    const auto e = solve_at_force(p, force_at(p, 1.0), Stage::Slip);
    ASSERT_TRUE(e.ok()) << "mu' = " << mu << ": " << e.message;
    stretch.push_back(e.part_three_stretch);
  }
  for (std::size_t k = 1; k < stretch.size(); ++k)
    EXPECT_LT(stretch[k], stretch[k - 1] * (1.0 - kResolved))
        << "mu' = " << frictions[k - 1] << " -> " << frictions[k];
  record("lambda_mu0", stretch.front());
  record("lambda_mu0.18", stretch[1]);
  record("lambda_mu1.95", stretch[4]);
}

// Part II (membrane on the indenter's side) appears on the lubricated indenter at large load
// (f = 1, the load of Fig. 12), not at small load (f = 0.05, early in the loading).
TEST(Trends, PartTwoAppearsUnderLubricationAtLargeLoad) {
  const Problem p = paper_problem(Gent{125.0}, 0.18);
  const auto large = solve_at_force(p, force_at(p, 1.0), Stage::Slip);
  const auto small = solve_at_force(p, force_at(p, 0.05), Stage::Slip);
  ASSERT_TRUE(large.ok()) << large.message;
  ASSERT_TRUE(small.ok()) << small.message;
  EXPECT_EQ(large.configuration, Configuration::SlipWithPartTwo) << to_string(large.configuration);
  EXPECT_GT(large.part_two_length_mm, 0.0);
  EXPECT_EQ(small.configuration, Configuration::SlipWithoutPartTwo)
      << to_string(small.configuration);
  EXPECT_EQ(small.part_two_length_mm, 0.0);
  EXPECT_LT(small.corner_slope_rad, kHalfPi);
  record("part_two_length_mm_at_f1", large.part_two_length_mm);
}

}  // namespace
}  // namespace puncture::test
