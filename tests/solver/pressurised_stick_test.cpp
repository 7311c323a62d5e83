// The stick stage under a held gas pressure (docs/model.md §17.3): the membrane inflated first,
// then held where it touches the probe, from the inflated pole on.  Checks: on the flat face the
// force is the gas pressure times the contact area, held or not; a held membrane dissipates
// nothing (the indenter's work is the change of Pi = U - p V); the held curve is stiffer than the
// sliding one; a vanishing pressure gives the unpressurised held curve; the first material held is
// the dome's pole; the sphere's contact tractions carry the force; `coulomb` releases where the
// held points' |tau| / p reaches mu.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "indentation/contact/flat_punch_held_face.hpp"
#include "indentation/dispatch.hpp"
#include "indentation/inflated_dome.hpp"
#include "pressurised_support.hpp"
#include "puncture/inflation.hpp"
#include "puncture/loading_curve.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

Problem held_under_gas(Problem p, StickCriterion stick = {StickRule::Always, 0.0}) {
  p.stick = stick;
  return p;
}

double inflated_pole_stretch_of(const Problem& p) {
  const auto inflated = inflate_at_pressure(inflation_problem(p), p.preload.pressure_mpa);
  EXPECT_TRUE(inflated.ok()) << inflated.message;
  return inflated.ok() ? inflated.states.front().pole_stretch : 1.0;
}

// On the flat face the membrane is flat: its normal balance is the gas pressure against the face's
// (no curvature), whatever tangential tractions hold it; it leaves the face horizontally (a line
// force there would lift Part I into the face).  So F = p pi c^2 held as well as sliding, c the
// contact disc's radius, to rounding.  The first material held is the dome's pole, at its stretch,
// and the held face is not uniform (the history gave it the edge's stretches).
TEST(PressurisedStick, OnTheHeldFaceTheForceIsThePressureTimesTheContactArea) {
  const Problem p = held_under_gas(flat());
  const double pole = inflated_pole_stretch_of(p), a = radius_mm(p.indenter);
  const auto dome = solve_at_depth(p, 0.0, Stage::Stick, sampled(2000));
  ASSERT_TRUE(dome.ok()) << dome.message;
  for (const double depth : {0.01, 0.05, 0.1, 0.2}) {
    SCOPED_TRACE(fmt::format("depth {} mm", depth));
    const auto e = solve_at_depth(p, depth, Stage::Stick, sampled(400));
    ASSERT_TRUE(e.ok()) << e.message;
    ASSERT_EQ(e.configuration, Configuration::Stick);
    const auto& m = e.fields;
    const auto face = part_indices(m, 3);
    ASSERT_GT(face.size(), 3u);
    double c = 0.0, l_min = std::numeric_limits<double>::infinity(), l_max = 0.0;
    for (const std::size_t i : face) {
      c = std::max(c, m.radius_mm[i]);
      EXPECT_NEAR(m.contact_pressure_mpa[i], kPressureMpa, 1e-15);
      for (const double l : {m.radial_stretch[i], m.hoop_stretch[i]}) {
        l_min = std::min(l_min, l);
        l_max = std::max(l_max, l);
      }
    }
    ASSERT_LT(c, a);
    EXPECT_NEAR(e.force_n / (kPressureMpa * kPi * c * c), 1.0, 1e-12);
    EXPECT_NEAR(m.radial_stretch[face.front()], pole, 1e-12);
    EXPECT_NEAR(m.hoop_stretch[face.front()], pole, 1e-12);
    const auto free = part_indices(m, 1);
    ASSERT_FALSE(free.empty());
    EXPECT_NEAR(m.slope_rad[free.front()], 0.0, 1e-12);
    for (const std::size_t i : free) EXPECT_GE(m.deflection_mm[i], e.depth_mm - 1e-12);
    // Against the dome's stretches of the same material (its fields, linear between 2000
    // samples: ~1e-7).
    double below_dome = std::numeric_limits<double>::infinity();
    for (const std::size_t i : face) {
      const double r_ref = m.reference_radius_mm[i];
      const auto& d = dome.fields;
      const std::size_t k = static_cast<std::size_t>(
          std::upper_bound(d.reference_radius_mm.begin(), d.reference_radius_mm.end(), r_ref) -
          d.reference_radius_mm.begin());
      ASSERT_GT(k, 0u);
      const double s = (r_ref - d.reference_radius_mm[k - 1]) /
                       (d.reference_radius_mm[k] - d.reference_radius_mm[k - 1]);
      const double l1 =
          d.radial_stretch[k - 1] + s * (d.radial_stretch[k] - d.radial_stretch[k - 1]);
      const double l2 = d.hoop_stretch[k - 1] + s * (d.hoop_stretch[k] - d.hoop_stretch[k - 1]);
      below_dome = std::min({below_dome, m.radial_stretch[i] - l1, m.hoop_stretch[i] - l2});
    }
    std::cout << fmt::format(
        "depth {} mm: c {:.6f} mm, held stretches {:.6f} .. {:.6f} (pole {:.6f}), held less the "
        "dome's at the same R: >= {:.3e}\n",
        depth,
        c,
        l_min,
        l_max,
        pole,
        below_dome);
    record(fmt::format("held_face_min_stretch_{}mm", depth), l_min);
    // Not uniform, and not the dome's: the free membrane at the disc's edge is less stretched than
    // the dome was there (the face flattens it; sliding, the face's stretch falls likewise, §17),
    // and material joins with that: held stretches fall below the dome's at the same material
    // (-3.2e-3 at 0.2 mm), tensile all the same.
    EXPECT_GT(l_max - l_min, 1e-4 * depth);
    // The traction reported is the ring's radial balance, tau = H (d(R s1)/dR - s2) / (lambda1 r):
    // again from the fields by central differences in R (second order, uneven steps), against
    // the map's fourth-order differences in c; on the outer three quarters of the disc (near the
    // pole both differences divide the march's start transient, O(c^3), by a small r: ~1e-2 of
    // the largest tau within the first grid steps).
    const double h_mm = p.geometry.thickness_mm;
    double tau_max = 0.0, tau_error = 0.0;
    for (std::size_t j = 1; j + 2 < face.size(); ++j) {
      const std::size_t i0 = face[j - 1], i = face[j], i1 = face[j + 1];
      if (m.radius_mm[i] < 0.25 * c) continue;
      const double r0 = m.reference_radius_mm[i0], r = m.reference_radius_mm[i],
                   r1 = m.reference_radius_mm[i1];
      const double q0 = r0 * m.radial_stress_mpa[i0], q = r * m.radial_stress_mpa[i],
                   q1 = r1 * m.radial_stress_mpa[i1];
      const double dq =
          (q1 - q) / (r1 - r) * (r - r0) / (r1 - r0) + (q - q0) / (r - r0) * (r1 - r) / (r1 - r0);
      const double tau =
          h_mm * (dq - m.hoop_stress_mpa[i]) / (m.radial_stretch[i] * m.radius_mm[i]);
      tau_max = std::max(tau_max, std::abs(m.friction_traction_mpa[i]));
      tau_error = std::max(tau_error, std::abs(tau - m.friction_traction_mpa[i]));
    }
    // The fields' differences err by ~1.7 (h / c)^2 of tau (measured), h = a / 200 the map's step.
    const double h_over_c = a / 200.0 / c;
    EXPECT_LT(tau_error, 4.0 * h_over_c * h_over_c * tau_max)
        << "largest tau " << tau_max << " MPa";
    std::cout << fmt::format("  largest tau {:.4e} MPa, from the fields' balance to {:.2e} of it\n",
                             tau_max,
                             tau_error / tau_max);
    record(fmt::format("held_face_traction_difference_{}mm", depth), tau_error / tau_max);
    EXPECT_LT(below_dome, 0.0);
    for (const std::size_t i : face) EXPECT_GT(m.hoop_stress_mpa[i], 0.0);
    record(fmt::format("held_less_dome_{}mm", depth), below_dome);
  }
}

// A held membrane dissipates nothing: at constant pressure the indenter's work is the change of
// Pi = U - p V (the quadratures of pressurised_support.hpp and membrane_potential.hpp, their own
// error estimates as the tolerance).  An independent check of the held face's history (and the
// sphere's under pressure): a held map that were not what the loading made would break it.
TEST(PressurisedStick, HeldWorkIsTheChangeOfThePotential) {
  for (const auto& [p, depth] : {std::pair{held_under_gas(flat()), 0.2},
                                 std::pair{held_under_gas(flat()), 10.0},
                                 std::pair{held_under_gas(pressurised()), 5.0}}) {
    SCOPED_TRACE(fmt::format("{}, depth {} mm", describe(p.indenter), depth));
    const Quadrature work = simpson_work(p, depth);
    const auto start = solve_at_depth(p, 0.0, Stage::Stick, sampled(2000));
    const auto end = solve_at_depth(p, depth, Stage::Stick, sampled(2000));
    ASSERT_TRUE(start.ok() && end.ok()) << start.message << end.message;
    const Quadrature pi0 = potential(p, start), pi1 = potential(p, end);
    const double change = pi1.value - pi0.value;
    const double tol = work.error + pi0.error + pi1.error + 1e-7 * std::abs(work.value);
    std::cout << fmt::format(
        "work {:.10g} mJ, change of Pi {:.10g} mJ, tolerance {:.3g}\n", work.value, change, tol);
    EXPECT_NEAR(change, work.value, tol);
    record(
        fmt::format("held_relative_difference_{}_{}mm", describe(p.indenter).substr(0, 4), depth),
        std::abs(change / work.value - 1.0));
  }
}

// Held, the material under the probe cannot give the free membrane more length: at the same depth
// the held force exceeds the sliding (frictionless) one, on the face, past it and on the sphere.
// The pole, the first material touched, keeps the dome's pole stretch (reported as the Part III
// stretch of both probes).
TEST(PressurisedStick, HeldIsStifferThanSliding) {
  const double pole = inflated_pole_stretch_of(flat());
  for (const Problem& base : {flat(), pressurised()}) {
    for (const double depth : {0.1, 1.0, 5.0, 20.0}) {
      SCOPED_TRACE(fmt::format("{}, depth {} mm", describe(base.indenter), depth));
      const auto stuck = solve_at_depth(held_under_gas(base), depth, Stage::Stick);
      const auto sliding = solve_at_depth(base, depth, Stage::Slip);
      ASSERT_TRUE(stuck.ok() && sliding.ok()) << stuck.message << sliding.message;
      EXPECT_GT(stuck.force_n, sliding.force_n);
      EXPECT_NEAR(stuck.part_three_stretch, pole, 1e-12);
    }
  }
}

// A vanishing pressure: with the tip at the same height (the unpressurised depth plus the dome's
// height) the held force tends to the unpressurised held force (the sharp punch's held edge at
// a / L0, §9; the sphere's map from the flat membrane, §15.4).  On the sphere the difference is of
// first order in p, as sliding (pressurised_test.cpp): the map forgets its start (§15.4).  The
// flat face is held whole while the force is still P a^2 / 2 -> 0, at the dome's strains, which
// go as p^(2/3) (Hencky): the held face remembers them, the difference is A p^(2/3) - B p (fitted:
// A = 12.1 MPa^(-2/3), B = 5.3e3 / MPa, B as sliding), so d / p^(2/3) converges with increments
// falling by 10^(1/3) per decade.  At p = 0 the same code runs with the gas's terms zero: the
// stick tests and the golden outputs are unchanged.
TEST(PressurisedStick, VanishingPressureGivesTheUnpressurisedHeldForce) {
  const std::vector<double> pressures{1e-9, 1e-10, 1e-11};
  for (const Indenter& indenter : {Indenter{FlatPunch{2.0}}, Indenter{SphereTipped{2.0}}}) {
    SCOPED_TRACE(describe(indenter));
    const double depth = 10.0;
    const auto free =
        solve_at_depth(held_under_gas(pressurised(0.0, 0.0, indenter)), depth, Stage::Stick);
    ASSERT_TRUE(free.ok()) << free.message;
    std::vector<double> differences;
    for (const double pressure : pressures) {
      const Problem p = held_under_gas(pressurised(pressure, 0.0, indenter));
      const auto dome = inflate_at_pressure(inflation_problem(p), pressure);
      ASSERT_TRUE(dome.ok()) << dome.message;
      const double h = dome.states.front().pole_height_mm;
      const auto e = solve_at_depth(p, depth + h, Stage::Stick);
      ASSERT_TRUE(e.ok()) << e.message;
      differences.push_back(std::abs(e.force_n / free.force_n - 1.0));
      std::cout << fmt::format(
          "p {:g} MPa: force {:.10g} N (unpressurised {:.10g}), relative "
          "difference {:.4e}, / p^(2/3) {:.4f}\n",
          pressure,
          e.force_n,
          free.force_n,
          differences.back(),
          differences.back() / std::cbrt(pressure * pressure));
    }
    if (std::holds_alternative<SphereTipped>(indenter)) {
      for (std::size_t k = 1; k < pressures.size(); ++k) {
        EXPECT_LT(differences[k], 0.15 * differences[k - 1]);  // a factor 10 per decade
        EXPECT_LT(differences[k], 1e4 * pressures[k]);
      }
    } else {
      std::vector<double> q;
      for (std::size_t k = 0; k < pressures.size(); ++k)
        q.push_back(differences[k] / std::cbrt(pressures[k] * pressures[k]));
      const double ratio = (q[1] - q[0]) / (q[2] - q[1]);
      EXPECT_NEAR(ratio, std::cbrt(10.0), 0.05 * std::cbrt(10.0));
      EXPECT_LT(differences[2], differences[1]);
      EXPECT_LT(differences[1], differences[0]);
      const double limit = q[2] + (q[2] - q[1]) / (std::cbrt(10.0) - 1.0);
      record("flat_held_force_difference_per_p_two_thirds", limit);
      std::cout << fmt::format("increments' ratio {:.4f} (10^(1/3) = {:.4f}), A = {:.4f}\n",
                               ratio,
                               std::cbrt(10.0),
                               limit);
    }
  }
}

// `coulomb` under pressure (§17.3): held while mu p holds every held point of the face (p the gas
// pressure there) and, past the face, while the held corner's capstan bound holds,
// |ln(s1_I / s1_face)| <= mu phi.  A larger mu holds longer.  At the switch the need equals mu:
// read back from the held state's fields (the face's |tau| / p at its samples, which are the
// map's grid points and the edge; the corner's s1 on both sides and the exit slope).  On the
// face the tractions are linear between grid points in both, so they agree to the switch's root
// tolerance; at the corner the fields' s1 are the state's own.
TEST(PressurisedStick, CoulombReleasesWhereTheHeldPointsNeedMoreThanMuP) {
  double previous_depth = 0.0;
  for (const double mu : {0.05, 0.18, 0.5, 1.0}) {
    SCOPED_TRACE(fmt::format("mu {}", mu));
    Problem p = held_under_gas(flat(), {StickRule::Coulomb, 0.0});
    p.friction = mu;
    const auto b = stick_slip_boundary(p);
    ASSERT_TRUE(b.ok()) << b.message;
    ASSERT_TRUE(b.switches);
    EXPECT_GT(b.depth_mm, previous_depth);
    previous_depth = b.depth_mm;
    const auto e = solve_at_depth(p, b.depth_mm, Stage::Stick, sampled(400));
    ASSERT_TRUE(e.ok()) << e.message;
    const auto& m = e.fields;
    double face_need = 0.0;
    for (const std::size_t i : part_indices(m, 3))
      face_need =
          std::max(face_need, std::abs(m.friction_traction_mpa[i]) / m.contact_pressure_mpa[i]);
    double corner_need = 0.0;
    const double face_load = kPressureMpa * kPi * 4.0;
    if (e.force_n > face_load) {
      const auto face = part_indices(m, 3);
      const auto free = part_indices(m, 1);
      corner_need =
          std::abs(std::log(m.radial_stress_mpa[free.front()] / m.radial_stress_mpa[face.back()])) /
          e.corner_slope_rad;
    }
    const double need = std::max(face_need, corner_need);
    std::cout << fmt::format(
        "mu {}: switch at {:.6g} mm, {:.6g} N ({}), face |tau|/p {:.6f}, corner {:.6f}\n",
        mu,
        b.depth_mm,
        e.force_n,
        e.force_n > face_load ? "past the face" : "on the face",
        face_need,
        corner_need);
    EXPECT_NEAR(need, mu, 1e-3 * mu);
  }
}

}  // namespace
}  // namespace puncture::test

namespace puncture::detail {
namespace {

// The held face's map converges as the Runge-Kutta's fourth order: the held radius R at c = a / 2
// and at the corner (R_a, where the held corner lies past the face) with 10, 20, 40 steps against
// 320 (measured orders 2.4 and 3.3 from 10 to 20, 3.3 and 3.5 from 20 to 40: the sub-stepped
// start, scaled with the step, approaches its asymptotics slowly), and the default 200 steps
// within 1e-12 of 320 (measured ~2e-14: the shooting's tolerance).
TEST(PressurisedStick, HeldFaceMapConvergesWithItsGrid) {
  const Problem p = test::flat();
  const SolverOptions o = test::tight_options();
  ShootingSettings settings = shooting_settings(o);
  const auto dome = inflated_dome(p, o);
  ASSERT_TRUE(dome);
  settings.pressure = dome->pressure;
  settings.dome_pole_stretch = dome->state.part_three_stretch;
  const FreePart<Gent> part_one(std::get<Gent>(p.material.law), settings);
  const double a = contact_settings(p, std::get<FlatPunch>(p.indenter)).a;
  auto measure = [&](int steps) {
    const HeldFaceHistory<Gent> map(part_one, a, settings.dome_pole_stretch, steps);
    EXPECT_TRUE(map.complete());
    return std::pair{map.points()[static_cast<std::size_t>(steps / 2)].r, map.points().back().r};
  };
  const auto exact = measure(320);
  std::vector<std::pair<double, double>> m;
  for (const int n : {10, 20, 40}) m.push_back(measure(n));
  for (std::size_t i = 0; i + 1 < m.size(); ++i) {
    const double order_half =
        std::log2(std::abs(m[i].first - exact.first) / std::abs(m[i + 1].first - exact.first));
    const double order_end =
        std::log2(std::abs(m[i].second - exact.second) / std::abs(m[i + 1].second - exact.second));
    std::cout << fmt::format("steps {} -> {}: order R(a / 2) {:.2f}, R_a {:.2f} (error {:.2e})\n",
                             10 << i,
                             20 << i,
                             order_half,
                             order_end,
                             std::abs(m[i + 1].second - exact.second) / exact.second);
    if (i == 1) {
      EXPECT_GT(order_half, 3.0);
      EXPECT_GT(order_end, 3.0);
    }
    EXPECT_GT(order_half, 2.0);
    EXPECT_GT(order_end, 3.0);
  }
  const auto fine = measure(HeldFaceHistory<Gent>::kDefaultSteps);
  EXPECT_NEAR(fine.first / exact.first, 1.0, 1e-12);
  EXPECT_NEAR(fine.second / exact.second, 1.0, 1e-12);
  std::cout << fmt::format("default steps: R(a / 2) {:.2e}, R_a {:.2e} off\n",
                           std::abs(fine.first / exact.first - 1.0),
                           std::abs(fine.second / exact.second - 1.0));
}

}  // namespace
}  // namespace puncture::detail
