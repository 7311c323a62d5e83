// Sliding with Part II near the limit load of a law without locking, where the depth runs away
// from the force: depth control by the Part III stretch (FlatPunchContact::contact_start,
// DepthControl::Contact), checked against the force-controlled states and the frictionless
// closed form of the force, f = a s_eq(L) / L (R s1 = f all down the side).
#include <gtest/gtest.h>

#include <cmath>

#include "indentation/dispatch.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

SolverOptions without_fields() {
  SolverOptions o;
  o.record_fields = false;
  return o;
}

// The normalised force at which the frictionless corner needs s_eq(L) / L = f / a at L -> inf:
// the neo-Hookean s_eq(L) / L = 1 - L^-6 (s_eq = L - L^-5) tends to 1, so f_lim = a / A.
double neo_hookean_limit(const Problem& p) {
  return std::get<FlatPunch>(p.indenter).radius_mm / p.geometry.clamp_radius_mm;
}

// The slow case: a thin neo-Hookean membrane held until 2.9946 N, then sliding
// frictionless with Part II at 0.999... of the limit load.
Problem slow_case() {
  Problem p;
  p.indenter = FlatPunch{4.86};
  p.geometry.thickness_mm = 0.02936;
  p.material.law = NeoHookean{};
  p.material.shear_modulus_mpa = 0.6708;
  p.friction = 0.0;
  p.critical_i1 = 118.0;
  p.stick = {StickRule::Force, 2.9946};
  return p;
}

// The same state by (f, p) and by (Part III stretch, p): force, depth, clamp residual, Part II
// and the largest I1 agree to the integration's accuracy (Part II is marched down to its corner
// in one and up from it in the other).
TEST(LimitLoad, CornerParametrisationGivesTheForceControlledState) {
  int compared = 0;
  for (const auto& [law, friction] : {std::pair<MaterialLaw, double>{Gent{125.0}, 0.18},
                                      {NeoHookean{}, 0.0},
                                      {NeoHookean{}, 1.0},
                                      {MooneyRivlin{0.2}, 0.5}}) {
    const Problem p = paper_problem(law, friction);
    detail::with_shooting(p, without_fields(), [&](const auto& shooting) {
      const auto onset = shooting.contact().slip_change(shooting);
      ASSERT_TRUE(onset.has_value());
      // Without friction the neo-Hookean states end at the limit load a / A = 0.08.
      const bool limited = friction == 0.0;
      for (const double x : {0.01, 0.2, 0.5}) {
        const double f =
            limited ? onset->f + x * (neo_hookean_limit(p) - onset->f) : onset->f * (1.0 + x);
        const auto at_force = shooting.solve(Stage::Slip, f);
        ASSERT_TRUE(at_force.ok()) << at_force.message;
        ASSERT_EQ(at_force.configuration, Configuration::SlipWithPartTwo);
        const auto at_corner = shooting.assemble_at_contact(
            Configuration::SlipWithPartTwo, at_force.part_three_stretch, at_force.parameter, false);
        ASSERT_TRUE(at_corner.integrated) << at_corner.message;
        const auto what = fmt::format("friction {} f {}", friction, f);
        ++compared;
        EXPECT_NEAR(at_corner.f / f, 1.0, 1e-9) << what;
        EXPECT_NEAR(at_corner.depth / at_force.depth, 1.0, 1e-9) << what;
        EXPECT_LE(std::abs(at_corner.residual), 1e-8) << what;
        EXPECT_NEAR(at_corner.part_two_length / at_force.part_two_length, 1.0, 1e-8) << what;
        EXPECT_NEAR(max_first_invariant_of(at_corner) / max_first_invariant_of(at_force), 1.0, 1e-9)
            << what;
      }
    });
  }
  EXPECT_EQ(compared, 12);
}

// Without friction (ring balance) R s1 is constant up the side, so the force of the corner
// parametrisation is a s_eq(L) / L whatever the top stretch.
TEST(LimitLoad, FrictionlessForceIsTheCornerClosedForm) {
  const Problem p = paper_problem(NeoHookean{}, 0.0);
  const double a = neo_hookean_limit(p);
  detail::with_shooting(p, without_fields(), [&](const auto& shooting) {
    for (const double l3 : {1.5, 3.0, 30.0, 300.0})
      for (const double top : {1.05, 1.2}) {
        const auto s = shooting.assemble_at_contact(Configuration::SlipWithPartTwo, l3, top, false);
        ASSERT_TRUE(s.integrated) << s.message;
        EXPECT_NEAR(s.f / (a * equibiaxial_stress(p.material.law, l3) / l3), 1.0, 1e-9)
            << l3 << ' ' << top;
        EXPECT_NEAR(s.part_three_stretch, l3, 1e-12 * l3);
      }
  });
}

// Beyond the frictionless limit load there is no state, reported as such at once; just below
// it the membrane wraps the side with a Part III stretch of s_eq(L) / L = f / a.
TEST(LimitLoad, FrictionlessLimitLoadIsTheNeoHookeanClosedForm) {
  const Problem p = paper_problem(NeoHookean{}, 0.0);
  const double f_lim = neo_hookean_limit(p);
  detail::with_shooting(p, without_fields(), [&](const auto& shooting) {
    const auto beyond = shooting.solve(Stage::Slip, f_lim * (1.0 + 1e-6));
    EXPECT_EQ(beyond.status, Status::LimitLoad) << beyond.message;
    const double f = f_lim * (1.0 - 1e-6);
    const auto below = shooting.solve(Stage::Slip, f);
    ASSERT_TRUE(below.ok()) << below.message;
    EXPECT_EQ(below.configuration, Configuration::SlipWithPartTwo);
    // 1 - L^-6 = f / f_lim: L = (1e6)^(1/6) = 10.  So near the limit an error e in the force
    // ratio moves L by L e / (6e-6): the integration's ~1e-11 moves it by up to ~2e-5.
    EXPECT_NEAR(below.part_three_stretch, 10.0, 2e-5);
  });
}

// The slow case's curve ends with the switch, where the sliding membrane, at 0.9999 of the limit
// load, is stretched 262-fold under the tip and punctures.  Its puncture state carries the
// switch depth like the curve's point there (both converged to 1e-9 relative in depth; the force
// search alone left it 1.3e-6 away), and its force is the closed form a s_eq(L) / L.
TEST(LimitLoad, SlowCasePuncturesAtTheSwitchDepth) {
  const Problem p = slow_case();
  CurveOptions curve;
  curve.points = 12;
  const LoadingCurve c = loading_curve(p, curve);
  ASSERT_TRUE(c.ok()) << c.message;
  ASSERT_TRUE(c.puncture.ok()) << c.puncture.message;
  ASSERT_TRUE(c.stick_slip.occurs);
  EXPECT_TRUE(c.puncture.at_switch);
  EXPECT_EQ(c.puncture.stage, Stage::Slip);
  EXPECT_NEAR(c.puncture.depth_mm / c.stick_slip.depth_mm, 1.0, 2e-9);
  EXPECT_NEAR(c.points.back().depth_mm, c.stick_slip.depth_mm, 0.0);
  const double l3 = c.puncture.part_three_stretch;
  EXPECT_GT(l3, 100.0);
  const double f_closed = neo_hookean_limit(p) * equibiaxial_stress(p.material.law, l3) / l3;
  EXPECT_NEAR(c.puncture.normalized_force / f_closed, 1.0, 1e-8);
  EXPECT_NEAR(c.points.back().normalized_force / f_closed, 1.0, 1e-8);
  record("puncture_depth_vs_switch", c.puncture.depth_mm / c.stick_slip.depth_mm - 1.0);
}

}  // namespace
}  // namespace puncture::test
