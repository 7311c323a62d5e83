// The loading curve after a `coulomb` release on the sphere-tipped probe follows the partial
// slip (docs/model.md §15.4): its points between the release and the hand-over are the family's
// states (PartialSlip::state_at_depth on a family built here independently of the curve's), the
// curve is continuous at the release (the held state) and at the hand-over (the sliding model's
// state), solve_at_depth gives the same states, and the energy to puncture is the area under the
// curve (the trapezoid rule on dense curves, Richardson-extrapolated).
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

#include "indentation/contact/partial_slip.hpp"
#include "indentation/dispatch.hpp"
#include "indentation/shooting.hpp"
#include "indentation/solver_scales.hpp"
#include "puncture/loading_curve.hpp"
#include "solver_test_support.hpp"

namespace puncture::detail {
namespace {

constexpr double kCurvePrestretch = 1.2;  // as partial_slip_test: friction holds the first touch

Problem coulomb_curve_problem(double mu, const Indenter& indenter = SphereTipped{2.0}) {
  Problem p = test::paper_problem(Gent{125.0}, mu);
  p.indenter = indenter;
  p.stick = {StickRule::Coulomb, 0.0};
  p.preload.prestretch = kCurvePrestretch;
  return p;
}

// Every curved probe is a SphereTippedContact profile.
SphereTippedSettings curve_family_settings(const Problem& p) {
  if (const auto* punch = std::get_if<FlatPunch>(&p.indenter)) return filleted_settings(p, *punch);
  if (const auto* cone = std::get_if<Cone>(&p.indenter)) return contact_settings(p, *cone);
  return contact_settings(p, std::get<SphereTipped>(p.indenter));
}

// The family on its own history (the default solver options, as the curve's).
struct CurveFamily {
  Problem problem;
  IndentationShooting<SphereTippedContact<Gent>> shooting;
  FreePart<Gent> part_one;
  ProfileStickHistory<Gent> held;
  PartialSlip<Gent> slip;
  double release = std::numeric_limits<double>::quiet_NaN();

  explicit CurveFamily(double mu, const Indenter& indenter = SphereTipped{2.0})
      : problem(coulomb_curve_problem(mu, indenter)),
        shooting(std::get<Gent>(problem.material.law),
                 shooting_settings(SolverOptions{}, kCurvePrestretch),
                 curve_family_settings(problem), false),
        part_one(std::get<Gent>(problem.material.law), shooting.settings()),
        held(part_one, shooting.contact().held_profile_history().profile()),
        slip(part_one, held, mu) {
    const auto& pts = held.points();
    std::size_t k = 2;
    while (k + 1 < pts.size() && held.held_ratio(pts[k].r) < mu) ++k;
    std::uintmax_t iterations = 200;
    const auto root =
        boost::math::tools::bisect([&](double r) { return held.held_ratio(r) - mu; },
                                   pts[k - 1].r,
                                   pts[k].r,
                                   [](double a, double b) { return std::abs(b - a) <= 1e-15; },
                                   iterations);
    release = 0.5 * (root.first + root.second);
  }
};

bool is_partial_slip(const CurvePoint& q) { return q.configuration == Configuration::PartialSlip; }

// The curve's partial-slip points are the family's states at their depths (force, edge and
// front to 1e-9 relative), the switch's two points agree (the held state and the family's
// first, an empty annulus: to the held map's own 1e-6), and the first sliding point past the
// hand-over continues the family's force (the hand-over's sliding state within 1e-5 of the
// family's last, as the family meets the sliding branch).
TEST(PartialSlipCurve, PointsAreTheFamilysStatesAndContinuous) {
  const CurveFamily s(0.5);
  const auto units = solver_scales(s.problem);
  const auto b = stick_slip_boundary(s.problem);
  ASSERT_TRUE(b.ok() && b.switches) << b.message;
  CurveOptions grid;
  for (double d = 0.25; d <= 12.0; d += 0.25) grid.depths_mm.push_back(d);
  const LoadingCurve c = loading_curve(s.problem, grid);
  ASSERT_TRUE(c.ok()) << c.message;
  ASSERT_TRUE(c.stick_slip.occurs);
  ASSERT_TRUE(c.stick_slip.full_sliding_depth_mm);
  const double handover = *c.stick_slip.full_sliding_depth_mm;
  std::cout << fmt::format(
      "release at {:.9f} mm, {:.9f} N; full sliding from {:.9f} mm, {:.9f} N\n",
      c.stick_slip.depth_mm,
      c.stick_slip.force_stuck_n,
      handover,
      c.stick_slip.full_sliding_force_n);
  EXPECT_NEAR(c.stick_slip.force_sliding_n, c.stick_slip.force_stuck_n, 1e-6 * b.force_stuck_n);
  std::size_t partial_points = 0;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const CurvePoint& q = c.points[i];
    if (q.depth_mm < c.stick_slip.depth_mm) EXPECT_EQ(q.stage, Stage::Stick) << q.depth_mm;
    if (q.depth_mm > c.stick_slip.depth_mm && q.depth_mm < handover) {
      ASSERT_TRUE(is_partial_slip(q)) << q.depth_mm;
      const auto st = s.slip.state_at_depth(q.depth_mm / units.length_mm, s.release);
      if (!st) {
        // Within a few um of the release the held state stands for the family's.
        EXPECT_LT(q.depth_mm - c.stick_slip.depth_mm, 0.01) << q.depth_mm;
        continue;
      }
      ++partial_points;
      EXPECT_NEAR(q.force_n, st->at_edge.f * units.force_n, 1e-9 * q.force_n) << q.depth_mm;
      EXPECT_NEAR(q.slip_front_reference_radius_mm, st->front * units.length_mm, 1e-9 * st->front);
      const auto& profile = s.held.profile();
      EXPECT_NEAR(q.contact_edge_radius_mm,
                  profile.radius(st->at_edge.psi) * units.length_mm,
                  1e-9 * q.contact_edge_radius_mm);
      EXPECT_EQ(q.part_three_stretch, kCurvePrestretch);  // the held pole
      // Part I leaves the 2 mm sphere tangentially: sin(slope) = r_edge / a, from the edge's
      // reported radius (not the profile's angle the point was built from) to its 1e-9.
      EXPECT_NEAR(std::sin(q.corner_slope_rad), q.contact_edge_radius_mm / 2.0, 1e-9) << q.depth_mm;
      EXPECT_GT(q.max_first_invariant, 3.0);
      // solve_at_depth gives the curve's state.
      const Equilibrium e = solve_at_depth(s.problem, q.depth_mm, Stage::Slip);
      ASSERT_TRUE(e.ok()) << e.message;
      EXPECT_EQ(e.configuration, Configuration::PartialSlip);
      EXPECT_NEAR(e.force_n, q.force_n, 1e-12 * q.force_n);
      EXPECT_NEAR(e.slip_front_radius_mm, q.slip_front_radius_mm, 1e-12);
      EXPECT_EQ(e.corner_slope_rad, q.corner_slope_rad);
    }
    if (q.depth_mm > handover) {
      EXPECT_EQ(q.stage, Stage::Slip);
      EXPECT_FALSE(is_partial_slip(q)) << q.depth_mm;
    }
  }
  EXPECT_GE(partial_points, 3u);
  // The hand-over: the sliding model's state at its depth has the family's force there.
  const Equilibrium sliding = solve_at_depth(s.problem, handover, Stage::Slip);
  ASSERT_TRUE(sliding.ok()) << sliding.message;
  EXPECT_NE(sliding.configuration, Configuration::PartialSlip);
  std::cout << fmt::format("hand-over: family {:.9f} N, sliding {:.9f} N ({:.2e})\n",
                           c.stick_slip.full_sliding_force_n,
                           sliding.force_n,
                           sliding.force_n / c.stick_slip.full_sliding_force_n - 1.0);
  EXPECT_NEAR(sliding.force_n, c.stick_slip.full_sliding_force_n, 1e-5 * sliding.force_n);
}

// The same on the filleted punch (0.5 mm fillet) and the cone (30 degrees, 0.5 mm tip), mu = 0.3:
// the curve's partial-slip points are the family's states (to 1e-9), the switch has no jump and
// the sliding state at the hand-over has the family's force (the fillet's face edge, the cone's
// pole; partial_slip_test measures 4e-5 and 1e-7 with the front nearer its end).
TEST(PartialSlipCurve, FilletAndConeFollowTheFamilyToo) {
  for (const Indenter& indenter :
       std::vector<Indenter>{FlatPunch{2.0, 0.5}, Cone{2.0, 30.0, 0.5}}) {
    const CurveFamily s(0.3, indenter);
    const auto units = solver_scales(s.problem);
    const auto b = stick_slip_boundary(s.problem);
    ASSERT_TRUE(b.ok() && b.switches) << b.message;
    CurveOptions grid;
    for (int k = 1; k <= 24; ++k) grid.depths_mm.push_back(b.depth_mm * (0.5 + 0.125 * k));
    const LoadingCurve c = loading_curve(s.problem, grid);
    ASSERT_TRUE(c.ok()) << c.message;
    ASSERT_TRUE(c.stick_slip.full_sliding_depth_mm);
    const double handover = *c.stick_slip.full_sliding_depth_mm;
    EXPECT_NEAR(c.stick_slip.force_sliding_n, c.stick_slip.force_stuck_n, 1e-6 * b.force_stuck_n);
    std::size_t on_family = 0;
    for (const CurvePoint& q : c.points) {
      if (!(q.depth_mm > c.stick_slip.depth_mm && q.depth_mm < handover)) continue;
      ASSERT_TRUE(is_partial_slip(q)) << q.depth_mm;
      const auto st = s.slip.state_at_depth(q.depth_mm / units.length_mm, s.release);
      if (!st) continue;  // within a few um of the release (the held state)
      ++on_family;
      EXPECT_NEAR(q.force_n, st->at_edge.f * units.force_n, 1e-9 * q.force_n) << q.depth_mm;
    }
    EXPECT_GE(on_family, 3u);
    const Equilibrium sliding = solve_at_depth(s.problem, handover, Stage::Slip);
    ASSERT_TRUE(sliding.ok()) << sliding.message;
    std::cout << fmt::format(
        "released at {:.6f} mm, full sliding from {:.6f} mm: family {:.9f} N, sliding {:.9f} N\n",
        c.stick_slip.depth_mm,
        handover,
        c.stick_slip.full_sliding_force_n,
        sliding.force_n);
    EXPECT_NEAR(sliding.force_n, c.stick_slip.full_sliding_force_n, 1e-4 * sliding.force_n);
  }
}

// The trapezoid rule along a curve's points (both states at the switch share one depth).
double area_under(const LoadingCurve& curve) {
  double sum = 0.0;
  for (std::size_t k = 1; k < curve.points.size(); ++k) {
    const auto &a = curve.points[k - 1], &b = curve.points[k];
    sum += 0.5 * (a.force_n + b.force_n) * (b.depth_mm - a.depth_mm);
  }
  return sum;
}

// The energy to puncture (Gauss-Legendre on the path's pieces, the partial slip's its own) is the
// area under the curve: the trapezoid rule on dense curves to puncture converges to it at order 2
// (kinks of dF/ddepth at the release, the hand-over and Part II's onset keep it O(h^2)), and the
// Richardson value agrees with it far better than the densest curve.  The curves' partial-slip
// points lie on the family (the other test), so the quadrature integrates the family's forces.
TEST(PartialSlipCurve, EnergyToPunctureIsTheAreaUnderTheCurve) {
  const Problem p = coulomb_curve_problem(0.5);
  SolverOptions o;
  o.energy_to_puncture = true;
  const auto puncture = predict_puncture(p, o);
  ASSERT_TRUE(puncture.ok()) << puncture.message;
  ASSERT_TRUE(puncture.energy_to_puncture_mj) << puncture.message;
  const double energy = *puncture.energy_to_puncture_mj;
  std::vector<double> areas;
  for (const int n : {201, 401, 801}) {
    CurveOptions c;
    c.points = n;
    const auto curve = loading_curve(p, c, o);
    ASSERT_TRUE(curve.ok()) << curve.message;
    ASSERT_TRUE(curve.stick_slip.full_sliding_depth_mm);
    EXPECT_TRUE(std::any_of(curve.points.begin(), curve.points.end(), is_partial_slip)) << n;
    areas.push_back(area_under(curve));
  }
  const double richardson = areas[2] + (areas[2] - areas[1]) / 3.0;
  std::cout << fmt::format(
      "energy to puncture {:.12f} mJ; trapezoid 201/401/801: {:+.3e} {:+.3e} {:+.3e}, "
      "Richardson {:+.3e} (relative)\n",
      energy,
      areas[0] / energy - 1.0,
      areas[1] / energy - 1.0,
      areas[2] / energy - 1.0,
      richardson / energy - 1.0);
  const double e401 = std::abs(areas[1] - energy), e801 = std::abs(areas[2] - energy);
  EXPECT_GT(e401 / e801, 2.5);
  EXPECT_LT(e401 / e801, 6.0);
  EXPECT_LT(std::abs(richardson - energy), 0.25 * e801);
}

}  // namespace
}  // namespace puncture::detail
