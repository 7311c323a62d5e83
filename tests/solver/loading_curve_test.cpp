// The displacement-controlled loading curve and the puncture point: monotonicity, continuity
// through the onset of Part II, the force drop at the stick -> slip switch, the puncture
// criterion at the end of the curve, and the puncture force found by two independent routes.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "indentation/scaled_problem.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

Problem with_stick(Problem p, StickRule rule, double threshold = 0.0) {
  p.stick = {rule, threshold};
  return p;
}

struct CurveCase {
  std::string name;
  Problem problem;
};
void PrintTo(const CurveCase& c, std::ostream* os) { *os << c.name; }
std::string curve_case_name(const ::testing::TestParamInfo<CurveCase>& info) {
  return info.param.name;
}

const std::vector<CurveCase> kCurves = {
    {"Lubricated", paper_problem()},
    {"Dry", paper_problem(Gent{125.0}, 1.95)},
    {"Frictionless", paper_problem(Gent{125.0}, 0.0)},
    {"HeldUntilForce", with_stick(paper_problem(), StickRule::Force, 0.3)},
    {"AlwaysHeld", with_stick(paper_problem(), StickRule::Always)},
    {"NeoHookean", paper_problem(NeoHookean{})},
    {"MooneyRivlin", paper_problem(MooneyRivlin{0.2})},
    {"Yeoh", paper_problem(Yeoh{0.05, 0.001})},
    // Ogden's (1972) three-term fit to Treloar (mu_p / G), Arruda-Boyce, Gent-Gent
    {"Ogden",
     paper_problem(std::get<Ogden>(ogden_material({0.63, 0.0012, -0.01}, {1.3, 5.0, -2.0}).law))},
    {"ArrudaBoyce", paper_problem(ArrudaBoyce{50.0})},
    {"GentGent", paper_problem(GentGent{125.0, 0.2})},
};

class Curve : public ::testing::TestWithParam<CurveCase> {
 protected:
  void SetUp() override {
    curve_ = loading_curve(GetParam().problem);
    ASSERT_TRUE(curve_.ok()) << curve_.message;
    ASSERT_TRUE(curve_.puncture.ok()) << curve_.puncture.message;
    ASSERT_GE(curve_.points.size(), 200u);
  }
  LoadingCurve curve_;
};
INSTANTIATE_TEST_SUITE_P(LoadingCurve, Curve, ::testing::ValuesIn(kCurves), curve_case_name);

// Depth never decreases along the curve (the only repeated depth is the stick -> slip switch,
// recorded in both stages), and within each stage the force strictly increases with depth: the
// smallest relative force step between neighbouring points (measured: 2.7e-3) is far above the
// 1e-8 relative accuracy of a point.
TEST_P(Curve, DepthAndForceIncreaseWithinEachStage) {
  const auto& pts = curve_.points;
  EXPECT_EQ(pts.front().depth_mm, 0.0);
  EXPECT_EQ(pts.front().force_n, 0.0);
  int repeated = 0;
  for (std::size_t k = 1; k < pts.size(); ++k) {
    const auto &prev = pts[k - 1], &cur = pts[k];
    if (cur.stage != prev.stage) {
      EXPECT_EQ(prev.stage, Stage::Stick);
      EXPECT_EQ(cur.stage, Stage::Slip);
      EXPECT_EQ(cur.depth_mm, prev.depth_mm) << "the switch is recorded at one depth";
      ++repeated;
      continue;
    }
    EXPECT_GT(cur.depth_mm, prev.depth_mm) << "point " << k;
    EXPECT_GT(cur.force_n, prev.force_n) << "point " << k << " at depth " << cur.depth_mm;
  }
  EXPECT_EQ(repeated, curve_.stick_slip.occurs ? 1 : 0);
}

// The curve ends at puncture: its last point is at the puncture depth, where the largest I1
// equals the critical value to 1e-6 (1e-8 relative).  The curve solves its last point at the
// puncture depth to Newton residuals of 1e-9; I1 then misses I1c by at most 2e-8 on the Gent
// curves and by 4e-7 on the neo-Hookean one, where near puncture I1 grows ~17 times faster than
// the force (see the 0.1% bracket below).
TEST_P(Curve, EndsAtPuncture) {
  const auto& last = curve_.points.back();
  const double i1c = GetParam().problem.critical_i1;
  EXPECT_NEAR(last.max_first_invariant, i1c, 1e-6);
  EXPECT_NEAR(last.depth_mm, curve_.puncture.depth_mm, 1e-12 * last.depth_mm);
  EXPECT_NEAR(last.force_n, curve_.puncture.force_n, 1e-8 * last.force_n);
  EXPECT_EQ(last.stage, curve_.puncture.stage);
  for (std::size_t k = 0; k + 1 < curve_.points.size(); ++k)
    EXPECT_LT(curve_.points[k].max_first_invariant, i1c) << "I1c reached before the end";
  record("last_i1_minus_i1c", last.max_first_invariant - i1c);
}

// The puncture force is the first force at which max I1 reaches I1c: bracketed by equilibria at
// 0.999 and 1.001 of it in the puncture's stage (a 0.1% change in force moves I1 by ~0.1%, far
// above the solver's 1e-8 accuracy).
TEST_P(Curve, PunctureForceIsBracketed) {
  const Problem& p = GetParam().problem;
  const auto& punct = curve_.puncture;
  const auto below = solve_at_force(p, 0.999 * punct.force_n, punct.stage);
  const auto above = solve_at_force(p, 1.001 * punct.force_n, punct.stage);
  ASSERT_TRUE(below.ok()) << below.message;
  EXPECT_LT(below.max_first_invariant, p.critical_i1);
  // Above the puncture force the state may lie beyond locking; if it exists, I1 exceeds I1c.
  if (above.ok()) {
    EXPECT_GT(above.max_first_invariant, p.critical_i1);
  } else {
    EXPECT_EQ(above.status, Status::BeyondLocking) << above.message;
  }
  EXPECT_NEAR(punct.state.max_first_invariant, p.critical_i1, 1e-6);
  record("i1_below", below.max_first_invariant);
  record("i1_above", above.max_first_invariant);
}

// Part II appears continuously on the sliding branch: at depths onset -/+ d, the forces from
// solve_at_depth (in the configurations without and with Part II) differ by no more than the
// curve's slope times 2d.  A jump J would instead show as |dF| / (2 d) ~ J / (2 d), growing as d
// shrinks; d goes down to 1e-4 mm, where the slope term (~1e-5 N) still dwarfs the 1e-8 relative
// accuracy of a force (~1e-9 N).  The bound is twice the largest secant slope of the curve around
// the onset.  The force at the onset depth must equal the reported onset force (1e-8 relative).
TEST(LoadingCurvePartTwo, OnsetIsContinuous) {
  const Problem p = paper_problem();
  const auto curve = loading_curve(p);
  ASSERT_TRUE(curve.ok()) << curve.message;
  ASSERT_TRUE(curve.part_two_onset_depth_mm && curve.part_two_onset_force_n);
  const double onset = *curve.part_two_onset_depth_mm;
  // Largest secant slope dF/ddepth of the curve within 2 mm of the onset.
  double slope = 0.0;
  for (std::size_t k = 1; k < curve.points.size(); ++k) {
    const auto &a = curve.points[k - 1], &b = curve.points[k];
    if (b.depth_mm < onset - 2.0 || a.depth_mm > onset + 2.0) continue;
    slope = std::max(slope, (b.force_n - a.force_n) / (b.depth_mm - a.depth_mm));
  }
  ASSERT_GT(slope, 0.0);
  // Configurations along the curve switch at the onset depth.
  for (const auto& pt : curve.points) {
    if (pt.depth_mm == 0.0) continue;
    EXPECT_EQ(
        pt.configuration,
        pt.depth_mm < onset ? Configuration::SlipWithoutPartTwo : Configuration::SlipWithPartTwo)
        << "depth " << pt.depth_mm;
  }
  const auto at = solve_at_depth(p, onset, Stage::Slip);
  ASSERT_TRUE(at.ok()) << at.message;
  EXPECT_NEAR(at.force_n, *curve.part_two_onset_force_n, 1e-8 * at.force_n);
  double worst = 0.0;
  for (double d : {1e-1, 1e-2, 1e-3, 1e-4}) {
    const auto lo = solve_at_depth(p, onset - d, Stage::Slip);
    const auto hi = solve_at_depth(p, onset + d, Stage::Slip);
    ASSERT_TRUE(lo.ok() && hi.ok()) << lo.message << " / " << hi.message;
    EXPECT_EQ(lo.configuration, Configuration::SlipWithoutPartTwo) << "d = " << d;
    EXPECT_EQ(hi.configuration, Configuration::SlipWithPartTwo) << "d = " << d;
    const double jump = hi.force_n - lo.force_n;
    EXPECT_GT(jump, 0.0) << "d = " << d;
    EXPECT_LE(jump, 2.0 * slope * 2.0 * d) << "d = " << d << " mm";
    worst = std::max(worst, jump / (2.0 * slope * 2.0 * d));
  }
  record("worst_jump_over_bound", worst);
  record("onset_depth_mm", onset);
}

// The stick -> slip switch under the force rule (held until 0.3 N): under displacement control
// the force drops from the held to the sliding state at the switch depth, the held state carries
// the threshold force there, and the sliding state is the slip-stage equilibrium at that depth
// (solve_at_depth, an independent bracketing solve; the curve's point comes from its Newton
// continuation): 1e-8 relative, the accuracy of each.
TEST(LoadingCurveStickSlip, ForceDropsAtSwitchToTheSlidingState) {
  const Problem p = with_stick(paper_problem(), StickRule::Force, 0.3);
  const auto curve = loading_curve(p);
  ASSERT_TRUE(curve.ok()) << curve.message;
  const auto& sw = curve.stick_slip;
  ASSERT_TRUE(sw.occurs);
  EXPECT_NEAR(sw.force_stuck_n, 0.3, 1e-12);
  EXPECT_LT(sw.force_sliding_n, sw.force_stuck_n);
  const auto held = solve_at_depth(p, sw.depth_mm, Stage::Stick);
  const auto sliding = solve_at_depth(p, sw.depth_mm, Stage::Slip);
  ASSERT_TRUE(held.ok()) << held.message;
  ASSERT_TRUE(sliding.ok()) << sliding.message;
  EXPECT_NEAR(held.force_n, sw.force_stuck_n, 1e-8 * sw.force_stuck_n);
  EXPECT_NEAR(sliding.force_n, sw.force_sliding_n, 1e-8 * sw.force_sliding_n);
  // The two curve points at the switch depth.
  std::optional<CurvePoint> stuck_point, sliding_point;
  for (std::size_t k = 1; k < curve.points.size(); ++k)
    if (curve.points[k - 1].stage == Stage::Stick && curve.points[k].stage == Stage::Slip) {
      stuck_point = curve.points[k - 1];
      sliding_point = curve.points[k];
    }
  ASSERT_TRUE(stuck_point && sliding_point);
  EXPECT_EQ(stuck_point->depth_mm, sw.depth_mm);
  EXPECT_EQ(sliding_point->depth_mm, sw.depth_mm);
  EXPECT_NEAR(stuck_point->force_n, held.force_n, 1e-8 * held.force_n);
  EXPECT_NEAR(sliding_point->force_n, sliding.force_n, 1e-8 * sliding.force_n);
  EXPECT_EQ(sliding_point->configuration, sliding.configuration);
  // The stretch is converged with the force; 1e-7 allows it ten times the force's sensitivity.
  EXPECT_NEAR(sliding_point->part_three_stretch,
              sliding.part_three_stretch,
              1e-7 * sliding.part_three_stretch);
  // The boundary reported on its own agrees.
  const auto boundary = stick_slip_boundary(p);
  ASSERT_EQ(boundary.status, Status::Converged) << boundary.message;
  EXPECT_TRUE(boundary.switches);
  EXPECT_EQ(boundary.first_stage, Stage::Stick);
  EXPECT_EQ(boundary.depth_mm, sw.depth_mm);
  record("force_drop_n", sw.force_stuck_n - sw.force_sliding_n);
  record("sliding_force_relative_error", std::abs(sliding.force_n / sw.force_sliding_n - 1.0));
}

// A membrane held so long that the sliding state at the switch depth is already past the
// critical I1 punctures at the switch: the curve then ends with the switch (the held and the
// sliding state at the switch depth), and LoadingCurve::stick_slip says the switch occurs.  Held
// until 45 mm or until 2 N (the default membrane slides to its puncture at 38 mm, 0.70 N).
// Whether this is the case is checked independently: at the switch depth (stick_slip_boundary)
// the held state (solve_at_depth) is below the critical I1 and the sliding one above it.  The
// forces are each converged to 1e-8 relative, the switch depth is the boundary's own value and
// the puncture's depth comes from the bracketing solve at that depth (TOMS 748 on the force to a
// few ulps, with dF/ddepth ~ F/depth): 1e-9 relative is ample.
class PunctureAtSwitch : public ::testing::TestWithParam<CurveCase> {};

TEST_P(PunctureAtSwitch, CurveEndsWithTheSwitchAndReportsIt) {
  const Problem& p = GetParam().problem;
  const auto boundary = stick_slip_boundary(p);
  ASSERT_EQ(boundary.status, Status::Converged) << boundary.message;
  ASSERT_TRUE(boundary.switches);
  const auto held = solve_at_depth(p, boundary.depth_mm, Stage::Stick);
  const auto sliding = solve_at_depth(p, boundary.depth_mm, Stage::Slip);
  ASSERT_TRUE(held.ok()) << held.message;
  ASSERT_TRUE(sliding.ok()) << sliding.message;
  ASSERT_LT(held.max_first_invariant, p.critical_i1);
  ASSERT_GT(sliding.max_first_invariant, p.critical_i1);

  const auto curve = loading_curve(p, {.points = 20});
  ASSERT_TRUE(curve.ok()) << curve.message;
  ASSERT_TRUE(curve.puncture.ok()) << curve.puncture.message;
  EXPECT_EQ(curve.puncture.stage, Stage::Slip);
  EXPECT_NEAR(curve.puncture.depth_mm, boundary.depth_mm, 1e-9 * boundary.depth_mm);
  EXPECT_NEAR(curve.puncture.force_n, sliding.force_n, 1e-8 * sliding.force_n);

  const auto& sw = curve.stick_slip;
  EXPECT_TRUE(sw.occurs);
  EXPECT_EQ(sw.depth_mm, boundary.depth_mm);
  EXPECT_NEAR(sw.force_stuck_n, held.force_n, 1e-8 * held.force_n);
  EXPECT_NEAR(sw.force_sliding_n, sliding.force_n, 1e-8 * sliding.force_n);

  // The last two points: held, then sliding, both at the switch depth; the last one is the
  // puncture.
  ASSERT_GE(curve.points.size(), 2u);
  const auto& before = curve.points[curve.points.size() - 2];
  const auto& last = curve.points.back();
  EXPECT_EQ(before.stage, Stage::Stick);
  EXPECT_EQ(last.stage, Stage::Slip);
  EXPECT_EQ(before.depth_mm, sw.depth_mm);
  EXPECT_EQ(last.depth_mm, sw.depth_mm);
  EXPECT_NEAR(before.force_n, held.force_n, 1e-8 * held.force_n);
  EXPECT_NEAR(last.force_n, curve.puncture.force_n, 1e-8 * curve.puncture.force_n);
  EXPECT_EQ(last.force_n, sw.force_sliding_n);
  // Every point before the switch is held, and the switch is the only repeated depth.
  for (std::size_t k = 0; k + 1 < curve.points.size(); ++k) {
    EXPECT_EQ(curve.points[k].stage, Stage::Stick) << "point " << k;
    if (k > 0 && k + 1 < curve.points.size() - 1)
      EXPECT_GT(curve.points[k].depth_mm, curve.points[k - 1].depth_mm) << "point " << k;
  }
}

// The same for every number of points: the last grid depth is the switch depth itself, never
// an ulp below it (where it would be a held point, and the switch would be lost).
TEST_P(PunctureAtSwitch, EveryGridEndsWithTheSwitch) {
  const Problem& p = GetParam().problem;
  for (int n = 2; n <= 24; ++n) {
    SCOPED_TRACE(n);
    const auto curve = loading_curve(p, {.points = n});
    ASSERT_TRUE(curve.ok()) << curve.message;
    ASSERT_TRUE(curve.stick_slip.occurs);
    ASSERT_EQ(curve.points.size(), static_cast<std::size_t>(n + 1));
    const auto& before = curve.points[n - 1];
    const auto& last = curve.points[n];
    EXPECT_EQ(before.stage, Stage::Stick);
    EXPECT_EQ(last.stage, Stage::Slip);
    EXPECT_EQ(before.depth_mm, curve.stick_slip.depth_mm);
    EXPECT_EQ(last.depth_mm, curve.stick_slip.depth_mm);
  }
}

INSTANTIATE_TEST_SUITE_P(
    LoadingCurveStickSlip, PunctureAtSwitch,
    ::testing::Values(
        CurveCase{"HeldToDepth45", with_stick(paper_problem(), StickRule::Depth, 45.0)},
        CurveCase{"HeldToForce2", with_stick(paper_problem(), StickRule::Force, 2.0)}),
    curve_case_name);

// Two independent routes to the puncture with the crack at the corner: the direct solve at the
// corner (detail::direct_puncture: corner state from the capstan condition and I1 = I1c, then
// a shooting on the force) and a root search of max I1 - I1c along the loading path
// (detail::solve_scaled at increasing force, bracketed by a scan and refined with TOMS 748 to
// ~1e-14).  Each solve meets the clamp to 1e-10; max I1 is located to the integration accuracy:
// the two forces agree to 1e-7 relative.
struct RouteCase {
  std::string name;
  Problem problem;
};
void PrintTo(const RouteCase& c, std::ostream* os) { *os << c.name; }

class PunctureRoutes : public ::testing::TestWithParam<RouteCase> {};

Problem with_indenter(Problem p, double a) {
  p.indenter = FlatPunch{a};
  return p;
}

INSTANTIATE_TEST_SUITE_P(
    LoadingCurve, PunctureRoutes,
    ::testing::Values(RouteCase{"Lubricated", paper_problem()},
                      RouteCase{"Dry", paper_problem(Gent{125.0}, 1.95)},
                      RouteCase{"Frictionless", paper_problem(Gent{125.0}, 0.0)},
                      RouteCase{"SmallIndenter", with_indenter(paper_problem(), 1.0)},
                      RouteCase{"LargeIndenter", with_indenter(paper_problem(), 4.0)},
                      RouteCase{"NeoHookean", paper_problem(NeoHookean{})}),
    [](const auto& info) { return info.param.name; });

TEST_P(PunctureRoutes, DirectCornerSolveAgreesWithPathSearch) {
  const Problem& p = GetParam().problem;
  SolverOptions o;
  o.record_fields = false;
  const auto direct = detail::direct_puncture(p, o);
  ASSERT_TRUE(direct.has_value()) << "the crack is expected at the corner";
  ASSERT_TRUE(direct->ok()) << direct->message;
  EXPECT_EQ(direct->configuration, Configuration::SlipWithPartTwo);
  EXPECT_NEAR(detail::max_first_invariant_of(*direct), p.critical_i1, 1e-7 * p.critical_i1);

  auto excess = [&](double f) {
    const auto s = detail::solve_scaled(p, f, Stage::Slip, o);
    // Past locking the state does not exist: that is beyond the puncture.
    if (!s.ok()) return s.status == Status::BeyondLocking ? 1.0 : std::nan("");
    return detail::max_first_invariant_of(s) - p.critical_i1;
  };
  // Scan up the loading path (force grows with depth in the slip stage) for the first crossing.
  double f_lo = 0.0, f_hi = 0.0, g_lo = 3.0 - p.critical_i1, g_hi = g_lo;
  for (double f = 0.01; f < 100.0; f *= 1.25) {
    const double g = excess(f);
    ASSERT_FALSE(std::isnan(g)) << "no equilibrium at f = " << f;
    if (g >= 0.0) {
      f_hi = f;
      g_hi = g;
      break;
    }
    f_lo = f;
    g_lo = g;
  }
  ASSERT_GT(f_hi, 0.0) << "max I1 never reaches I1c";
  std::uintmax_t iterations = 100;
  const auto bracket = boost::math::tools::toms748_solve(
      excess, f_lo, f_hi, g_lo, g_hi, boost::math::tools::eps_tolerance<double>(45), iterations);
  const double f_path = 0.5 * (bracket.first + bracket.second);
  EXPECT_NEAR(direct->f / f_path, 1.0, 1e-7);
  record("relative_difference", std::abs(direct->f / f_path - 1.0));
}

}  // namespace
}  // namespace puncture::test
