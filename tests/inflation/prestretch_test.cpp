// The inflation of a pre-stretched membrane (InflationProblem::prestretch, docs/model.md §16):
// the flat state at L0, the small-pressure law of a pre-tensioned membrane (a closed form), an
// exact embedding (the inner disc of an inflated stress-free membrane is an inflated
// pre-stretched one), the pole's burst and the energy identity.
#include <cmath>
#include <numbers>

#include "inflation_test_support.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture {
namespace {

using test::membrane;
using test::solved;

InflationProblem prestretched(double l0, MaterialLaw law = Gent{125.0}) {
  auto p = membrane(law);
  p.prestretch = l0;
  return p;
}

TEST(PrestretchInflation, TheFlatStateIsThePreStretch) {
  const auto p = prestretched(1.3);
  const auto flat = solved(p, 1.3);
  EXPECT_EQ(flat.pressure_mpa, 0.0);
  EXPECT_EQ(flat.volume_mm3, 0.0);
  EXPECT_EQ(flat.pole_height_mm, 0.0);
  ASSERT_FALSE(flat.fields.hoop_stretch.empty());
  for (std::size_t k = 0; k < flat.fields.hoop_stretch.size(); ++k) {
    EXPECT_EQ(flat.fields.hoop_stretch[k], 1.3);
    EXPECT_EQ(flat.fields.radial_stretch[k], 1.3);
  }
  // The clamp's reference radius is the stress-free disc's, A / L0.
  EXPECT_DOUBLE_EQ(flat.fields.reference_radius_mm.back(), 25.0 / 1.3);
  EXPECT_DOUBLE_EQ(flat.fields.radius_mm.back(), 25.0);
  const auto at_zero = inflate_at_pressure(p, 0.0);
  ASSERT_TRUE(at_zero.ok()) << at_zero.message;
  EXPECT_EQ(at_zero.states.front().pole_stretch, 1.3);
}

// A pre-tensioned membrane (true line tension T0 = G H s_eq(L0) / L0) under a small pressure
// p: the in-plane displacements are of second order, the tension stays T0 and the deflection
// solves T0 lap(w) = -p, so w = p (A^2 - r^2) / (4 T0), the pole height p A^2 / (4 T0) and the
// volume pi p A^4 / (8 T0): linear in p, where the unstretched membrane has Hencky's p^(1/3).
// The relative error is O((w / A)^2 G / T0): it falls in proportion to the pole stretch's
// excess over L0 (which goes as w^2).
TEST(PrestretchInflation, SmallPressureMeetsThePreTensionedMembranesLinearLaw) {
  for (const auto& [name, law] : test::laws()) {
    for (const double l0 : {1.1, 1.5}) {
      SCOPED_TRACE(fmt::format("{}, L0 = {}", name, l0));
      const auto p = prestretched(l0, law);
      const double s_eq = membrane_stress(law, l0, l0).s1;
      const double tension = p.material.shear_modulus_mpa * p.thickness_mm * s_eq / l0;
      const double big_a = p.clamp_radius_mm;
      double previous = INFINITY;
      for (const double excess : {1e-4, 1e-5, 1e-6}) {
        const auto s = solved(p, l0 * (1.0 + excess));
        const double pressure = s.pressure_mpa;
        const double height = pressure * big_a * big_a / (4.0 * tension);
        const double volume = std::numbers::pi * pressure * std::pow(big_a, 4) / (8.0 * tension);
        const double error = std::max(std::abs(s.pole_height_mm / height - 1.0),
                                      std::abs(s.volume_mm3 / volume - 1.0));
        test::record(fmt::format("{}_L0_{}_excess_{:g}", name, l0, excess), error);
        // Proportional to the excess: tenfold smaller per decade, with a margin for the
        // states' own 1e-10.
        EXPECT_LT(error, 0.2 * previous + 1e-8);
        EXPECT_LT(error, 10.0 * excess);
        previous = error;
      }
    }
  }
}

// The inner disc R <= R' of a stress-free membrane inflated by p is in equilibrium under p with
// its edge at r' = lambda2(R') R': it is the membrane pre-stretched by L0 = lambda2(R') and
// clamped at A' = r' (the clamp fixes only the edge's radius), with the same pole stretch.  So
// the pre-stretched solver must give the same pressure, and its pole height is the stress-free
// membrane's height of the pole above that ring.  R' is interpolated linearly between 4000
// field samples (spacing 6e-3 mm; the interpolation error of lambda2 is ~1e-8), which bounds
// the agreement: measured <= 1.8e-8 for every law, asserted to 1e-7.
TEST(PrestretchInflation, TheInnerDiscOfAnInflatedMembraneIsAPreStretchedOne) {
  for (const auto& [name, law] : test::laws()) {
    SCOPED_TRACE(name);
    const auto free = membrane(law);
    SolverOptions o;
    o.field_points = 4000;
    const double pole = 1.6;
    const auto big = solved(free, pole, o);
    const auto& f = big.fields;
    for (const double l0 : {1.2, 1.4}) {
      // lambda2 falls from the pole stretch to 1 at the clamp: find where it passes L0.
      std::size_t k = 1;
      while (k < f.hoop_stretch.size() && f.hoop_stretch[k] > l0) ++k;
      ASSERT_LT(k, f.hoop_stretch.size());
      const double t = (f.hoop_stretch[k - 1] - l0) / (f.hoop_stretch[k - 1] - f.hoop_stretch[k]);
      const auto lerp = [&](const std::vector<double>& v) {
        return v[k - 1] + t * (v[k] - v[k - 1]);
      };
      const double r_ref = lerp(f.reference_radius_mm);
      const double ring_height = big.pole_height_mm - lerp(f.deflection_mm);
      auto small = prestretched(l0, law);
      small.clamp_radius_mm = l0 * r_ref;
      const auto inner = solved(small, pole);
      EXPECT_NEAR(inner.pressure_mpa / big.pressure_mpa, 1.0, 1e-7) << "L0 = " << l0;
      EXPECT_NEAR(inner.pole_height_mm / ring_height, 1.0, 1e-7) << "L0 = " << l0;
      test::record(fmt::format("{}_L0_{}_pressure", name, l0),
                   std::abs(inner.pressure_mpa / big.pressure_mpa - 1.0));
    }
  }
}

// The pole is equibiaxial at the pole stretch, whatever the pre-stretch: where the burst is at
// the pole (the paper's Gent membrane), it comes at the same pole stretch, I1 = 2 l^2 + l^-4.
TEST(PrestretchInflation, ThePolesBurstStretchDoesNotDependOnThePreStretch) {
  const auto free = inflation_burst(membrane());
  ASSERT_TRUE(free.ok()) << free.message;
  ASSERT_EQ(free.state.max_first_invariant_reference_radius_mm, 0.0);
  for (const double l0 : {1.2, 2.0}) {
    const auto burst = inflation_burst(prestretched(l0));
    ASSERT_TRUE(burst.ok()) << burst.message;
    EXPECT_EQ(burst.state.max_first_invariant_reference_radius_mm, 0.0);
    EXPECT_NEAR(burst.state.pole_stretch, free.state.pole_stretch, 1e-9);
    EXPECT_NEAR(burst.state.max_first_invariant, 95.2, 1e-6);
  }
}

TEST(PrestretchInflation, StoredEnergyGrowsAsPressureTimesVolume) {
  for (const auto& [name, law] : test::laws()) {
    const auto p = prestretched(1.25, law);
    for (const double l0 : {1.3, 2.0, 3.0}) {
      SCOPED_TRACE(fmt::format("{} at pole stretch {}", name, l0));
      // Central differences as in InflationEnergy (step 1e-3 of the excess over the flat state).
      const double h = 1e-3 * std::min(1.0, l0 - 1.25);
      const auto lo = solved(p, l0 - h), mid = solved(p, l0), hi = solved(p, l0 + h);
      const double du_dv =
          (hi.stored_energy_mj - lo.stored_energy_mj) / (hi.volume_mm3 - lo.volume_mm3);
      EXPECT_NEAR(du_dv / mid.pressure_mpa, 1.0, 1e-5);
    }
  }
}

TEST(PrestretchInflation, CurvesStartFlatAtThePreStretch) {
  InflationCurveOptions c;
  c.points = 20;
  const auto curve = inflation_curve(prestretched(1.5), c);
  ASSERT_TRUE(curve.ok()) << curve.message;
  EXPECT_EQ(curve.states.front().pole_stretch, 1.5);
  EXPECT_EQ(curve.states.front().pressure_mpa, 0.0);
  for (std::size_t k = 1; k < curve.states.size(); ++k)
    EXPECT_GT(curve.states[k].volume_mm3, curve.states[k - 1].volume_mm3);
  // The states at a pressure agree with the curve's.
  const auto& mid = curve.states[5];
  const auto at = inflate_at_pressure(prestretched(1.5), mid.pressure_mpa);
  ASSERT_TRUE(at.ok()) << at.message;
  EXPECT_NEAR(at.states.front().pole_stretch, mid.pole_stretch, 1e-9);
}

TEST(PrestretchInflation, BadPreStretchesAndPoleStretchesAreRefusedByName) {
  for (const double bad : {0.9, -1.0, double(NAN), double(INFINITY)}) {
    const auto errors = validation_errors(prestretched(bad));
    ASSERT_EQ(errors.size(), 1u) << bad;
    EXPECT_EQ(errors.front().parameter, "prestretch");
  }
  // Mounted at or beyond the critical I1: it would burst as it is mounted.
  const auto mounted = validation_errors(prestretched(7.0));
  ASSERT_EQ(mounted.size(), 1u);
  EXPECT_NE(mounted.front().message.find("as it is mounted"), std::string::npos);
  try {
    inflate_at_pole_stretch(prestretched(1.3), 1.2);
    FAIL() << "a pole stretch below the pre-stretch was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("pre-stretch 1.3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace puncture
