// The pressure maximum (limit point) of the inflation curve, and its minimum where the law
// stiffens again.
#include <cmath>

#include "inflation_test_support.hpp"

namespace puncture {
namespace {

using test::membrane;
using test::solved;

PressureExtremum only_maximum(const InflationProblem& p, double end) {
  const auto e = pressure_extrema(p, end);
  EXPECT_TRUE(e.ok()) << e.message;
  std::vector<PressureExtremum> maxima;
  for (const auto& x : e.extrema)
    if (x.kind == ExtremumKind::Maximum) maxima.push_back(x);
  EXPECT_EQ(maxima.size(), 1u);
  return maxima.empty() ? PressureExtremum{} : maxima.front();
}

TEST(InflationLimitPoint, NeoHookeanPressureHasOneMaximumWithZeroSlope) {
  const auto p = membrane(NeoHookean{});
  const auto e = pressure_extrema(p, 6.0);
  ASSERT_TRUE(e.ok()) << e.message;
  ASSERT_EQ(e.extrema.size(), 1u);  // no re-stiffening: the pressure falls for ever after
  const auto& max = e.extrema.front();
  EXPECT_EQ(max.kind, ExtremumKind::Maximum);
  EXPECT_LT(max.curvature_mpa, 0.0);
  const double l = max.state.pole_stretch;
  test::record("neo_hookean_limit_pole_stretch", l);
  test::record("neo_hookean_limit_normalized_pressure", max.state.normalized_pressure);
  // A second, independent evaluation: states a little either side, solved on their own.
  // With delta = 1e-3 the central difference of a smooth maximum is P''' delta^2 / 6 ~ 1e-7
  // of P'', so a slope below 1e-5 |P''| places the maximum within 1e-5 of the located stretch
  // (the scan's spacing is 0.08: a plain scan would miss by up to 0.04).
  const double delta = 1e-3;
  const auto left = solved(p, l - delta), right = solved(p, l + delta);
  EXPECT_LT(left.pressure_mpa, max.state.pressure_mpa);
  EXPECT_LT(right.pressure_mpa, max.state.pressure_mpa);
  const double slope = (right.pressure_mpa - left.pressure_mpa) / (2.0 * delta);
  const double curvature =
      (right.pressure_mpa - 2.0 * max.state.pressure_mpa + left.pressure_mpa) / (delta * delta);
  EXPECT_LT(std::abs(slope), 1e-5 * std::abs(curvature));
  EXPECT_NEAR(curvature / max.curvature_mpa, 1.0, 1e-3);  // the second derivative, twice
  test::record("neo_hookean_limit_offset", std::abs(slope / curvature));
}

TEST(InflationLimitPoint, GentWithLargeJlimApproachesTheNeoHookeanLimitPoint) {
  const auto nh = only_maximum(membrane(NeoHookean{}), 4.0);
  double previous = INFINITY;
  for (const double j_lim : {1e3, 1e4, 1e5}) {
    SCOPED_TRACE(j_lim);
    const auto gent = only_maximum(membrane(Gent{j_lim}), 4.0);
    // Gent stiffens by a relative (I1 - 3) / J_lim at the limit point (I1 - 3 ~ 7): the
    // shift of the limit point shrinks like 1 / J_lim, tenfold per decade (at least 5x).
    const double shift = std::abs(gent.state.pole_stretch - nh.state.pole_stretch);
    EXPECT_LT(shift, previous / 5.0);
    EXPECT_GT(gent.state.pressure_mpa, nh.state.pressure_mpa);  // Gent is stiffer
    EXPECT_LT(gent.state.pressure_mpa / nh.state.pressure_mpa - 1.0, 30.0 / j_lim);
    previous = shift;
  }
  EXPECT_LT(previous, 1e-3);  // J_lim = 1e5
}

TEST(InflationLimitPoint, GentStiffensAgainAfterItsMaximum) {
  // The paper's Gent (J_lim = 125): a maximum, then a minimum before the burst.
  const auto c = inflation_curve(membrane(Gent{125.0}), {.points = 20});
  ASSERT_TRUE(c.ok()) << c.message;
  ASSERT_EQ(c.extrema.size(), 2u);
  EXPECT_EQ(c.extrema[0].kind, ExtremumKind::Maximum);
  EXPECT_EQ(c.extrema[1].kind, ExtremumKind::Minimum);
  EXPECT_LT(c.extrema[0].state.pole_stretch, c.extrema[1].state.pole_stretch);
  EXPECT_GT(c.extrema[0].state.pressure_mpa, c.extrema[1].state.pressure_mpa);
  EXPECT_GT(c.extrema[1].curvature_mpa, 0.0);
  // Every state of the curve lies between the extrema's pressures where it should.
  for (const auto& s : c.states) {
    if (s.pole_stretch < c.extrema[0].state.pole_stretch)
      EXPECT_LE(s.pressure_mpa, c.extrema[0].state.pressure_mpa);
    else if (s.pole_stretch < c.extrema[1].state.pole_stretch)
      EXPECT_GE(s.pressure_mpa, c.extrema[1].state.pressure_mpa);
  }
  for (const auto& e : c.extrema) {
    // The located slope, in units of the local curvature times the pole stretch, is below
    // the four-point difference's noise (the pressures are solved to 1e-12).
    EXPECT_LT(std::abs(e.pressure_slope_mpa), 1e-6 * std::abs(e.curvature_mpa));
  }
}

TEST(InflationLimitPoint, AMaximumInsideTheLastScanIntervalIsFound) {
  // The paper's Gent (J_lim = 125) up to pole stretch 2.4 with a coarse scan of 8 stretches
  // (step 0.175): its maximum lies between the last two scanned stretches, 2.225 and 2.4, and
  // the pressure at 2.4 is still above the one at 2.225, so the scanned pressures rise
  // monotonically and only the slope at the end of the range shows the maximum.
  const auto p = membrane(Gent{125.0});
  const double end = 2.4;
  const int scan = 8;
  const double last_scanned = 1.0 + (end - 1.0) * (scan - 1) / scan;
  // The reference: the same maximum located with the default, fine scan of a longer range,
  // where it lies well inside.
  const auto reference = only_maximum(p, 3.0);
  ASSERT_GT(reference.state.pole_stretch, last_scanned);
  ASSERT_LT(reference.state.pole_stretch, end);
  ASSERT_GT(solved(p, end).pressure_mpa, solved(p, last_scanned).pressure_mpa);

  const auto coarse = pressure_extrema(p, end, scan);
  ASSERT_TRUE(coarse.ok()) << coarse.message;
  ASSERT_EQ(coarse.extrema.size(), 1u);
  const auto& max = coarse.extrema.front();
  EXPECT_EQ(max.kind, ExtremumKind::Maximum);
  EXPECT_LT(max.curvature_mpa, 0.0);
  // Both are roots of a difference approximation of dp/dl0: the reference's central one with h
  // = 0.0083 (error ~ h^4 P^(5) / 30), the coarse scan's backward one in its last interval
  // with h = 0.011 (error ~ h^4 P^(5) / 5).  With h^4 ~ 1e-8 and P^(5) / P'' of order 10 to
  // 100, each root is off by ~1e-7 at most in pole stretch: 1e-6 leaves a margin.
  EXPECT_NEAR(max.state.pole_stretch, reference.state.pole_stretch, 1e-6);
  EXPECT_NEAR(max.state.pressure_mpa / reference.state.pressure_mpa, 1.0, 1e-9);
}

}  // namespace
}  // namespace puncture
