// States at and next to the force at which Part II appears (the membrane starts wrapping the
// indenter's side): the two sliding configurations meet there, Part II with zero length.
#include <gtest/gtest.h>

#include <cmath>

#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

double onset_force_n(const Problem& p) {
  CurveOptions curve;
  curve.points = 4;
  curve.max_depth_mm = 200.0;
  const LoadingCurve c = loading_curve(p, curve);
  EXPECT_TRUE(c.part_two_onset_force_n.has_value()) << c.message;
  return c.part_two_onset_force_n.value_or(0.0);
}

// With friction the shooting parameter of Part II's configuration is bracketed up to the onset
// stretch, where the root lies at the onset force itself: the cap must be tried, not only
// approached by halving (which failed with "found no parameter meeting the clamp condition").
// The states an ulp-scale distance either side are the same state: depth and Part III stretch
// continuous to 1e-9 relative (the shooting's accuracy), Part II's length zero at the onset.
TEST(PartTwoOnset, StatesAtAndAroundTheOnsetForceConverge) {
  for (const double friction : {0.18, 3.0}) {
    const Problem p = paper_problem(Gent{125.0}, friction);
    const double onset = onset_force_n(p);
    SolverOptions options;
    options.record_fields = false;
    const Equilibrium at = solve_at_force(p, onset, Stage::Slip, options);
    ASSERT_TRUE(at.ok()) << friction << ": " << at.message;
    EXPECT_LE(at.part_two_length_mm, 1e-6 * p.geometry.clamp_radius_mm) << friction;
    for (const double rel : {-1e-10, -1e-12, 1e-12, 1e-10}) {
      const Equilibrium e = solve_at_force(p, onset * (1.0 + rel), Stage::Slip, options);
      ASSERT_TRUE(e.ok()) << friction << ' ' << rel << ": " << e.message;
      EXPECT_NEAR(e.depth_mm / at.depth_mm, 1.0, 1e-9) << friction << ' ' << rel;
      EXPECT_NEAR(e.part_three_stretch / at.part_three_stretch, 1.0, 1e-9)
          << friction << ' ' << rel;
    }
  }
}

}  // namespace
}  // namespace puncture::test
