// Indentation of an inflated membrane (Problem::preload.pressure_mpa, docs/model.md §17), with the
// sphere-tipped probe and the flat punch: the state before contact is the inflation solver's, the
// constant-pressure energy balance dPi/ddelta = F with Pi = U - p V, the contact pressure and
// geometry along the contact, F = p pi c^2 while the membrane touches the flat face only, the
// limit of a vanishing pressure, and a pressure no inflated state holds.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "pressurised_support.hpp"
#include "puncture/inflation.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

TEST(Pressurised, BeforeContactTheMembraneIsTheInflationSolversState) {
  for (const Problem& p : {pressurised(), flat()}) {
    SCOPED_TRACE(describe(p.indenter));
    const auto inflated = inflate_at_pressure(inflation_problem(p), kPressureMpa);
    ASSERT_TRUE(inflated.ok()) << inflated.message;
    const InflationState& dome = inflated.states.front();
    const auto e = solve_at_depth(p, 0.0, Stage::Slip, sampled(200));
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(e.force_n, 0.0);
    EXPECT_EQ(e.configuration, Configuration::Unloaded);
    EXPECT_NEAR(e.part_three_stretch, dome.pole_stretch, 1e-12);
    EXPECT_NEAR(e.max_first_invariant, dome.max_first_invariant, 1e-12);
    // The fields: the pole stretch at the centre, the clamp L0 = 1, and the deflection, measured
    // from the inflated pole, reaching the dome's height at the clamp.
    const auto& m = e.fields;
    ASSERT_GT(m.size(), 200u);
    EXPECT_NEAR(m.hoop_stretch.front(), dome.pole_stretch, 1e-12);
    EXPECT_NEAR(m.hoop_stretch.back(), 1.0, 1e-9);
    EXPECT_EQ(m.deflection_mm.front(), 0.0);
    EXPECT_NEAR(m.deflection_mm.back(), dome.pole_height_mm, 1e-9 * dome.pole_height_mm);
    for (std::size_t i = 0; i < m.size(); ++i) EXPECT_EQ(m.part[i], MembranePart::Free);
    // Continuity: a shallow indentation starts from that dome (the pole stretch moves by O(depth)).
    const auto shallow = solve_at_depth(p, 1e-4, Stage::Slip, sampled(200));
    ASSERT_TRUE(shallow.ok()) << shallow.message;
    EXPECT_NEAR(shallow.part_three_stretch, dome.pole_stretch, 1e-4);
    EXPECT_GT(shallow.force_n, 0.0);
  }
}

// Constant pressure, frictionless: the indenter's work is the change of Pi = U - p V,
//   int_0^delta F ddelta = Pi(delta) - Pi(0).
// Work by Simpson's rule on a 401-point curve (error bounded by |S_h - S_2h|); Pi from the fields
// of the end states (2000 samples each, trapezoid + Richardson, error estimated as above).
// The flat punch: on the face alone to 0.2 mm (the contact disc reaches the corner at 0.27 mm),
// then past the onset of Part II.
TEST(Pressurised, WorkIsTheChangeOfThePotentialAtConstantPressure) {
  for (const auto& [p, depth] : {std::pair{pressurised(), 5.0},
                                 std::pair{pressurised(), 20.0},
                                 std::pair{flat(), 0.2},
                                 std::pair{flat(), 20.0}}) {
    SCOPED_TRACE(fmt::format("{}, depth {} mm", describe(p.indenter), depth));
    const Quadrature work = simpson_work(p, depth);
    const double fine = work.value;
    const auto start = solve_at_depth(p, 0.0, Stage::Slip, sampled(2000));
    const auto end = solve_at_depth(p, depth, Stage::Slip, sampled(2000));
    ASSERT_TRUE(start.ok() && end.ok()) << start.message << end.message;
    const Quadrature pi0 = potential(p, start), pi1 = potential(p, end);
    const double change = pi1.value - pi0.value;
    const double tol = work.error + pi0.error + pi1.error + 1e-7 * std::abs(fine);
    EXPECT_NEAR(change, fine, tol) << "work " << fine << " mJ, change of Pi " << change << " mJ";
    const std::string key = fmt::format("{}_{}mm", describe(p.indenter).substr(0, 4), depth);
    record("relative_difference_" + key, std::abs(change / fine - 1.0));
    record("tolerance_relative_" + key, tol / std::abs(fine));
    // The gas's share is not small: without -p V the balance would fail by far.
    Problem no_gas = p;
    no_gas.preload.pressure_mpa = 0.0;
    const double without_gas = potential(no_gas, end).value;
    EXPECT_GT(std::abs(without_gas - fine), 100.0 * tol);
  }
}

// While the membrane touches the flat face only, the gas alone carries the force on the contact
// disc: F = p pi c^2 exactly, c the disc's radius (from the fields: the outermost point under the
// tip), and Part I leaves the face tangentially, below it.  Just past F = p pi a^2 the membrane
// wraps the corner, continuously: the same Part III stretch, a corner slope from zero.
TEST(Pressurised, OnTheFlatFaceTheForceIsThePressureTimesTheContactArea) {
  const Problem p = flat();
  const double a = radius_mm(p.indenter);
  for (const double depth : {0.01, 0.05, 0.1, 0.2}) {
    SCOPED_TRACE(fmt::format("depth {} mm", depth));
    const auto e = solve_at_depth(p, depth, Stage::Slip, sampled(400));
    ASSERT_TRUE(e.ok()) << e.message;
    const auto& m = e.fields;
    double c = 0.0;
    for (std::size_t i = 0; i < m.size(); ++i)
      if (m.part[i] == MembranePart::Tip) c = std::max(c, m.radius_mm[i]);
    ASSERT_LT(c, a);
    EXPECT_NEAR(e.force_n / (kPressureMpa * kPi * c * c), 1.0, 1e-12);
    const auto free = part_indices(m, 1);
    ASSERT_FALSE(free.empty());
    EXPECT_NEAR(m.slope_rad[free.front()], 0.0, 1e-12);
    for (const std::size_t i : free) EXPECT_GE(m.deflection_mm[i], e.depth_mm - 1e-12);
    EXPECT_EQ(e.corner_slope_rad, 0.0);
  }
  const double face_load = kPressureMpa * kPi * a * a;
  const auto below = solve_at_force(p, face_load * (1.0 - 1e-7), Stage::Slip);
  const auto above = solve_at_force(p, face_load * (1.0 + 1e-7), Stage::Slip);
  ASSERT_TRUE(below.ok() && above.ok()) << below.message << above.message;
  EXPECT_NEAR(above.part_three_stretch, below.part_three_stretch, 1e-6);
  EXPECT_NEAR(below.corner_reference_radius_mm * below.part_three_stretch, a, 1e-6);
  EXPECT_LT(above.corner_slope_rad, 1e-3);
  EXPECT_GT(above.corner_slope_rad, 0.0);
}

// Negative control: with Coulomb slip on the hemisphere (mu' = 0.18; the contact stays on it to
// 8 mm) friction dissipates part of the work: the same quadratures (accurate to ~1e-6) show the
// work exceeding the change of Pi by far more, and friction raises the force.
TEST(Pressurised, FrictionDissipatesPartOfTheWork) {
  const Problem p = pressurised(kPressureMpa, 0.18);
  const double depth = 8.0;
  const Quadrature work = simpson_work(p, depth);
  const auto start = solve_at_depth(p, 0.0, Stage::Slip, sampled(2000));
  const auto end = solve_at_depth(p, depth, Stage::Slip, sampled(2000));
  ASSERT_TRUE(start.ok() && end.ok()) << start.message << end.message;
  ASSERT_EQ(end.configuration, Configuration::SlipWithoutPartTwo);
  const double change = potential(p, end).value - potential(p, start).value;
  EXPECT_GT(work.value - change, 1e-3 * work.value);
  record("dissipated_fraction", (work.value - change) / work.value);
  const auto frictionless = solve_at_depth(pressurised(), depth, Stage::Slip);
  EXPECT_GT(end.force_n, frictionless.force_n);
}

// The contact pressure is Laplace's plus the gas pressure (>= p), the hoop stress stays tensile,
// the cap lies on the sphere and Part I never enters it; the contact pressure's axial resultant
// over the cap carries the force (trapezoid + Richardson over the samples: 1e-6).
TEST(Pressurised, ContactPressureAtLeastTheGasPressureAndCarryingTheForce) {
  const Problem p = pressurised();
  const double a = radius_mm(p.indenter), tol = 1e-9 * p.geometry.clamp_radius_mm;
  for (const double depth : {2.0, 8.0}) {
    SCOPED_TRACE(fmt::format("depth {} mm", depth));
    const auto e = solve_at_depth(p, depth, Stage::Slip, sampled(2000));
    ASSERT_TRUE(e.ok()) << e.message;
    ASSERT_EQ(e.configuration, Configuration::SlipWithoutPartTwo);
    const auto& m = e.fields;
    const double centre = e.depth_mm - a;
    std::vector<double> r_squared, normal;
    for (std::size_t i = 0; i < m.size(); ++i) {
      EXPECT_GT(m.hoop_stress_mpa[i], 0.0) << "R " << m.reference_radius_mm[i];
      const double r = m.radius_mm[i], z = m.deflection_mm[i];
      if (m.part[i] == MembranePart::Tip) {
        EXPECT_GE(m.contact_pressure_mpa[i], kPressureMpa);
        EXPECT_NEAR(std::hypot(r, z - centre), a, tol);
        r_squared.push_back(r * r);
        normal.push_back(m.contact_pressure_mpa[i]);
      } else if (r < a) {
        EXPECT_GE(z - (centre + std::sqrt(a * a - r * r)), -tol) << "Part I enters the sphere";
      }
    }
    // On a surface of revolution the axial component of p n dA is p d(pi r^2).
    const Quadrature resultant = integrate(r_squared, normal);
    EXPECT_NEAR(kPi * resultant.value / e.force_n, 1.0, 1e-6);
    record(fmt::format("resultant_relative_error_{}mm", depth),
           std::abs(kPi * resultant.value / e.force_n - 1.0));
  }
}

// A vanishing pressure: the force with the probe's tip at a given height tends to the
// unpressurised one.  Depths are measured from the inflated pole, so the same tip position is the
// unpressurised depth plus the dome's height (Hencky: ~ p^(1/3), 0.13 mm at 1e-9 MPa).  What is
// left is of first order in p (the gas's push on the membrane, and the dome's pre-tension, which
// goes as h^2 ~ p^(2/3) but acts through the indentation's strains): measured 6.68e-6 at 1e-9
// MPa, tenfold smaller per decade.
TEST(Pressurised, VanishingPressureGivesTheUnpressurisedForce) {
  const double depth = 10.0;
  const auto free = solve_at_depth(pressurised(0.0), depth, Stage::Slip);
  ASSERT_TRUE(free.ok()) << free.message;
  double previous = std::numeric_limits<double>::infinity();
  for (const double pressure : {1e-9, 1e-10, 1e-11}) {
    const Problem p = pressurised(pressure);
    const auto dome = inflate_at_pressure(inflation_problem(p), pressure);
    ASSERT_TRUE(dome.ok()) << dome.message;
    const double h = dome.states.front().pole_height_mm;
    const auto e = solve_at_depth(p, depth + h, Stage::Slip);
    ASSERT_TRUE(e.ok()) << e.message;
    const double difference = std::abs(e.force_n / free.force_n - 1.0);
    std::cout << fmt::format(
        "p {:g} MPa: dome {:.4g} mm, force {:.10g} N (unpressurised {:.10g}), "
        "relative difference {:.3e}\n",
        pressure,
        h,
        e.force_n,
        free.force_n,
        difference);
    EXPECT_LT(difference, 0.15 * previous);  // first order: a factor 10 per decade
    EXPECT_LT(difference, 1e4 * pressure);
    previous = difference;
    record(fmt::format("relative_difference_p{:g}", pressure), difference);
  }
}

// A neo-Hookean membrane holds no pressure above its limit point (the paper's: ~8.7e-4 MPa): a
// physical failure before contact.  Gent stiffens again beyond its limit point: at 1e-3 MPa its
// only state is a balloon overhanging the clamp, indented as it stands (overhanging_dome_test).
TEST(Pressurised, APressureNoInflatedStateHoldsIsALimitLoad) {
  Problem neo = pressurised(1e-3);
  neo.material.law = NeoHookean{};
  const auto e = solve_at_depth(neo, 5.0, Stage::Slip);
  EXPECT_EQ(e.status, Status::LimitLoad);
  EXPECT_NE(e.message.find("bursts or snaps through"), std::string::npos) << e.message;
  EXPECT_EQ(failure_kind(e.status), FailureKind::Physical);
  const auto balloon = solve_at_depth(pressurised(1e-3), 5.0, Stage::Slip);
  ASSERT_TRUE(balloon.ok()) << balloon.message;
  EXPECT_GT(balloon.force_n, 0.0);
  Problem negative = pressurised(-1e-4);
  ASSERT_FALSE(validation_errors(negative).empty());
  EXPECT_EQ(validation_errors(negative).front().parameter, "preload.pressure_mpa");
}

}  // namespace
}  // namespace puncture::test
