// The puncture of a later inflated state whose path folds before any puncture (docs/model.md
// §8.1, "Following a fold"): predict_puncture reports the puncture under depth control, the
// loading curve's, with the snap-through on the way.
#include <gtest/gtest.h>

#include <algorithm>

#include "pressurised_support.hpp"
#include "puncture/inflation.hpp"
#include "puncture/loading_curve.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

Problem snap_middle_state() {
  Problem p = pressurised(9e-4, 0.18, SphereTipped{2.0});
  p.preload.inflated_state = 2;
  return p;
}

// The puncture command's solve and the curve's agree: both are the first inflated state's
// puncture search (not the curve's points), shifted by the poles' heights' difference; the
// shift is checked against the two inflated states' own pole heights.  Tolerance 1e-9 relative:
// the curve's points converge to curve_tol = 1e-9, and the puncture is not read from them.
TEST(SnapPuncture, ThePunctureSolveIsTheCurvesUnderDepthControl) {
  const Problem p = snap_middle_state();
  const PuncturePrediction alone = predict_puncture(p);
  ASSERT_TRUE(alone.ok()) << alone.message;
  CurveOptions c;
  c.points = 21;
  const LoadingCurve curve = loading_curve(p, c);
  ASSERT_TRUE(curve.ok()) << curve.message;
  ASSERT_TRUE(curve.puncture.ok()) << curve.puncture.message;
  EXPECT_NEAR(alone.force_n, curve.puncture.force_n, 1e-9 * curve.puncture.force_n);
  EXPECT_NEAR(alone.depth_mm, curve.puncture.depth_mm, 1e-9 * curve.puncture.depth_mm);

  // The snap-through it states is the curve's event.
  ASSERT_TRUE(alone.snap_through.has_value());
  const auto event = std::find_if(curve.events.begin(), curve.events.end(), [](const auto& e) {
    return e.kind == CurveEventKind::SnapThrough;
  });
  ASSERT_NE(event, curve.events.end());
  EXPECT_EQ(alone.snap_through->depth_mm, event->depth_mm);
  EXPECT_EQ(alone.snap_through->force_n, event->force_n);
  ASSERT_TRUE(alone.snap_through->force_after_n.has_value());
  EXPECT_EQ(*alone.snap_through->force_after_n, 0.0);  // the probe leaves the membrane
  EXPECT_NEAR(alone.snap_through->depth_mm, 0.025355, 1e-6);

  // The first state's puncture, shifted by its pole's depth below the middle state's.
  const auto states = inflate_at_pressure(inflation_problem(p), 9e-4).states;
  ASSERT_GE(states.size(), 2u);
  const double offset_mm = states[1].pole_height_mm - states[0].pole_height_mm;
  ASSERT_TRUE(alone.snap_through->end_depth_mm.has_value());
  EXPECT_NEAR(*alone.snap_through->end_depth_mm, offset_mm, 1e-9 * offset_mm);
  Problem first = p;
  first.preload.inflated_state = 1;
  const PuncturePrediction on_first = predict_puncture(first);
  ASSERT_TRUE(on_first.ok()) << on_first.message;
  EXPECT_NEAR(alone.force_n, on_first.force_n, 1e-9 * on_first.force_n);
  EXPECT_NEAR(alone.depth_mm, on_first.depth_mm + offset_mm, 1e-9 * alone.depth_mm);
  EXPECT_NEAR(alone.state.depth_mm, alone.depth_mm, 1e-12 * alone.depth_mm);
  EXPECT_FALSE(on_first.snap_through.has_value());
  record("snap_puncture_force_n", alone.force_n);
  record("snap_puncture_depth_mm", alone.depth_mm);
}

}  // namespace
}  // namespace puncture::test
