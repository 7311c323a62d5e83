// The end of the held (stick) branch: the force at which Part I leaves the indenter's edge
// vertically.  Beyond it a held membrane would wrap the side.  The branch is followed to its end:
// the shooting parameter is the horizontal line tension t at the edge, which goes to zero there
// linearly with the force's distance from the end, while the edge stretch's distance from the
// vertical exit's goes as its square (docs/model.md, "Stick").
#include <gtest/gtest.h>

#include <cmath>

#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

// A held Gent membrane with J_lim = 1000: its branch ends near 37.7 N at I1 = 884.
Problem held_membrane() {
  Problem p = paper_problem(Gent{1000.0});
  p.critical_i1 = 900.0;
  p.stick.rule = StickRule::Always;
  return p;
}

// The end, by bisection on whether a held state exists (to 1e-13 relative).
double branch_end_n(const Problem& p) {
  double lo = 30.0, hi = 45.0;
  EXPECT_TRUE(solve_at_force(p, lo, Stage::Stick).ok());
  EXPECT_EQ(solve_at_force(p, hi, Stage::Stick).status, Status::StickWrapsSide);
  while (hi - lo > 1e-13 * hi) {
    const double mid = 0.5 * (lo + hi);
    (solve_at_force(p, mid, Stage::Stick).ok() ? lo : hi) = mid;
  }
  return lo;
}

TEST(HeldBranchEnd, EveryStateUpToTheEndMeetsTheClampCondition) {
  const Problem p = held_membrane();
  SolverOptions options;
  options.record_fields = false;
  const double end = branch_end_n(p);
  // Below the end by a relative 1e-3 ... 1e-10: the clamp condition is met to the shooting's
  // tolerance (1e-10), not stalled at ~1e-8 as when the shooting was on the edge stretch.
  double slope_gap_prev = 0.0;
  for (const double below : {1e-3, 1e-4, 1e-6, 1e-8, 1e-10}) {
    const Equilibrium e = solve_at_force(p, end * (1.0 - below), Stage::Stick, options);
    ASSERT_TRUE(e.ok()) << below << ": " << e.message;
    EXPECT_LE(e.clamp_residual, 1e-10) << below;
    // Independent of the shooting's parameter: the clamp residual is linear in t at the vertical
    // exit, so the exit slope tends to 90 degrees linearly in the distance: a hundredfold closer,
    // a hundredfold smaller gap (to 1%: measured 100.01, 99.999, 99.90, the last one off by the
    // end's own bisection error, 1e-13 of a distance of 1e-10).
    const double slope_gap = kHalfPi - e.corner_slope_rad;
    EXPECT_GT(slope_gap, 0.0);
    if (below <= 1e-6) {  // steps of 100
      EXPECT_NEAR(slope_gap_prev / slope_gap, 100.0, 1.0) << below;
    }
    slope_gap_prev = slope_gap;
  }
}

// The critical I1 (900) lies beyond the branch's end (884): no puncture, a physical answer
// with the I1 reached, not the numerical failure "the state at puncture did not converge".
TEST(HeldBranchEnd, CriterionBeyondTheEndIsNotReached) {
  const PuncturePrediction at = predict_puncture(held_membrane());
  EXPECT_EQ(at.status, Status::NotReached) << at.message;
  EXPECT_EQ(at.failure_kind(), FailureKind::Physical);
  EXPECT_NE(at.message.find("reaches only 884.1"), std::string::npos) << at.message;
  EXPECT_NE(at.message.find("wrap its side"), std::string::npos) << at.message;
}

}  // namespace
}  // namespace puncture::test
