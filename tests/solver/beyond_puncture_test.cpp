// States and curve points past the puncture point are marked: the model continues there, the
// real membrane does not.
#include <gtest/gtest.h>

#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

TEST(BeyondPuncture, StatesAreMarkedByTheirOwnCriterion) {
  const Problem p = paper_problem();
  const PuncturePrediction at = predict_puncture(p);
  ASSERT_TRUE(at.ok()) << at.message;
  // The puncture state itself is not past puncture (its I1 equals the critical value to ~1e-10).
  EXPECT_FALSE(at.state.beyond_puncture);
  const Equilibrium below = solve_at_force(p, 0.99 * at.force_n, Stage::Slip);
  const Equilibrium above = solve_at_force(p, 1.01 * at.force_n, Stage::Slip);
  ASSERT_TRUE(below.ok() && above.ok());
  EXPECT_FALSE(below.beyond_puncture);
  EXPECT_TRUE(above.beyond_puncture);
  // Independent of the flag's own rule: the largest I1 on either side of the critical value.
  EXPECT_LT(below.max_first_invariant, p.critical_i1);
  EXPECT_GT(above.max_first_invariant, p.critical_i1);
  const Equilibrium deep = solve_at_depth(p, 1.05 * at.depth_mm, Stage::Slip);
  ASSERT_TRUE(deep.ok()) << deep.message;
  EXPECT_TRUE(deep.beyond_puncture);
}

TEST(BeyondPuncture, CurvePointsPastThePunctureDepthAreMarked) {
  const Problem p = paper_problem();
  const LoadingCurve to_puncture = loading_curve(p, {.points = 30});
  ASSERT_TRUE(to_puncture.ok()) << to_puncture.message;
  for (const auto& q : to_puncture.points) EXPECT_FALSE(q.beyond_puncture) << q.depth_mm;
  const double puncture_depth = to_puncture.puncture.depth_mm;
  const LoadingCurve past = loading_curve(p, {.points = 30, .max_depth_mm = 1.2 * puncture_depth});
  ASSERT_TRUE(past.ok()) << past.message;
  int marked = 0;
  for (const auto& q : past.points) {
    EXPECT_EQ(q.beyond_puncture, q.depth_mm > puncture_depth) << q.depth_mm;
    marked += q.beyond_puncture;
  }
  // Depths 1.2 d (k / 29), k = 0..29, past d: k > 29 / 1.2 = 24.2, so k = 25..29.
  EXPECT_EQ(marked, 5);
}

}  // namespace
}  // namespace puncture::test
