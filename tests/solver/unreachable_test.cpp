// Loads and depths the membrane cannot reach: a physical failure that gives the deepest state
// and why, never another state presented as the answer.
#include <gtest/gtest.h>

#include <cmath>
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

// Near a limit load the force search cannot resolve the depth (it grows without bound as the
// force approaches the limit): depth control follows the states there.  Neo-Hookean, frictionless
// sliding: the puncture state found by the force search is reached again by depth.
TEST(UnreachableDepth, DepthControlFollowsTheStatesNearALimitLoad) {
  Problem p = paper_problem(NeoHookean{}, 0.0);
  p.indenter = FlatPunch{4.86};
  p.geometry.thickness_mm = 0.02936;
  p.material.shear_modulus_mpa = 0.6708;
  p.critical_i1 = 118.0;
  const PuncturePrediction sliding = predict_puncture(p);
  ASSERT_TRUE(sliding.ok()) << sliding.message;
  const Equilibrium again = solve_at_depth(p, sliding.depth_mm, Stage::Slip);
  ASSERT_TRUE(again.ok()) << again.message;
  // Two routes to one state: the force agrees to the shooting's accuracy near the plateau
  // (dF/d(depth) ~ 0 there, so the force is insensitive to the depth).
  EXPECT_NEAR(again.force_n / sliding.force_n, 1.0, 1e-8);
  EXPECT_NEAR(again.max_first_invariant, p.critical_i1, 1e-3);
}

// Held until 2.9946 N, this membrane switches at a depth the sliding membrane reaches only just
// below its limit load (the force search alone cannot resolve that depth and took it for
// unreachable; depth control by the Part III stretch reaches it: limit_load_test.cpp).  Sliding,
// it reaches the critical I1 already at a smaller depth, so it punctures on sliding at the
// switch: the sliding state at the switch depth, past the criterion.
TEST(UnreachableDepth, PuncturesOnSlidingAtTheSwitchNearALimitLoad) {
  Problem p = paper_problem(NeoHookean{}, 0.0);
  p.indenter = FlatPunch{4.86};
  p.geometry.thickness_mm = 0.02936;
  p.material.shear_modulus_mpa = 0.6708;
  p.critical_i1 = 118.0;
  const PuncturePrediction sliding_only = predict_puncture(p);
  ASSERT_TRUE(sliding_only.ok()) << sliding_only.message;
  p.stick = {StickRule::Force, 2.9946};
  const StageBoundary b = stick_slip_boundary(p);
  ASSERT_TRUE(b.ok() && b.switches) << b.message;
  // The independent fact behind the answer: sliding reaches the criterion before the switch.
  EXPECT_LT(sliding_only.depth_mm, b.depth_mm);
  const PuncturePrediction at = predict_puncture(p);
  ASSERT_TRUE(at.ok()) << at.message;
  EXPECT_TRUE(at.at_switch);
  EXPECT_EQ(at.stage, Stage::Slip);
  EXPECT_NEAR(at.depth_mm / b.depth_mm, 1.0, 2e-9);
  EXPECT_GT(at.state.max_first_invariant, p.critical_i1);
  // Just below the neo-Hookean frictionless limit load a / A: the ring balance gives
  // f = (a / A) s_eq(L) / L = (a / A) (1 - L^-6) with L the Part III stretch (~262, so 3e-15
  // below the limit, less than the integration's error of ~1e-11 in f).
  const double f_limit = 4.86 / p.geometry.clamp_radius_mm;
  const double l3 = at.part_three_stretch;
  EXPECT_GT(l3, 100.0);
  EXPECT_NEAR(at.normalized_force / (f_limit * (1.0 - std::pow(l3, -6.0))), 1.0, 1e-10);
  EXPECT_GT(at.normalized_force, (1.0 - 1e-3) * f_limit);
  const LoadingCurve c = loading_curve(p, {.points = 8});
  ASSERT_TRUE(c.ok()) << c.message;
  EXPECT_NEAR(c.points.back().depth_mm / b.depth_mm, 1.0, 1e-12);
  EXPECT_EQ(c.points.back().stage, Stage::Slip);
  for (std::size_t i = 0; i + 1 < c.points.size(); ++i)
    EXPECT_FALSE(c.points[i].beyond_puncture) << c.points[i].depth_mm;
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
