// The puncture of a later inflated state whose path folds before any puncture (docs/model.md
// §8.1, "Following a fold"): predict_puncture reports the puncture under depth control, the
// loading curve's, with the snap-through on the way.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

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

// The trapezoid rule on points[lo..hi] (hi - lo even, evenly spaced) and on every other one:
// {T_h, T_2h}.
std::array<double, 2> snap_trapezoids(const std::vector<CurvePoint>& q, std::size_t lo,
                                      std::size_t hi) {
  std::array<double, 2> t{0.0, 0.0};
  for (std::size_t i = lo; i < hi; ++i)
    t[0] += 0.5 * (q[i + 1].depth_mm - q[i].depth_mm) * (q[i].force_n + q[i + 1].force_n);
  for (std::size_t i = lo; i + 2 <= hi; i += 2)
    t[1] += 0.5 * (q[i + 2].depth_mm - q[i].depth_mm) * (q[i].force_n + q[i + 2].force_n);
  return t;
}

// The energy to puncture across the snap-through: the area under the path depth control
// follows, the work to the fold, nothing while the probe is clear of the landed membrane (the
// force's drop is dissipated), then the first state's from its touch.  Checked against the
// trapezoid rule on the curve's 201 evenly spaced points to the fold and on the first state's 201
// to its puncture, each with the error bound |T_h - T_2h| (the error of T_h is (T_h - T_2h) / 3
// for a smooth force, 0.55 of it for the square-root end at the fold, F ~ sqrt(fold - depth));
// and the work to the fold alone (the difference from the first state's own energy to puncture,
// its own quadrature from its dome) against the first piece.
TEST(SnapPuncture, TheEnergyToPunctureIsTheAreaUnderThePathDepthControlFollows) {
  const Problem p = snap_middle_state();
  SolverOptions o;
  o.energy_to_puncture = true;
  const PuncturePrediction alone = predict_puncture(p, o);
  ASSERT_TRUE(alone.ok()) << alone.message;
  ASSERT_TRUE(alone.energy_to_puncture_mj.has_value()) << alone.message;
  Problem first = p;
  first.preload.inflated_state = 1;
  const PuncturePrediction on_first = predict_puncture(first, o);
  ASSERT_TRUE(on_first.energy_to_puncture_mj.has_value()) << on_first.message;

  CurveOptions c;
  c.points = 201;
  c.locate_events = false;
  const LoadingCurve curve = loading_curve(p, c, o);
  ASSERT_TRUE(curve.ok()) << curve.message;
  ASSERT_TRUE(curve.puncture.energy_to_puncture_mj.has_value()) << curve.puncture.message;
  const double energy = *alone.energy_to_puncture_mj;
  EXPECT_NEAR(*curve.puncture.energy_to_puncture_mj, energy, 1e-9 * energy);

  // The points: 0..200 to the fold (the last), the landing at the fold's depth (force 0), then
  // the first state's 201 from its touch (force 0) to its puncture.
  const auto& q = curve.points;
  ASSERT_EQ(q.size(), 403u);
  ASSERT_TRUE(curve.puncture.snap_through.has_value());
  EXPECT_EQ(q[200].depth_mm, curve.puncture.snap_through->depth_mm);
  EXPECT_EQ(q[201].force_n, 0.0);
  EXPECT_EQ(q[202].force_n, 0.0);
  const auto to_fold = snap_trapezoids(q, 0, 200), landed = snap_trapezoids(q, 202, 402);
  const double bound_to_fold = std::abs(to_fold[0] - to_fold[1]);
  const double bound_landed = std::abs(landed[0] - landed[1]);
  EXPECT_NEAR(energy, to_fold[0] + landed[0], bound_to_fold + bound_landed);
  const double work_to_fold = energy - *on_first.energy_to_puncture_mj;
  EXPECT_NEAR(work_to_fold, to_fold[0], bound_to_fold);
  EXPECT_GT(work_to_fold, 10.0 * bound_to_fold);  // the check sees the piece
  record("snap_energy_to_puncture_mj", energy);
  record("snap_work_to_fold_mj", work_to_fold);
  record("snap_work_to_fold_trapezoid_mj", to_fold[0]);
  record("snap_work_to_fold_bound_mj", bound_to_fold);
  record("snap_landed_trapezoid_mj", landed[0]);
  record("snap_landed_bound_mj", bound_landed);
}

// A curve at given depths (a fit's) goes through the fold as the even one does: the given depths
// short of the fold, the fold and the landing at its depth, then the given depths beyond, at
// force 0 while the probe is clear of the first state and that state's own beyond.  Its states
// match the even curves' at common depths (to 1e-8 of the force: each point converges to
// curve_tol = 1e-9 from its own predictor), and at a depth of neither the first state's own
// state solved alone at the shifted depth.
TEST(SnapPuncture, ACurveAtGivenDepthsGoesThroughTheFoldAsTheEvenOne) {
  const Problem p = snap_middle_state();
  CurveOptions to_puncture;
  to_puncture.points = 21;
  to_puncture.locate_events = false;
  const LoadingCurve full = loading_curve(p, to_puncture);
  ASSERT_TRUE(full.ok()) << full.message;
  CurveOptions to_depth = to_puncture;
  to_depth.points = 11;
  to_depth.max_depth_mm = 50.0;
  const LoadingCurve even = loading_curve(p, to_depth);
  ASSERT_TRUE(even.ok()) << even.message;
  CurveOptions given;
  given.locate_events = false;
  given.depths_mm = {full.points[5].depth_mm,
                     full.points[10].depth_mm,
                     5.0,
                     10.0,
                     15.0,
                     20.0,
                     22.5,
                     25.0,
                     30.0,
                     35.0,
                     40.0,
                     45.0,
                     50.0};
  const LoadingCurve at = loading_curve(p, given);
  ASSERT_TRUE(at.ok()) << at.message;
  ASSERT_EQ(at.points.size(), given.depths_mm.size() + 2);
  ASSERT_FALSE(at.events.empty());
  const CurveEvent& snap = at.events.front();
  EXPECT_EQ(snap.kind, CurveEventKind::SnapThrough);
  EXPECT_EQ(snap.depth_mm, full.events.front().depth_mm);
  EXPECT_FALSE(at.beyond_fold.empty());
  // The fold, then the landing (the probe clear of the first state: force 0), at its depth.
  EXPECT_EQ(at.points[2].depth_mm, snap.depth_mm);
  EXPECT_EQ(at.points[2].force_n, snap.force_n);
  EXPECT_EQ(at.points[3].depth_mm, snap.depth_mm);
  EXPECT_EQ(at.points[3].force_n, 0.0);
  // Short of the fold: the curve to puncture's states.
  for (const std::size_t i : {0u, 1u}) {
    const CurvePoint& a = at.points[i];
    const CurvePoint& b = full.points[i == 0 ? 5 : 10];
    EXPECT_EQ(a.depth_mm, b.depth_mm);
    EXPECT_NEAR(a.force_n, b.force_n, 1e-8 * b.force_n) << a.depth_mm;
    EXPECT_EQ(a.configuration, b.configuration);
  }
  // Beyond: the even curve's at 5, 10, ..., 50 mm.
  Problem first = p;
  first.preload.inflated_state = 1;
  const double offset_mm = *snap.end_depth_mm;
  int common = 0;
  for (std::size_t i = 4; i < at.points.size(); ++i) {
    const CurvePoint& a = at.points[i];
    EXPECT_EQ(a.depth_mm, given.depths_mm[i - 2]);
    const auto b = std::find_if(even.points.begin() + 2, even.points.end(), [&](const auto& q) {
      return std::abs(q.depth_mm - a.depth_mm) < 1e-12 * a.depth_mm;
    });
    if (b == even.points.end()) {  // 22.5 mm: the first state's own state there
      const Equilibrium alone = solve_at_depth(first, a.depth_mm - offset_mm, Stage::Slip);
      ASSERT_TRUE(alone.ok()) << alone.message;
      EXPECT_NEAR(a.force_n, alone.force_n, 1e-8 * alone.force_n);
      continue;
    }
    ++common;
    if (a.depth_mm <= offset_mm) {
      EXPECT_EQ(a.force_n, 0.0) << a.depth_mm;
      EXPECT_EQ(b->force_n, 0.0) << a.depth_mm;
      continue;
    }
    EXPECT_NEAR(a.force_n, b->force_n, 1e-8 * b->force_n) << a.depth_mm;
    EXPECT_NEAR(a.max_first_invariant, b->max_first_invariant, 1e-8 * b->max_first_invariant);
    EXPECT_EQ(a.configuration, b->configuration) << a.depth_mm;
  }
  EXPECT_EQ(common, 10);
  // The same puncture, the first state's under depth control.
  ASSERT_TRUE(at.puncture.ok()) << at.puncture.message;
  EXPECT_NEAR(at.puncture.force_n, full.puncture.force_n, 1e-9 * full.puncture.force_n);
  EXPECT_NEAR(at.puncture.depth_mm, full.puncture.depth_mm, 1e-9 * full.puncture.depth_mm);
}

}  // namespace
}  // namespace puncture::test
