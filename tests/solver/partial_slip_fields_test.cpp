// The fields along the meridian of a partial-slip state (state --depth after a `coulomb` release
// on a curved probe; partial_slip_fields.hpp): the held pole or face, the held core, the slipping
// annulus and Part I.  Checks: the stretches, stresses, position and slope are continuous across
// the slip front and the contact edge (Part I leaves the profile tangentially: its slope from the
// force and its own tension equals the profile's), the contact pressure is >= 0 and on the sphere
// Laplace's law in physical units, the friction traction is below mu p in the held core and mu p
// in the annulus, the vertical balance of Part I's meridian tension (at the edge and at the
// clamp) gives the reported force, and Part I reaches the clamp at r = A, z = 0 (the state's
// depth).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <vector>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "solver_test_support.hpp"

namespace puncture {
namespace {

Problem pslip_fields_problem(const Indenter& indenter, double mu) {
  Problem p = test::paper_problem(Gent{125.0}, mu);
  p.indenter = indenter;
  p.stick = {StickRule::Coulomb, 0.0};
  p.preload.prestretch = 1.2;
  return p;
}

// The index of the point at reference radius r_mm on the probe, the first (`first`) or the last
// of those within 1e-12 mm of it.
std::size_t pslip_fields_index_at(const MembraneFields& m, double r_mm, bool first) {
  std::size_t found = m.size();
  for (std::size_t i = 0; i < m.size(); ++i)
    if (std::abs(m.reference_radius_mm[i] - r_mm) <= 1e-12 * std::max(1.0, r_mm)) {
      found = i;
      if (first) break;
    }
  return found;
}

// The vertical load carried by the meridian tension at point i: 2 pi R s1 H sin(phi) [N] (the
// nominal s1 per reference length of the circumference 2 pi R).
double pslip_fields_pull_n(const Problem& p, const MembraneFields& m, std::size_t i) {
  return 2.0 * std::numbers::pi * m.reference_radius_mm[i] * m.radial_stress_mpa[i] *
         p.geometry.thickness_mm * std::sin(m.slope_rad[i]);
}

void check_partial_slip_fields(const Problem& p, double depth_mm, bool sphere) {
  const Equilibrium e = solve_at_depth(p, depth_mm, Stage::Slip);
  ASSERT_TRUE(e.ok()) << e.message;
  ASSERT_EQ(e.configuration, Configuration::PartialSlip);
  const MembraneFields& m = e.fields;
  ASSERT_GT(m.size(), 30u);
  const double big_a = p.geometry.clamp_radius_mm;
  const double r_front = e.slip_front_reference_radius_mm;
  // Centre outwards.
  for (std::size_t i = 1; i < m.size(); ++i)
    EXPECT_GE(m.reference_radius_mm[i], m.reference_radius_mm[i - 1]) << i;
  // The slip front: the core's point and the annulus's first, continuous in every field but the
  // friction traction, which jumps from the held core's |tau| < mu p to mu p.
  const std::size_t core = pslip_fields_index_at(m, r_front, true);
  ASSERT_LT(core, m.size());
  ASSERT_LT(core + 1, m.size());
  const std::size_t annulus = core + 1;
  ASSERT_NEAR(m.reference_radius_mm[annulus], r_front, 1e-12);
  for (const auto* field : {&m.radius_mm,
                            &m.deflection_mm,
                            &m.slope_rad,
                            &m.radial_stretch,
                            &m.hoop_stretch,
                            &m.radial_stress_mpa,
                            &m.hoop_stress_mpa,
                            &m.first_invariant,
                            &m.contact_pressure_mpa})
    EXPECT_NEAR((*field)[annulus], (*field)[core], 1e-12 * std::max(1.0, std::abs((*field)[core])));
  // Against the neighbouring points: no step across the front larger than twice the largest
  // step between neighbours on either side (a jump would not shrink with the spacing).
  auto largest_step = [&](std::size_t from, std::size_t to) {
    double s = 0.0;
    for (std::size_t i = from; i < to; ++i)
      s = std::max(s, std::abs(m.radial_stretch[i + 1] - m.radial_stretch[i]));
    return s;
  };
  ASSERT_GE(core, 3u);
  EXPECT_LE(std::abs(m.radial_stretch[annulus + 1] - m.radial_stretch[core - 1]),
            2.0 * std::max(largest_step(core - 3, core), largest_step(annulus, annulus + 3)));
  // Where Part I starts: the contact edge, continuous with the annulus's last point; Part I's
  // slope atan2(f, t) from its own tension equals the profile's (tangential departure).
  std::size_t edge = 0;
  while (edge < m.size() && m.part[edge] != MembranePart::Free) ++edge;
  ASSERT_GT(edge, annulus + 2);
  ASSERT_LT(edge, m.size());
  const std::size_t last_on_probe = edge - 1;
  EXPECT_NEAR(m.radius_mm[edge], e.contact_edge_radius_mm, 1e-12);
  for (const auto* field : {&m.reference_radius_mm,
                            &m.radius_mm,
                            &m.deflection_mm,
                            &m.slope_rad,
                            &m.radial_stretch,
                            &m.hoop_stretch,
                            &m.radial_stress_mpa,
                            &m.first_invariant})
    EXPECT_NEAR((*field)[edge], (*field)[last_on_probe], 1e-10 * std::max(1.0, (*field)[edge]));
  // Tractions on the probe: p >= 0; |tau| <= mu p in the held core, = mu p in the annulus; none
  // on Part I.
  for (std::size_t i = 0; i < edge; ++i) {
    EXPECT_GE(m.contact_pressure_mpa[i], 0.0) << i;
    if (i <= core)
      EXPECT_LE(std::abs(m.friction_traction_mpa[i]),
                p.friction * m.contact_pressure_mpa[i] * (1.0 + 1e-9))
          << i;
    else
      EXPECT_NEAR(m.friction_traction_mpa[i], p.friction * m.contact_pressure_mpa[i], 1e-15) << i;
    // On the hemisphere the normal balance is Laplace's: p = (T1 + T2) / a, T = s H / lambda.
    if (sphere && m.reference_radius_mm[i] > 0.0) {
      const double t1 = m.radial_stress_mpa[i] * p.geometry.thickness_mm / m.hoop_stretch[i];
      const double t2 = m.hoop_stress_mpa[i] * p.geometry.thickness_mm / m.radial_stretch[i];
      EXPECT_NEAR(m.contact_pressure_mpa[i], (t1 + t2) / 2.0, 1e-9 * m.contact_pressure_mpa[i])
          << i;
    }
  }
  for (std::size_t i = edge; i < m.size(); ++i) EXPECT_EQ(m.contact_pressure_mpa[i], 0.0);
  // The meridian tension's vertical resultant at the edge and at the clamp is the force.
  const std::size_t clamp = m.size() - 1;
  EXPECT_NEAR(pslip_fields_pull_n(p, m, edge), e.force_n, 1e-10 * e.force_n);
  EXPECT_NEAR(pslip_fields_pull_n(p, m, clamp), e.force_n, 1e-7 * e.force_n);
  // The clamp: R = A / L0, r = A, at the clamp plane (the depth is the edge's height plus
  // Part I's climb).
  EXPECT_NEAR(m.reference_radius_mm[clamp], big_a / p.preload.prestretch, 1e-9 * big_a);
  EXPECT_NEAR(m.radius_mm[clamp], big_a, 1e-8 * big_a);
  EXPECT_NEAR(m.deflection_mm[clamp], 0.0, 1e-8 * depth_mm);
  // The largest I1 reported is the fields' (the contact edge's, sampled by both).
  const double fields_i1 = *std::max_element(m.first_invariant.begin(), m.first_invariant.end());
  EXPECT_NEAR(fields_i1, e.max_first_invariant, 1e-6 * e.max_first_invariant);
  std::cout << fmt::format(
      "depth {:.4f} mm: {} points, front R = {:.6f} mm, edge r = {:.6f} mm, force {:.9f} N, "
      "clamp pull {:+.2e}, clamp z {:+.2e} mm, front tau/p {:.4f} -> {:.4f}\n",
      depth_mm,
      m.size(),
      r_front,
      e.contact_edge_radius_mm,
      e.force_n,
      pslip_fields_pull_n(p, m, clamp) / e.force_n - 1.0,
      m.deflection_mm[clamp],
      m.friction_traction_mpa[core] / m.contact_pressure_mpa[core],
      m.friction_traction_mpa[annulus] / m.contact_pressure_mpa[annulus]);
}

// The sphere-tipped probe (mu = 0.5: released at 0.913 mm, sliding from 3.49 mm) at three depths
// of the partial slip; the filleted punch and the cone (mu = 0.3) half-way through theirs.
TEST(PartialSlipFields, ContinuousAdmissibleAndCarryTheForce) {
  const Problem sphere = pslip_fields_problem(SphereTipped{2.0}, 0.5);
  for (const double depth : {1.2, 2.0, 3.3}) check_partial_slip_fields(sphere, depth, true);
  for (const Indenter& indenter :
       std::vector<Indenter>{FlatPunch{2.0, 0.5}, Cone{2.0, 30.0, 0.5}}) {
    const Problem p = pslip_fields_problem(indenter, 0.3);
    SolverOptions quiet;
    quiet.record_fields = false;
    const LoadingCurve c = loading_curve(p, CurveOptions{.max_depth_mm = 4.0}, quiet);
    ASSERT_TRUE(c.ok()) << c.message;
    ASSERT_TRUE(c.stick_slip.full_sliding_depth_mm);
    check_partial_slip_fields(
        p, 0.5 * (c.stick_slip.depth_mm + *c.stick_slip.full_sliding_depth_mm), false);
  }
}

}  // namespace
}  // namespace puncture
