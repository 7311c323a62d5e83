// The flat punch with Coulomb friction on an inflated membrane (docs/model.md §17): Part III,
// pressed onto the face by the gas, is held back by the traction mu' p and is no longer uniform.
// Checks: F = p pi c^2 on the face whatever the friction; mu' -> 0 gives the frictionless
// solution and p -> 0 the unpressurised friction solution, both at first order; the work of F
// less the change of Pi = U - p V equals the work against the face's friction, computed
// independently from the slip of the material between neighbouring states; where the face's
// material slides (the model assumes outward).
#include <gtest/gtest.h>

#include <algorithm>
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

Problem rough_flat(double friction, double pressure_mpa = kPressureMpa) {
  return pressurised(pressure_mpa, friction, FlatPunch{2.0});
}

// Part III's samples (reference radius, current radius) from the pole to the contact's edge.
struct Face {
  std::vector<double> r_ref, r;
};
Face face_of(const Equilibrium& e) {
  Face out;
  const auto& m = e.fields;
  for (const std::size_t i : part_indices(m, static_cast<int>(MembranePart::Tip))) {
    out.r_ref.push_back(m.reference_radius_mm[i]);
    out.r.push_back(m.radius_mm[i]);
  }
  return out;
}

// r at reference radius x by linear interpolation (x inside the samples).
double radius_at(const Face& f, double x) {
  const auto it = std::upper_bound(f.r_ref.begin(), f.r_ref.end(), x);
  if (it == f.r_ref.begin()) return f.r.front();
  if (it == f.r_ref.end()) return f.r.back();
  const std::size_t k = static_cast<std::size_t>(it - f.r_ref.begin());
  const double t = (x - f.r_ref[k - 1]) / (f.r_ref[k] - f.r_ref[k - 1]);
  return f.r[k - 1] + t * (f.r[k] - f.r[k - 1]);
}

// The work of the face's friction on the membrane, taken with the opposite sign, from the tip at
// 0+ to `depth` [mJ], from n states: over each step the traction mu' p (per current area, towards
// the axis: the model's direction, for material sliding outward) times the slip of the material
// in contact at the step's start, r_{k+1}(R) - r_k(R), on the area d(pi r^2) averaged over the two
// states (trapezoid over the samples).  Positive where the material slides outward (dissipation).
// The material entering the contact during a step slides for part of it: an error of first order
// in the step, removed by Richardson's extrapolation from n and 2 n states.
double face_friction_work(const Problem& p, double depth, int n) {
  const double traction = p.friction * p.preload.pressure_mpa;
  std::vector<Face> faces;
  for (int k = 1; k <= n; ++k) {
    const auto e = solve_at_depth(p, depth * k / n, Stage::Slip, sampled(400));
    EXPECT_TRUE(e.ok()) << e.message;
    faces.push_back(face_of(e));
  }
  double total = 0.0;
  for (std::size_t k = 0; k + 1 < faces.size(); ++k) {
    const Face &a = faces[k], &b = faces[k + 1];
    for (std::size_t i = 0; i + 1 < a.r_ref.size(); ++i) {
      const double rb0 = radius_at(b, a.r_ref[i]), rb1 = radius_at(b, a.r_ref[i + 1]);
      const double slip = 0.5 * ((rb0 - a.r[i]) + (rb1 - a.r[i + 1]));
      const double area =
          0.5 * kPi * ((a.r[i + 1] * a.r[i + 1] - a.r[i] * a.r[i]) + (rb1 * rb1 - rb0 * rb0));
      total += traction * slip * area;
    }
  }
  // The first step, from first contact (a point) to the first state, is of higher order in c.
  return total;
}

// The largest and the smallest slip of Part III's material between the states at depth and
// depth + step [mm]: where both are positive, the whole face slides outward.
std::pair<double, double> face_slip_range(const Problem& p, double depth, double step) {
  const auto a = solve_at_depth(p, depth, Stage::Slip, sampled(400));
  const auto b = solve_at_depth(p, depth + step, Stage::Slip, sampled(400));
  EXPECT_TRUE(a.ok() && b.ok()) << a.message << b.message;
  const Face fa = face_of(a), fb = face_of(b);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 1; i < fa.r_ref.size(); ++i) {
    if (fa.r_ref[i] > fb.r_ref.back()) break;
    const double slip = radius_at(fb, fa.r_ref[i]) - fa.r[i];
    lo = std::min(lo, slip);
    hi = std::max(hi, slip);
  }
  return {lo, hi};
}

// On the face the gas alone carries the force, whatever the friction: F = p pi c^2 (c the
// outermost point of Part III).  Friction makes Part III non-uniform: both stretches grow from
// the pole to the edge, the radial one faster (the series: lambda1 - L = 2 (lambda2 - L)), and
// the contact pressure there is p with the traction mu' p.
TEST(PressurisedFriction, OnTheFaceTheForceIsThePressureTimesTheContactArea) {
  for (const double mu : {0.18, 1.95}) {
    const Problem p = rough_flat(mu);
    const double a = radius_mm(p.indenter);
    for (const double depth : {0.05, 0.2}) {
      SCOPED_TRACE(fmt::format("mu' {}, depth {} mm", mu, depth));
      const auto e = solve_at_depth(p, depth, Stage::Slip, sampled(400));
      ASSERT_TRUE(e.ok()) << e.message;
      const auto& m = e.fields;
      const auto tip = part_indices(m, static_cast<int>(MembranePart::Tip));
      ASSERT_GT(tip.size(), 10u);
      const double c = m.radius_mm[tip.back()];
      ASSERT_LT(c, a);
      EXPECT_NEAR(e.force_n / (kPressureMpa * kPi * c * c), 1.0, 1e-12);
      const std::size_t pole = tip.front(), edge = tip.back();
      EXPECT_GT(m.hoop_stretch[edge], m.hoop_stretch[pole]);
      EXPECT_GT(m.radial_stretch[edge], m.hoop_stretch[edge]);
      EXPECT_NEAR((m.radial_stretch[tip[1]] - m.radial_stretch[pole]) /
                      (m.hoop_stretch[tip[1]] - m.hoop_stretch[pole]),
                  2.0,
                  0.05);
      for (const std::size_t i : tip) {
        EXPECT_EQ(m.contact_pressure_mpa[i], kPressureMpa);
        EXPECT_NEAR(m.friction_traction_mpa[i], mu * kPressureMpa, 1e-18);
      }
      // Part I leaves the face tangentially, below it, with the edge's stretches.
      const auto free = part_indices(m, static_cast<int>(MembranePart::Free));
      ASSERT_FALSE(free.empty());
      EXPECT_NEAR(m.slope_rad[free.front()], 0.0, 1e-12);
      EXPECT_NEAR(m.radial_stretch[free.front()], m.radial_stretch[edge], 1e-9);
      for (const std::size_t i : free) EXPECT_GE(m.deflection_mm[i], e.depth_mm - 1e-12);
      record(fmt::format("edge_over_pole_mu{}_{}mm", mu, depth),
             m.hoop_stretch[edge] / m.hoop_stretch[pole] - 1.0);
    }
  }
}

// mu' -> 0: the frictionless solution (a uniform Part III, solved by other code), at first order
// in mu', on the face and past the onset of Part II.
TEST(PressurisedFriction, VanishingFrictionGivesTheFrictionlessSolution) {
  for (const double depth : {0.2, 3.0, 20.0}) {
    SCOPED_TRACE(fmt::format("depth {} mm", depth));
    const auto frictionless = solve_at_depth(flat(), depth, Stage::Slip);
    ASSERT_TRUE(frictionless.ok()) << frictionless.message;
    double previous = std::numeric_limits<double>::infinity();
    for (const double mu : {1e-3, 1e-4, 1e-5}) {
      const auto e = solve_at_depth(rough_flat(mu), depth, Stage::Slip);
      ASSERT_TRUE(e.ok()) << e.message;
      EXPECT_EQ(e.configuration, frictionless.configuration);
      const double difference = std::abs(e.force_n / frictionless.force_n - 1.0);
      std::cout << fmt::format(
          "depth {} mm, mu' {:g}: force {:.12g} N (frictionless {:.12g}), "
          "relative difference {:.3e}\n",
          depth,
          mu,
          e.force_n,
          frictionless.force_n,
          difference);
      EXPECT_LT(difference, 0.15 * previous);  // first order: a factor 10 per decade
      EXPECT_LT(difference, 10.0 * mu);
      previous = difference;
      record(fmt::format("relative_difference_{}mm_mu{:g}", depth, mu), difference);
    }
  }
}

// p -> 0 with mu' = 0.18: the unpressurised sliding solution (Part III uniform, no traction on
// the face), at first order in p; the tip at the same height (the unpressurised depth plus the
// dome's height), as in Pressurised.VanishingPressureGivesTheUnpressurisedForce.
TEST(PressurisedFriction, VanishingPressureGivesTheUnpressurisedFrictionSolution) {
  const double depth = 10.0;
  const auto unpressurised = solve_at_depth(rough_flat(0.18, 0.0), depth, Stage::Slip);
  ASSERT_TRUE(unpressurised.ok()) << unpressurised.message;
  double previous = std::numeric_limits<double>::infinity();
  for (const double pressure : {1e-9, 1e-10, 1e-11}) {
    const Problem p = rough_flat(0.18, pressure);
    const auto dome = inflate_at_pressure(inflation_problem(p), pressure);
    ASSERT_TRUE(dome.ok()) << dome.message;
    const double h = dome.states.front().pole_height_mm;
    const auto e = solve_at_depth(p, depth + h, Stage::Slip);
    ASSERT_TRUE(e.ok()) << e.message;
    const double difference = std::abs(e.force_n / unpressurised.force_n - 1.0);
    std::cout << fmt::format(
        "p {:g} MPa: force {:.12g} N (unpressurised {:.12g}), relative "
        "difference {:.3e}\n",
        pressure,
        e.force_n,
        unpressurised.force_n,
        difference);
    EXPECT_LT(difference, 0.15 * previous);
    EXPECT_LT(difference, 1e4 * pressure);
    previous = difference;
    record(fmt::format("relative_difference_p{:g}", pressure), difference);
  }
}

// The energy balance with friction: the work of F less the change of Pi = U - p V is the work
// done against the friction.  On the face alone (to 0.2 mm, mu' = 1.95) that work is computed
// independently from the slip between 40 and 80 states (Richardson): the identity holds, and its
// sign shows the face's material sliding inward there (the model's friction then pushes it:
// docs/model.md §17, a limitation).  Over 20 mm (past the corner, with Part II: the capstan and
// the side dissipate too) the friction dissipates, more with more friction.
TEST(PressurisedFriction, WorkLessTheChangeOfThePotentialIsTheFrictionsWork) {
  {
    const Problem p = rough_flat(1.95);
    const double depth = 0.2;
    const Quadrature work = simpson_work(p, depth);
    const auto start = solve_at_depth(p, 0.0, Stage::Slip, sampled(2000));
    const auto end = solve_at_depth(p, depth, Stage::Slip, sampled(2000));
    ASSERT_TRUE(start.ok() && end.ok()) << start.message << end.message;
    const Quadrature pi0 = potential(p, start), pi1 = potential(p, end);
    const double lost = work.value - (pi1.value - pi0.value);
    const double d40 = face_friction_work(p, depth, 40), d80 = face_friction_work(p, depth, 80);
    const double friction_work = 2.0 * d80 - d40;
    const double tol =
        work.error + pi0.error + pi1.error + std::abs(d80 - d40) + 1e-7 * std::abs(work.value);
    std::cout << fmt::format(
        "face: work {:.6e} mJ, work - change of Pi {:.6e} mJ, against friction {:.6e} mJ (40 "
        "states {:.6e}, 80 states {:.6e}), tolerance {:.2e}\n",
        work.value,
        lost,
        friction_work,
        d40,
        d80,
        tol);
    EXPECT_NEAR(lost, friction_work, tol);
    EXPECT_LT(tol, 0.2 * std::abs(friction_work));  // the check can fail
    EXPECT_LT(friction_work, 0.0);                  // inward sliding: the limitation, measured
    record("face_friction_work_relative_difference", std::abs(lost / friction_work - 1.0));
    record("face_friction_work_over_work", friction_work / work.value);
  }
  // Over 20 mm, lubricated: the face slides outward from ~2 mm on, and the friction (face, capstan,
  // side) dissipates.  Dry, the face's material slides inward to beyond 10 mm (below), where the
  // model's friction does work on it: the balance is measured (-0.16 %), not asserted.
  for (const double mu : {0.18, 1.95}) {
    const Problem p = rough_flat(mu);
    const double depth = 20.0;
    const Quadrature work = simpson_work(p, depth);
    const auto start = solve_at_depth(p, 0.0, Stage::Slip, sampled(2000));
    const auto end = solve_at_depth(p, depth, Stage::Slip, sampled(2000));
    ASSERT_TRUE(start.ok() && end.ok()) << start.message << end.message;
    const Quadrature pi0 = potential(p, start), pi1 = potential(p, end);
    const double lost = work.value - (pi1.value - pi0.value);
    const double tol = work.error + pi0.error + pi1.error + 1e-7 * std::abs(work.value);
    std::cout << fmt::format(
        "mu' {}, 20 mm: work {:.6e} mJ, work - change of Pi {:.4f} % of it "
        "(tolerance {:.1e} %)\n",
        mu,
        work.value,
        100.0 * lost / work.value,
        100.0 * tol / work.value);
    if (mu < 1.0) EXPECT_GT(lost, tol);
    record(fmt::format("lost_fraction_mu{}", mu), lost / work.value);
  }
}

// Where the face's material slides (the model assumes outward; docs/model.md §17).  Lubricated:
// inward on the face and just past the corner (as without friction, where the Part III stretch
// falls from the dome's 1.1177 to 1.1100 at ~1.3 mm), outward from ~2 mm on.  Dry: inward still
// at 10 mm (there the face would rather be held, a stick phase the model lacks), outward from
// 20 mm on, to beyond the puncture (77 mm for a 1 mm probe, 112 mm for this 2 mm one).
TEST(PressurisedFriction, WhereTheFaceSlidesOutward) {
  for (const double mu : {0.18, 1.95}) {
    const Problem p = rough_flat(mu);
    for (const double depth : {0.1, 1.0, 2.0, 3.0, 5.0, 10.0, 20.0, 40.0, 70.0}) {
      const auto [lo, hi] = face_slip_range(p, depth, 0.01);
      std::cout << fmt::format(
          "mu' {}, depth {} mm: face slip from {:.3e} to {:.3e} mm\n", mu, depth, lo, hi);
      record(fmt::format("least_slip_mu{}_{}mm", mu, depth), lo);
      if (depth >= (mu < 1.0 ? 2.0 : 20.0))
        EXPECT_GT(lo, 0.0) << "mu' " << mu << ", depth " << depth;
      if (depth <= 1.0 || (mu > 1.0 && depth <= 10.0))
        EXPECT_LT(hi, 0.0) << "mu' " << mu << ", depth " << depth;
    }
  }
}

// The library tells the curve's points whose face slides inward (not the membrane's states)
// from the rest: its first outward point lies where the two-state comparison above puts the
// change of direction (lubricated: inward at 1 mm, outward at 2 mm; dry: inward at 10 mm,
// outward at 20 mm), and a puncture where the face slides outward stays a puncture.
TEST(PressurisedFriction, TheCurveNamesWhereTheFaceStartsSlidingOutward) {
  for (const double mu : {0.18, 1.95}) {
    SCOPED_TRACE(fmt::format("mu' {}", mu));
    CurveOptions curve;
    curve.depths_mm = mu < 1.0 ? std::vector<double>{0.5, 1.0, 1.5, 2.0, 3.0, 4.0}
                               : std::vector<double>{5.0, 10.0, 15.0, 20.0, 25.0};
    const auto c = loading_curve(rough_flat(mu), curve);
    ASSERT_TRUE(c.ok()) << c.message;
    ASSERT_TRUE(c.face_slides_outward_from_mm.has_value());
    EXPECT_GT(*c.face_slides_outward_from_mm, mu < 1.0 ? 1.0 : 10.0);
    EXPECT_LE(*c.face_slides_outward_from_mm, mu < 1.0 ? 2.0 : 20.0);
    EXPECT_GT(face_slip_range(rough_flat(mu), *c.face_slides_outward_from_mm, 0.01).first, 0.0);
  }
  // Without friction or without gas the question does not arise.
  CurveOptions curve;
  curve.depths_mm = {1.0, 2.0};
  EXPECT_FALSE(loading_curve(rough_flat(0.0), curve).face_slides_outward_from_mm.has_value());
  Problem unpressurised;
  EXPECT_FALSE(loading_curve(unpressurised, curve).face_slides_outward_from_mm.has_value());
}

// The seed's Fig. 14 situation: its steel indenter of radius 1 mm on an inflated membrane (the
// paper gives no pressure nor balloon size: the paper's membrane at 3e-4 MPa), lubricated (0.18)
// and dry (1.95): both puncture, the dry membrane later and at a larger force (as measured).
TEST(PressurisedFriction, LubricatedAndDryPunctureOfTheInflatedMembrane) {
  PuncturePrediction previous;
  for (const double mu : {0.18, 1.95}) {
    const Problem p = pressurised(kPressureMpa, mu, FlatPunch{1.0});
    const auto puncture = predict_puncture(p);
    ASSERT_TRUE(puncture.ok()) << puncture.message;
    std::cout << fmt::format(
        "mu' {}: puncture at {:.6g} mm, {:.6g} N\n", mu, puncture.depth_mm, puncture.force_n);
    if (mu > 1.0) {
      EXPECT_GT(puncture.force_n, previous.force_n);
      EXPECT_GT(puncture.depth_mm, previous.depth_mm);
    }
    previous = puncture;
  }
}

}  // namespace
}  // namespace puncture::test
