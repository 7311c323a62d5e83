// Loads and depths the membrane cannot reach: a physical failure that gives the deepest state
// and why, never another state presented as the answer.
#include <gtest/gtest.h>

#include <string>

#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A Gent membrane pushed ever deeper ends where the material locks: the depth search must stop
// there and say so, with the deepest state's depth, rather than return that state for any depth.
TEST(UnreachableDepth, GentEndsAtLockingWithTheDeepestState) {
  const Problem p = paper_problem();
  const Equilibrium far = solve_at_depth(p, 1e6, Stage::Slip);
  EXPECT_EQ(far.status, Status::BeyondLocking) << far.message;
  EXPECT_EQ(far.failure_kind(), FailureKind::Physical);
  EXPECT_TRUE(contains(far.message, "cannot be reached")) << far.message;
  EXPECT_TRUE(contains(far.message, "deepest equilibrium")) << far.message;
  // Independent criterion for "the deepest state": its largest I1 is at the locking value
  // 3 + J_lim (the bracket closes within a few ulps of the force where states stop existing;
  // I1 then lies within 1e-3 relative of locking, as I1 rises steeply near the end).
  const double locking_i1 = 3.0 + 125.0;
  EXPECT_NEAR(far.max_first_invariant / locking_i1, 1.0, 1e-3);
  EXPECT_GT(far.depth_mm, 100.0);
  EXPECT_LT(far.depth_mm, 1e6);
  // Any depth short of the deepest is reached, to the search's tolerance.
  const Equilibrium near = solve_at_depth(p, 0.9 * far.depth_mm, Stage::Slip);
  ASSERT_TRUE(near.ok()) << near.message;
  EXPECT_NEAR(near.depth_mm / (0.9 * far.depth_mm), 1.0, 1e-8);
}

// A law without locking ends at a limit load: the force cannot grow past a maximum.
TEST(UnreachableDepth, NeoHookeanEndsAtItsLimitLoad) {
  const Problem p = paper_problem(NeoHookean{});
  const Equilibrium far = solve_at_depth(p, 1e6, Stage::Slip);
  EXPECT_EQ(far.status, Status::LimitLoad) << far.message;
  EXPECT_EQ(far.failure_kind(), FailureKind::Physical);
  EXPECT_TRUE(contains(far.message, "limit load")) << far.message;
  // The same limit under force control: just above the deepest state's force there is none.
  const Equilibrium above = solve_at_force(p, 1.01 * far.force_n, Stage::Slip);
  EXPECT_EQ(above.status, Status::LimitLoad) << above.message;
  const Equilibrium below = solve_at_force(p, 0.9 * far.force_n, Stage::Slip);
  EXPECT_TRUE(below.ok()) << below.message;
}

TEST(UnreachableForce, GentBeyondLockingIsPhysical) {
  const Equilibrium e = solve_at_force(paper_problem(), 1e8, Stage::Slip);
  EXPECT_EQ(e.status, Status::BeyondLocking) << e.message;
  EXPECT_EQ(e.failure_kind(), FailureKind::Physical);
}

TEST(FailureKinds, EveryStatusHasOne) {
  EXPECT_EQ(failure_kind(Status::Converged), FailureKind::None);
  EXPECT_EQ(failure_kind(Status::NoConvergence), FailureKind::Numerical);
  for (Status s :
       {Status::BeyondLocking, Status::LimitLoad, Status::StickWrapsSide, Status::NotReached})
    EXPECT_EQ(failure_kind(s), FailureKind::Physical) << to_string(s);
  EXPECT_EQ(failure_kind(Status::OutsideModel), FailureKind::OutsideModel);
  EXPECT_EQ(to_token(FailureKind::Physical), "physical");
  EXPECT_EQ(to_token(FailureKind::Numerical), "numerical");
}

}  // namespace
}  // namespace puncture::test
