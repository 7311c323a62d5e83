// Partial slip after a `coulomb` release under a held gas pressure (docs/model.md §15.4, §17.3):
// on the sphere-tipped probe, the ball and the cone the family carries the gas's share (the
// normal traction gains P, the edge's force P r^2 / 2).  Checks: no jump at the release, the
// family's last state is the sliding model's at the hand-over (solved on its own), the fields'
// vertical balance with the gas (2 pi R s1 H sin(phi) + p pi r^2 = F at the edge and the clamp)
// and Laplace's normal balance plus the gas on the sphere, a critical I1 met inside the stretch
// found there (bracketed by the states at depths either side); the filleted punch's face, which
// the sliding model lets slide under the gas, keeps the jump.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <vector>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "solver_test_support.hpp"

namespace puncture {
namespace {

constexpr double kPslipGasMpa = 0.0005;  // the dome's pole stretch ~1.21

Problem pslip_gas_problem(const Indenter& indenter, double mu, double prestretch) {
  Problem p = test::paper_problem(Gent{125.0}, mu);
  p.indenter = indenter;
  p.stick = {StickRule::Coulomb, 0.0};
  p.preload.prestretch = prestretch;
  p.preload.pressure_mpa = kPslipGasMpa;
  return p;
}

SolverOptions pslip_gas_quiet() {
  SolverOptions o;
  o.record_fields = false;
  return o;
}

// The vertical load at field point i: the meridian tension's 2 pi R s1 H sin(phi) plus the gas's
// p pi r^2 inside it [N].
double pslip_gas_load_n(const Problem& p, const MembraneFields& m, std::size_t i) {
  const double r = m.radius_mm[i];
  return 2.0 * std::numbers::pi * m.reference_radius_mm[i] * m.radial_stress_mpa[i] *
             p.geometry.thickness_mm * std::sin(m.slope_rad[i]) +
         p.preload.pressure_mpa * std::numbers::pi * r * r;
}

void check_partial_slip_under_gas(const Problem& p, double max_depth_mm, double sphere_radius_mm,
                                  double handover_tol) {
  const LoadingCurve c =
      loading_curve(p, CurveOptions{.points = 60, .max_depth_mm = max_depth_mm}, pslip_gas_quiet());
  ASSERT_TRUE(c.ok()) << c.message;
  ASSERT_TRUE(c.stick_slip.occurs);
  ASSERT_TRUE(c.stick_slip.full_sliding_depth_mm);
  const double release = c.stick_slip.depth_mm, handover = *c.stick_slip.full_sliding_depth_mm;
  EXPECT_NEAR(
      c.stick_slip.force_sliding_n, c.stick_slip.force_stuck_n, 1e-6 * c.stick_slip.force_stuck_n);
  int partial = 0;
  for (const CurvePoint& q : c.points)
    if (q.configuration == Configuration::PartialSlip) ++partial;
  EXPECT_GE(partial, 3);
  const Equilibrium sliding = solve_at_depth(p, handover, Stage::Slip, pslip_gas_quiet());
  ASSERT_TRUE(sliding.ok()) << sliding.message;
  EXPECT_NE(sliding.configuration, Configuration::PartialSlip);
  std::cout << fmt::format(
      "released at {:.6f} mm, {:.9f} N; hand-over at {:.6f} mm: family {:.9f} N, sliding "
      "{:.9f} N ({:+.2e})\n",
      release,
      c.stick_slip.force_stuck_n,
      handover,
      c.stick_slip.full_sliding_force_n,
      sliding.force_n,
      c.stick_slip.full_sliding_force_n / sliding.force_n - 1.0);
  EXPECT_NEAR(c.stick_slip.full_sliding_force_n, sliding.force_n, handover_tol * sliding.force_n);
  // Half-way: the fields' balances with the gas.
  const double mid = 0.5 * (release + handover);
  const Equilibrium e = solve_at_depth(p, mid, Stage::Slip);
  ASSERT_TRUE(e.ok()) << e.message;
  ASSERT_EQ(e.configuration, Configuration::PartialSlip);
  const MembraneFields& m = e.fields;
  std::size_t edge = 0;
  while (edge < m.size() && m.part[edge] != MembranePart::Free) ++edge;
  ASSERT_LT(edge, m.size());
  const std::size_t clamp = m.size() - 1;
  EXPECT_NEAR(pslip_gas_load_n(p, m, edge), e.force_n, 1e-10 * e.force_n);
  EXPECT_NEAR(pslip_gas_load_n(p, m, clamp), e.force_n, 1e-7 * e.force_n);
  for (std::size_t i = 0; i < edge; ++i) {
    EXPECT_GT(m.contact_pressure_mpa[i], kPslipGasMpa) << i;
    if (m.reference_radius_mm[i] > e.slip_front_reference_radius_mm)
      EXPECT_NEAR(m.friction_traction_mpa[i], p.friction * m.contact_pressure_mpa[i], 1e-15);
    else
      EXPECT_LE(std::abs(m.friction_traction_mpa[i]),
                p.friction * m.contact_pressure_mpa[i] * (1.0 + 1e-9));
    if (sphere_radius_mm > 0.0 && m.reference_radius_mm[i] > 0.0) {
      const double t1 = m.radial_stress_mpa[i] * p.geometry.thickness_mm / m.hoop_stretch[i];
      const double t2 = m.hoop_stress_mpa[i] * p.geometry.thickness_mm / m.radial_stretch[i];
      EXPECT_NEAR(m.contact_pressure_mpa[i],
                  (t1 + t2) / sphere_radius_mm + kPslipGasMpa,
                  1e-9 * m.contact_pressure_mpa[i])
          << i;
    }
  }
  std::cout << fmt::format("  at {:.6f} mm: clamp load {:+.2e}, edge p {:.6g} MPa\n",
                           mid,
                           pslip_gas_load_n(p, m, clamp) / e.force_n - 1.0,
                           m.contact_pressure_mpa[edge - 1]);
}

// The sphere-tipped probe (stress-free, mu = 0.5), the ball (3 mm, mu = 0.5) and the cone (30
// degrees, 0.5 mm tip, L0 = 1.2, mu = 0.3) under 0.5 kPa; the hand-over's force agrees with the
// sliding model's (measured 4e-12, 6e-12, 7e-11; 1e-9 allowed).
TEST(PartialSlipUnderGas, SphereBallConeFollowTheFamilyToTheSlidingState) {
  check_partial_slip_under_gas(pslip_gas_problem(SphereTipped{2.0}, 0.5, 1.0), 9.0, 2.0, 1e-9);
  check_partial_slip_under_gas(pslip_gas_problem(Ball{2.0, 3.0}, 0.5, 1.0), 14.0, 3.0, 1e-9);
  check_partial_slip_under_gas(pslip_gas_problem(Cone{2.0, 30.0, 0.5}, 0.3, 1.2), 1.0, 0.0, 1e-9);
}

// A critical I1 of 3.6 (the sphere's partial slip under the gas runs from I1 3.44 to 3.99) is met
// inside the stretch: the states 1 um either side of the reported depth lie below and above it.
TEST(PartialSlipUnderGas, PunctureInsideThePartialSlip) {
  Problem p = pslip_gas_problem(SphereTipped{2.0}, 0.5, 1.0);
  p.critical_i1 = 3.6;
  const PuncturePrediction found = predict_puncture(p);
  ASSERT_TRUE(found.ok()) << found.message;
  EXPECT_EQ(found.configuration, Configuration::PartialSlip);
  EXPECT_NEAR(found.state.max_first_invariant, 3.6, 1e-9);
  const Equilibrium before =
      solve_at_depth(p, found.depth_mm - 1e-6, Stage::Slip, pslip_gas_quiet());
  const Equilibrium after =
      solve_at_depth(p, found.depth_mm + 1e-6, Stage::Slip, pslip_gas_quiet());
  ASSERT_TRUE(before.ok() && after.ok()) << before.message << after.message;
  EXPECT_EQ(before.configuration, Configuration::PartialSlip);
  EXPECT_LT(before.max_first_invariant, 3.6);
  EXPECT_GT(after.max_first_invariant, 3.6);
  std::cout << fmt::format("puncture at {:.9f} mm, {:.9f} N ({})\n",
                           found.depth_mm,
                           found.force_n,
                           found.crack_location);
}

// The filleted punch's face under the gas: the sliding model's face slides (a rough face), the
// family's stays held, so the family's end is not the sliding state; the curve keeps the jump.
TEST(PartialSlipUnderGas, FilletKeepsTheJump) {
  const Problem p = pslip_gas_problem(FlatPunch{2.0, 0.5}, 0.3, 1.2);
  const LoadingCurve c =
      loading_curve(p, CurveOptions{.points = 20, .max_depth_mm = 6.0}, pslip_gas_quiet());
  ASSERT_TRUE(c.ok()) << c.message;
  ASSERT_TRUE(c.stick_slip.occurs);
  EXPECT_FALSE(c.stick_slip.full_sliding_depth_mm);
  for (const CurvePoint& q : c.points) EXPECT_NE(q.configuration, Configuration::PartialSlip);
}

}  // namespace
}  // namespace puncture
