// Paths on inflated domes beyond a hemisphere at a held pressure (docs/model.md §8.1, §17): the
// 2 mm sphere at 0.9 kPa, whose path ended at 16.27 mm (14.02 mm frictionless), has no fold there:
// its contact reaches the sphere's equator and goes on down the side, the force rising all the
// way to the puncture; and a later inflated state (the balloon, state 3 of 3 at 0.9 kPa) indented
// in depth control from its own dome.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "pressurised_support.hpp"
#include "puncture/inflation.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

constexpr double kNearLimitPointMpa = 9e-4;  // three inflated states, the first overhanging

Problem sphere_near_limit_point(double friction) {
  return pressurised(kNearLimitPointMpa, friction, SphereTipped{2.0});
}

// The loading curve to 20 mm (friction 0.18; 16 mm frictionless) in steps of 0.25 mm: the force
// rises at every point (no fold, no force maximum: no event), the contact stays on the cap
// (corner slope below pi/2, growing) up to the onset the curve reports and runs down the side
// past it (its length growing from zero).  The onset's depth is where the corner slope of the
// last two cap points, extrapolated linearly, reaches pi/2 (within 0.01 mm: the slope's
// curvature over 0.25 mm), and its force lies between theirs and the next point's.
TEST(OverhangingPaths, TheSpheresContactReachesItsEquatorWithoutAFold) {
  for (const auto& [friction, end_mm, onset_mm] :
       {std::tuple{0.18, 20.0, 16.5115}, std::tuple{0.0, 16.0, 14.1}}) {
    SCOPED_TRACE(fmt::format("friction {}", friction));
    const Problem p = sphere_near_limit_point(friction);
    CurveOptions c;
    c.max_depth_mm = end_mm;
    c.points = static_cast<int>(end_mm / 0.25) + 1;
    const auto curve = loading_curve(p, c);
    ASSERT_TRUE(curve.ok()) << curve.message;
    EXPECT_TRUE(curve.events.empty());
    ASSERT_TRUE(curve.part_two_onset_depth_mm.has_value());
    ASSERT_TRUE(curve.part_two_onset_force_n.has_value());
    const double onset = *curve.part_two_onset_depth_mm;
    EXPECT_NEAR(onset, onset_mm, 0.1);
    std::size_t last_on_cap = 0;
    for (std::size_t k = 1; k < curve.points.size(); ++k) {
      const CurvePoint& a = curve.points[k - 1];
      const CurvePoint& b = curve.points[k];
      EXPECT_GT(b.force_n, a.force_n) << "at " << b.depth_mm << " mm";
      if (b.depth_mm < onset) {
        EXPECT_EQ(b.configuration, Configuration::SlipWithoutPartTwo);
        EXPECT_LT(b.corner_slope_rad, kHalfPi);
        if (k > 1) EXPECT_GT(b.corner_slope_rad, a.corner_slope_rad);
        last_on_cap = k;
      } else {
        EXPECT_EQ(b.configuration, Configuration::SlipWithPartTwo);
        EXPECT_NEAR(b.corner_slope_rad, kHalfPi, 1e-12);
        EXPECT_GT(b.part_two_length_mm, a.depth_mm < onset ? 0.0 : a.part_two_length_mm);
      }
    }
    ASSERT_GE(last_on_cap, 2u);
    ASSERT_LT(last_on_cap + 1, curve.points.size());
    const CurvePoint& a = curve.points[last_on_cap - 1];
    const CurvePoint& b = curve.points[last_on_cap];
    const double slope_rate = (b.corner_slope_rad - a.corner_slope_rad) / (b.depth_mm - a.depth_mm);
    const double extrapolated = b.depth_mm + (kHalfPi - b.corner_slope_rad) / slope_rate;
    EXPECT_NEAR(extrapolated, onset, 0.01);
    EXPECT_GT(*curve.part_two_onset_force_n, b.force_n);
    EXPECT_LT(*curve.part_two_onset_force_n, curve.points[last_on_cap + 1].force_n);
    record(fmt::format("onset_depth_mm_friction_{}", friction), onset);
    record(fmt::format("onset_force_n_friction_{}", friction), *curve.part_two_onset_force_n);
    record(fmt::format("onset_extrapolated_from_cap_mm_friction_{}", friction), extrapolated);
  }
}

// Past the equator the states the path reaches are equilibria: solved independently at their
// depths (the public solve, its own force search and depth control), they carry the curve's force
// to 1e-7; and without friction dPi/d(depth) = F there with Pi = U - p V (central differences at
// h and h/2, h = 1 % of the depth, extrapolated; 2000-sample fields; 1e-6 as the other domes').
TEST(OverhangingPaths, PastTheEquatorTheStatesAreEquilibria) {
  for (const auto& [friction, depths] : {std::pair{0.18, std::vector<double>{16.75, 20.0}},
                                         std::pair{0.0, std::vector<double>{15.0}}}) {
    SCOPED_TRACE(fmt::format("friction {}", friction));
    const Problem p = sphere_near_limit_point(friction);
    CurveOptions c;
    c.points = 81;
    c.max_depth_mm = 20.0;
    const auto curve = loading_curve(p, c);
    ASSERT_TRUE(curve.ok()) << curve.message;
    for (const double depth : depths) {
      SCOPED_TRACE(fmt::format("{} mm", depth));
      const auto e = solve_at_depth(p, depth, Stage::Slip, sampled(2000));
      ASSERT_TRUE(e.ok()) << e.message;
      EXPECT_EQ(e.configuration, Configuration::SlipWithPartTwo);
      const auto on_curve =
          std::find_if(curve.points.begin(), curve.points.end(), [&](const auto& q) {
            return std::abs(q.depth_mm - depth) < 1e-9;
          });
      if (on_curve != curve.points.end())
        EXPECT_NEAR(e.force_n, on_curve->force_n, 1e-7 * e.force_n);
      if (friction != 0.0) continue;
      auto pi_at = [&](double d) {
        const auto s = solve_at_depth(p, d, Stage::Slip, sampled(2000));
        EXPECT_TRUE(s.ok()) << s.message;
        return potential(p, s).value;
      };
      const double h = 0.01 * depth;
      const double d1 = (pi_at(depth + h) - pi_at(depth - h)) / (2.0 * h);
      const double d2 = (pi_at(depth + h / 2) - pi_at(depth - h / 2)) / h;
      const double slope = (4.0 * d2 - d1) / 3.0;
      EXPECT_NEAR(slope, e.force_n, 1e-6 * e.force_n) << "dPi/ddelta " << slope << " N";
      record("relative_difference_dpi_ddelta_past_equator", std::abs(slope / e.force_n - 1.0));
    }
  }
}

// The puncture lies past the equator (0.78588 N at 51.656 mm with friction 0.18, 0.47875 N at
// 33.490 mm without, measured): its state has the critical I1, the state solved at its depth has
// its force, the verdict is a local puncture and the energy to it is computed; without friction
// that energy (the curve's Gauss-Legendre quadrature, its pieces meeting at the onset) equals the
// change of Pi = U - p V from the dome to the puncture state.
TEST(OverhangingPaths, TheSpherePuncturesPastItsEquator) {
  for (const double friction : {0.18, 0.0}) {
    SCOPED_TRACE(fmt::format("friction {}", friction));
    const Problem p = sphere_near_limit_point(friction);
    SolverOptions o = sampled(2000);
    o.failure_verdict = true;
    o.energy_to_puncture = true;
    const auto puncture = predict_puncture(p, o);
    ASSERT_TRUE(puncture.ok()) << puncture.message;
    EXPECT_NEAR(puncture.state.max_first_invariant, p.critical_i1, 1e-8 * p.critical_i1);
    EXPECT_EQ(puncture.state.configuration, Configuration::SlipWithPartTwo);
    EXPECT_NEAR(puncture.force_n, friction > 0.0 ? 0.78588 : 0.47875, 1e-5);
    const auto at = solve_at_depth(p, puncture.depth_mm, Stage::Slip);
    ASSERT_TRUE(at.ok()) << at.message;
    EXPECT_NEAR(at.force_n, puncture.force_n, 1e-7 * puncture.force_n);
    ASSERT_TRUE(puncture.failure_verdict.has_value());
    EXPECT_EQ(puncture.failure_verdict->mode, FailureMode::LocalPuncture);
    ASSERT_TRUE(puncture.energy_to_puncture_mj.has_value());
    if (friction != 0.0) continue;
    const auto dome = solve_at_depth(p, 0.0, Stage::Slip, sampled(2000));
    ASSERT_TRUE(dome.ok()) << dome.message;
    const Quadrature pi0 = potential(p, dome), pi1 = potential(p, puncture.state);
    const double change = pi1.value - pi0.value;
    EXPECT_NEAR(
        *puncture.energy_to_puncture_mj, change, pi0.error + pi1.error + 1e-6 * std::abs(change));
    record("relative_difference_work_to_puncture_past_equator",
           std::abs(*puncture.energy_to_puncture_mj / change - 1.0));
  }
}

// A later inflated state that overhangs (the last of 3 at 0.9 kPa, a balloon 85.3 mm high) is
// indented from its own dome: at zero depth the state is the inflation solver's last state
// (pole stretch to 1e-12, pole height and volume from 2000-sample fields to 1e-9); a state at a
// force is refused (the searches near zero force find the first state's branch); the puncture
// is found along the path in depth, its pole stretch above the dome's, with the critical I1; the
// loading curve (depth control from the dome) brackets it; and without friction the work to the
// puncture equals the change of Pi = U - p V from the dome (an energy balance along the branch).
TEST(OverhangingPaths, ALaterInflatedStateIsIndentedFromItsOwnDome) {
  for (const auto& indenter : {Indenter{SphereTipped{2.0}}, Indenter{FlatPunch{2.0}}}) {
    SCOPED_TRACE(describe(indenter));
    Problem p = pressurised(kNearLimitPointMpa, 0.0, indenter);
    p.preload.inflated_state = kLastInflatedState;
    const auto at = inflate_at_pressure(inflation_problem(p), kNearLimitPointMpa);
    ASSERT_TRUE(at.ok()) << at.message;
    ASSERT_EQ(at.states.size(), 3u);
    const InflationState& balloon = at.states.back();
    ASSERT_GT(balloon.clamp_slope_rad, kHalfPi);
    const auto dome = solve_at_depth(p, 0.0, Stage::Slip, sampled(2000));
    ASSERT_TRUE(dome.ok()) << dome.message;
    EXPECT_NEAR(dome.part_three_stretch, balloon.pole_stretch, 1e-12 * balloon.pole_stretch);
    EXPECT_NEAR(
        dome.fields.deflection_mm.back(), balloon.pole_height_mm, 1e-9 * balloon.pole_height_mm);
    const double volume = [&] {
      std::vector<double> r_squared, height;
      const auto& m = dome.fields;
      for (std::size_t i = 0; i < m.size(); ++i) {
        r_squared.push_back(m.radius_mm[i] * m.radius_mm[i]);
        height.push_back(m.deflection_mm.back() - m.deflection_mm[i]);
      }
      return kPi * integrate(r_squared, height).value;
    }();
    EXPECT_NEAR(volume, balloon.volume_mm3, 1e-9 * balloon.volume_mm3);
    const auto by_force = solve_at_force(p, 0.1, Stage::Slip);
    EXPECT_EQ(by_force.status, Status::OutsideModel);
    SolverOptions o = sampled(2000);
    o.failure_verdict = true;
    o.energy_to_puncture = true;
    const auto puncture = predict_puncture(p, o);
    ASSERT_TRUE(puncture.ok()) << puncture.message;
    EXPECT_NEAR(puncture.state.max_first_invariant, p.critical_i1, 1e-8 * p.critical_i1);
    EXPECT_GT(puncture.state.part_three_stretch, balloon.pole_stretch);
    CurveOptions around;
    around.depths_mm = {puncture.depth_mm - 0.1, puncture.depth_mm + 0.1};
    const auto curve = loading_curve(p, around);
    ASSERT_TRUE(curve.ok()) << curve.message;
    ASSERT_EQ(curve.points.size(), 2u);
    EXPECT_LT(curve.points[0].max_first_invariant, p.critical_i1);
    EXPECT_GT(curve.points[1].max_first_invariant, p.critical_i1);
    EXPECT_LT(curve.points[0].force_n, puncture.force_n);
    EXPECT_GT(curve.points[1].force_n, puncture.force_n);
    ASSERT_TRUE(puncture.energy_to_puncture_mj.has_value());
    const Quadrature pi0 = potential(p, dome), pi1 = potential(p, puncture.state);
    const double change = pi1.value - pi0.value;
    EXPECT_NEAR(
        *puncture.energy_to_puncture_mj, change, pi0.error + pi1.error + 1e-6 * std::abs(change));
    record(fmt::format("later_state_puncture_force_n_{}", describe(indenter).substr(0, 4)),
           puncture.force_n);
    record(fmt::format("later_state_puncture_depth_mm_{}", describe(indenter).substr(0, 4)),
           puncture.depth_mm);
    record(fmt::format("later_state_work_relative_difference_{}", describe(indenter).substr(0, 4)),
           std::abs(*puncture.energy_to_puncture_mj / change - 1.0));
  }
}

}  // namespace
}  // namespace puncture::test
