// The held membrane pivoting over the cone's kink (docs/model.md §15.5, "Past the kink"): once the
// held contact edge reaches the kink onto the shank, the kink's material point stays there and
// Part I leaves it at a slope between the cone's and the vertical.  Checks: the pivot starts from
// the history's last (tangent) state; work conjugacy along the pivot (held points do no work);
// the kink's ring force from the held cap's tractions (global vertical equilibrium) against the
// jump of the meridian stress resultants; admissibility (contact pressure >= 0, hoop tension);
// the end at the vertical exit (StickWrapsSide); the CLI's case reaches its puncture.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <optional>
#include <vector>

#include "indentation/dispatch.hpp"
#include "indentation/shooting.hpp"
#include "indentation/solver_scales.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "solver_test_support.hpp"
#include "sphere_model_energy.hpp"

namespace puncture::detail {
namespace cone_kink_pivot_test {

Problem held_cone(double half_angle_deg, double tip_mm) {
  Problem p = test::paper_problem(Gent{125.0}, 0.0);
  p.indenter = Cone{2.0, half_angle_deg, tip_mm};
  p.stick = {StickRule::Always, 0.0};
  return p;
}

using ConeShooting = IndentationShooting<SphereTippedContact<Gent>>;

// The shooting holds the problem's law by reference: `p` must outlive it.
ConeShooting cone_shooting(const Problem& p, const SolverOptions& o) {
  return ConeShooting(std::get<Gent>(p.material.law),
                      shooting_settings(o, p.preload.prestretch),
                      contact_settings(p, std::get<Cone>(p.indenter)),
                      false);
}

// At the kink's force the pivot's start at the cone's slope is the history's tangent edge start
// (the same Part I start to rounding), and the states just below and above the kink's force
// (1e-9 apart relative) agree with the history's last point: force, depth, the edge's stretch
// and the pole's (held at the first touch) to 1e-8 relative (the depth moves by ~1e-9 relative
// over the step; the history's last point is solved with the clamp tolerance 1e-13).
TEST(ConeKinkPivot, StartsFromTheLastTangentHeldState) {
  const Problem p = held_cone(30.0, 0.2);
  const auto shooting = cone_shooting(p, test::tight_options());
  const auto& history = shooting.contact().held_profile_history();
  const auto pivot = shooting.contact().kink_pivot();
  ASSERT_TRUE(pivot.follows());
  const StuckPoint k = pivot.kink();
  const double tangency = history.profile().tangency;
  EXPECT_LT(history.profile().end_psi - k.theta, 1e-6);

  const auto tangent = history.edge_start(k.r, k.f);
  const auto pivoting = pivot.start(pivot.parameter_of(tangency), k.f);
  ASSERT_TRUE(tangent && pivoting);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(pivoting->state[i], tangent->state[i], 1e-12 * std::abs(tangent->state[i])) << i;
  EXPECT_NEAR(pivoting->slope, tangency, 1e-14);
  EXPECT_NEAR(pivoting->ratio, 1.0, 1e-12);

  const double s1_kink =
      membrane_stress(shooting.contact().law(), k.l1, history.profile().radius(k.theta) / k.r).s1;
  const auto below = shooting.solve(Stage::Stick, k.f * (1.0 - 1e-9));
  const auto above = shooting.solve(Stage::Stick, k.f * (1.0 + 1e-9));
  ASSERT_TRUE(below.ok() && above.ok()) << below.message << " / " << above.message;
  EXPECT_GE(below.parameter, pivot.kink_parameter());
  EXPECT_LT(above.parameter, pivot.kink_parameter());
  for (const auto* s : {&below, &above}) {
    EXPECT_NEAR(s->depth, k.depth, 1e-8 * k.depth);
    EXPECT_NEAR(s->part_three_stretch, 1.0, 0.0);
    EXPECT_NEAR(s->edge_s1, s1_kink, 1e-7 * s1_kink);
    EXPECT_NEAR(s->corner_slope, tangency, 1e-6);
    EXPECT_NEAR(s->max_i1, below.max_i1, 1e-7 * below.max_i1);
  }
  std::cout << fmt::format(
      "kink reached at F = {:.6f} N, depth {:.4f} mm; across it: depth {:.3e}, slope {:.3e} rad\n",
      test::force_at(p, k.f),
      k.depth * solver_scales(p).length_mm,
      above.depth / below.depth - 1.0,
      above.corner_slope - below.corner_slope);
}

// The stored energy (/ (2 pi G H A^2)) of a pivoting state at force f and its depth: the held
// cap's is frozen (its points keep their stretches), Part I's from its start at the kink by the
// free-membrane system that carries the energy.
struct PivotEnergy {
  double energy;
  double depth;
};

std::optional<PivotEnergy> pivot_energy(const ConeShooting& shooting, double f) {
  const auto sol = shooting.solve(Stage::Stick, f);
  if (!sol.ok() || !shooting.contact().kink_pivot().pivoting(sol.parameter)) return std::nullopt;
  const auto st = shooting.contact().free_start(Configuration::Stick, f, sol.parameter);
  if (!st) return std::nullopt;
  const auto part_one = test::part_one_energy(shooting.contact().law(), f, *st);
  if (!part_one) return std::nullopt;
  return PivotEnergy{*part_one, sol.depth};
}

// Work conjugacy along the pivot: the probe's tractions on the held cap and the kink's ring force
// act on material moving with the probe, so a held membrane dissipates nothing and dU/ddelta = F
// (U's held cap is constant here; Part I carries the change).  Four-point central differences in
// f (step 1e-3 f, error ~1e-12 relative); the clamp tolerance 1e-13 bounds the rest.  Asserted
// 1e-6 at a pivot just started, half-way and near the vertical exit.  A wrong kink kinematics
// (lambda2 not a / R_k, the depth without the kink's height) would miss by far more.
TEST(ConeKinkPivot, WorkEqualsStoredEnergy) {
  const Problem p = held_cone(30.0, 0.2);
  const auto shooting = cone_shooting(p, test::tight_options());
  const auto pivot = shooting.contact().kink_pivot();
  ASSERT_TRUE(pivot.follows());
  const double f_kink = pivot.kink().f;
  for (const double f : {1.05 * f_kink, 4.0 * f_kink, 20.0 * f_kink}) {
    const double h = 1e-3 * f;
    std::vector<PivotEnergy> e;
    for (const double df : {-2.0 * h, -h, h, 2.0 * h}) {
      const auto x = pivot_energy(shooting, f + df);
      ASSERT_TRUE(x) << f + df;
      e.push_back(*x);
    }
    const double de = e[0].energy - 8.0 * e[1].energy + 8.0 * e[2].energy - e[3].energy;
    const double dd = e[0].depth - 8.0 * e[1].depth + 8.0 * e[2].depth - e[3].depth;
    const double ratio = de / dd / f;
    const auto sol = shooting.solve(Stage::Stick, f);
    std::cout << fmt::format(
        "pivot at f {:.4f} (exit slope {:.4f} rad): dU/ddelta / F - 1 = {:.3e}\n",
        f,
        sol.corner_slope,
        ratio - 1.0);
    EXPECT_NEAR(ratio, 1.0, 1e-6) << f;
  }
}

// The kink's ring force two ways: from global vertical equilibrium of the held cap, f less the
// vertical resultant of the probe's tractions on the cap (int (p cos(phi) + tau sin(phi)) r lambda1
// dR over the history's grid, composite Simpson on its uniform part, trapezoid on the last,
// shorter interval), and from the jump of the meridian stress resultants over the kink,
// R_k (s1+ sin(phi) - s1- sin(phi_t)).  The quadrature is the only error: tau jumps at the tip
// sphere's tangency and the grid's tau is first order next to it, so Simpson's rule is bounded
// by its difference from the trapezoid rule's (measured: Simpson 1.6e-5 off f_k = 0.1314, the
// trapezoid 8.1e-5), the tolerance.  The radial component,
// R_k (s1+ cos(phi) - s1- cos(phi_t)), points outward and the ring force presses the membrane on
// the kink: its component along the kink's bisector is >= 0.
TEST(ConeKinkPivot, RingForceFromTheHeldCapsEquilibrium) {
  const Problem p = held_cone(30.0, 0.2);
  const auto shooting = cone_shooting(p, test::tight_options());
  const auto& history = shooting.contact().held_profile_history();
  const auto pivot = shooting.contact().kink_pivot();
  ASSERT_TRUE(pivot.follows());
  const auto& pts = history.points();
  const HeldProfile& q = history.profile();
  auto integrand = [&](std::size_t k) {
    const auto t = history.traction(k);
    const double phi = q.slope(pts[k].theta);
    return (t.pressure * std::cos(phi) + t.tangential * std::sin(phi)) * q.radius(pts[k].theta) *
           pts[k].l1;
  };
  // The uniform grid's intervals: an even number by Simpson (the first one by trapezoid if odd).
  const std::size_t n = pts.size() - 1;  // intervals; the last is the shorter one
  const double h = history.step();
  double cap = 0.0;
  std::size_t k0 = 0;
  if ((n - 1) % 2 == 1) {
    cap += 0.5 * h * (integrand(0) + integrand(1));
    k0 = 1;
  }
  for (std::size_t k = k0; k + 2 <= n - 1; k += 2)
    cap += h / 3.0 * (integrand(k) + 4.0 * integrand(k + 1) + integrand(k + 2));
  cap += 0.5 * (pts[n].r - pts[n - 1].r) * (integrand(n - 1) + integrand(n));
  double trapezoid = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    trapezoid += 0.5 * (pts[k + 1].r - pts[k].r) * (integrand(k) + integrand(k + 1));
  std::cout << fmt::format("cap's resultant: Simpson {:.9e}, trapezoid {:.9e}, f_k {:.9e}\n",
                           cap,
                           trapezoid,
                           pivot.kink().f);
  const double quadrature_error = std::abs(cap - trapezoid);
  EXPECT_NEAR(cap, pivot.kink().f, quadrature_error);
  for (const double f : {1.5 * pivot.kink().f, 10.0 * pivot.kink().f}) {
    const auto sol = shooting.solve(Stage::Stick, f);
    ASSERT_TRUE(sol.ok()) << sol.message;
    const auto st = shooting.contact().free_start(Configuration::Stick, f, sol.parameter);
    ASSERT_TRUE(st);
    const auto ring = pivot.ring_force(*st);
    EXPECT_NEAR(ring.vertical, f - cap, quadrature_error);
    const double s1_held = membrane_stress(shooting.contact().law(),
                                           pivot.kink().l1,
                                           q.radius(pivot.kink().theta) / pivot.kink().r)
                               .s1;
    const double s1_out = membrane_stress(shooting.contact().law(), st->state[1], st->state[2]).s1;
    EXPECT_NEAR(ring.radial,
                pivot.kink().r * (s1_out * std::cos(st->slope) - s1_held * std::cos(q.tangency)),
                1e-12 * std::abs(ring.radial));
    // Along the bisector's inward normal, (-sin, cos) of the mean slope: pressing the kink.
    const double mean = 0.5 * (st->slope + q.tangency);
    EXPECT_GE(-ring.radial * std::sin(mean) + ring.vertical * std::cos(mean), 0.0);
    std::cout << fmt::format(
        "f {:.4f}: ring force vertical {:.6e} (cap's equilibrium {:.6e}), radial {:.4e}\n",
        f,
        ring.vertical,
        f - cap,
        ring.radial);
  }
}

// A pivoting state (40 mm, the exit at 80 deg) is admissible: contact pressure >= 0 and hoop
// tension on the held cap (an ok state: no wrinkling), the exit slope between the cone's and the
// vertical, Part I outside the shank (r >= a, to the kink point's distance from the kink).
TEST(ConeKinkPivot, PivotingStatesAreAdmissible) {
  Problem p = held_cone(30.0, 0.2);
  const auto eq = solve_at_depth(p, 40.0, Stage::Stick);
  ASSERT_TRUE(eq.ok()) << eq.message;
  const double tangency = test::kHalfPi - 30.0 * test::kPi / 180.0;
  EXPECT_GT(eq.corner_slope_rad, tangency + 0.1);
  EXPECT_LT(eq.corner_slope_rad, test::kHalfPi);
  const auto& m = eq.fields;
  const auto held = test::part_indices(m, 3), free = test::part_indices(m, 1);
  ASSERT_GT(held.size(), 20u);
  for (const auto i : held) {
    EXPECT_GE(m.contact_pressure_mpa[i], 0.0) << i;
    if (m.radial_stretch[i] != 1.0 || m.hoop_stretch[i] != 1.0)
      EXPECT_GT(m.hoop_stress_mpa[i], 0.0) << i;
  }
  // The kink's held point lies within 1e-6 rad (rho 1e-6 = 2e-7 mm of arc) of the kink.
  for (const auto i : free) EXPECT_GE(m.radius_mm[i], 2.0 - 2e-7) << i;
}

// The pivot ends where the exit reaches the vertical: beyond, the held membrane would wrap the
// shank (StickWrapsSide, as the sphere-tipped probe's held membrane at its equator).  The last
// states before it leave the kink within 1e-3 rad of the vertical.
TEST(ConeKinkPivot, EndsWhereTheExitIsVertical) {
  const Problem p = held_cone(30.0, 0.2);
  const auto shooting = cone_shooting(p, SolverOptions{});
  double lo = shooting.contact().kink_pivot().kink().f, hi = 100.0 * lo;
  auto hi_state = shooting.solve(Stage::Stick, hi);
  ASSERT_EQ(hi_state.status, Status::StickWrapsSide) << hi_state.message;
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (lo + hi);
    const auto s = shooting.solve(Stage::Stick, mid);
    ASSERT_TRUE(s.ok() || s.status == Status::StickWrapsSide) << s.message;
    (s.ok() ? lo : hi) = mid;
  }
  const auto last = shooting.solve(Stage::Stick, lo);
  ASSERT_TRUE(last.ok());
  EXPECT_GT(last.corner_slope, test::kHalfPi - 1e-3);
  std::cout << fmt::format(
      "the exit reaches the vertical at f = {:.6f} (slope {:.6f} rad)\n", lo, last.corner_slope);
}

// The cone's kink tends to the sharp punch's held corner (§9) as its half-angle tends to 90 deg:
// the flank flattens into the punch's face and the tip sphere's share vanishes, the held cap
// tends to the flat membrane at rest under the face and the kink's pivot to the held corner's
// exit (a second code: flat_punch.hpp, shooting on the line tension).  The force at 10 and 40 mm
// (both pivoting) converges at first order in 90 deg - alpha: relative errors 16.4, 8.3, 4.2,
// 2.1 % at 10 mm and 2.15, 1.12, 0.58, 0.29 % at 40 mm for 90 - alpha = 20, 10, 5, 2.5 deg (rates
// 0.94-0.99); asserted: each halving divides the error by 1.7 to 2.3.
TEST(ConeKinkPivot, TendsToTheFlatPunchHeldAtItsCornerAsTheConeFlattens) {
  Problem punch = test::paper_problem(Gent{125.0}, 0.0);
  punch.stick = {StickRule::Always, 0.0};
  for (const double depth : {10.0, 40.0}) {
    const auto sharp = solve_at_depth(punch, depth, Stage::Stick);
    ASSERT_TRUE(sharp.ok()) << sharp.message;
    std::vector<double> errors;
    for (const double gap : {20.0, 10.0, 5.0, 2.5}) {
      const auto eq = solve_at_depth(held_cone(90.0 - gap, 0.2), depth, Stage::Stick);
      ASSERT_TRUE(eq.ok()) << eq.message;
      errors.push_back(std::abs(eq.force_n / sharp.force_n - 1.0));
      std::cout << fmt::format("{} mm, cone {} deg: force {:.6f} N (sharp punch held {:.6f} N)\n",
                               depth,
                               90.0 - gap,
                               eq.force_n,
                               sharp.force_n);
    }
    for (std::size_t k = 1; k < errors.size(); ++k) {
      EXPECT_GT(errors[k - 1] / errors[k], 1.7) << depth << " " << k;
      EXPECT_LT(errors[k - 1] / errors[k], 2.3) << depth << " " << k;
    }
  }
}

// The case the held history could not finish (it ended at the kink at 0.2477 N, largest I1 5.05):
// pivoting, it punctures at the kink, where the membrane leaves the probe (the largest I1 at the
// kink's material), stuck, the critical I1 met; the 60 deg, 0.5 mm cone too.
TEST(ConeKinkPivot, HeldConePuncturesAtTheKink) {
  for (const auto& [angle, tip] :
       std::vector<std::pair<double, double>>{{30.0, 0.2}, {60.0, 0.5}}) {
    const Problem p = held_cone(angle, tip);
    const auto punct = predict_puncture(p);
    ASSERT_TRUE(punct.ok()) << punct.message;
    EXPECT_EQ(punct.stage, Stage::Stick);
    EXPECT_NE(punct.crack_location.find("kink"), std::string::npos) << punct.crack_location;
    EXPECT_NEAR(punct.crack_radius_mm, 2.0, 1e-6);
    const auto shooting = cone_shooting(p, SolverOptions{});
    const double r_kink = shooting.contact().kink_pivot().kink().r * solver_scales(p).length_mm;
    EXPECT_NEAR(punct.crack_reference_radius_mm, r_kink, 1e-9 * r_kink);
    EXPECT_GT(punct.force_n, test::force_at(p, shooting.contact().kink_pivot().kink().f));
    std::cout << fmt::format("cone {} deg, tip {} mm, held: punctures at {:.5f} N, {:.3f} mm\n",
                             angle,
                             tip,
                             punct.force_n,
                             punct.depth_mm);
  }
}

// The Coulomb rule at a held kink (pre-stretched, L0 = 1.2, mu = 4: the cap's points hold, the
// kink does not for long): the kink needs mu >= |ln(s1+ / s1-)| / (phi - phi_t) (the capstan law
// over the angle it is wrapped), and the rule releases on the pivot, where that ratio reaches mu
// (the held ratio at the switch is mu to 1e-6, the cap's own largest ratio below it).
TEST(ConeKinkPivot, CoulombReleasesWhereTheKinksCapstanRatioReachesMu) {
  Problem p = held_cone(30.0, 0.5);
  p.preload.prestretch = 1.2;
  p.friction = 4.0;
  p.stick = {StickRule::Coulomb, 0.0};
  const auto boundary = stick_slip_boundary(p);
  ASSERT_TRUE(boundary.ok()) << boundary.message;
  ASSERT_TRUE(boundary.switches);
  const auto shooting = cone_shooting(p, SolverOptions{});
  const auto pivot = shooting.contact().kink_pivot();
  ASSERT_TRUE(pivot.follows());
  const double f = boundary.force_stuck_n / solver_scales(p).force_n;
  EXPECT_GT(f, pivot.kink().f);
  const auto sol = shooting.solve(Stage::Stick, f);
  ASSERT_TRUE(sol.ok()) << sol.message;
  const auto st = shooting.contact().free_start(Configuration::Stick, f, sol.parameter);
  ASSERT_TRUE(st);
  const double kink = pivot.kink_ratio(*st);
  const double capstan = std::log(st->ratio) / (st->slope - pivot.slope_of(pivot.kink_parameter()));
  EXPECT_NEAR(kink, capstan, 1e-12 * capstan);
  EXPECT_NEAR(sol.held_traction_ratio, p.friction, 1e-6 * p.friction);
  EXPECT_NEAR(kink, p.friction, 1e-6 * p.friction);
  const double cap = shooting.contact().held_profile_history().held_ratio(pivot.kink().r);
  EXPECT_LT(cap, p.friction);
  std::cout << fmt::format(
      "coulomb mu 4, L0 1.2: released on the pivot at {:.4f} mm, {:.5f} N (exit {:.4f} rad, "
      "s1+/s1- {:.4f}); the cap's largest ratio {:.4f}\n",
      boundary.depth_mm,
      boundary.force_stuck_n,
      st->slope,
      st->ratio,
      cap);
}

// The held loading curve (depth control, 200 points) crosses the kink without a switch: force
// and exit slope grow with the depth, the exit slope stays the flank's up to the kink's depth and
// steepens past it, and the curve ends at the puncture, its points on the held states at a force
// (each point's depth from its force to 1e-7 relative: the depth Newton and the force shooting
// agree across the kink).
TEST(ConeKinkPivot, HeldCurveCrossesTheKink) {
  const Problem p = held_cone(30.0, 0.2);
  const auto curve = loading_curve(p);
  ASSERT_TRUE(curve.ok()) << curve.message;
  const auto shooting = cone_shooting(p, SolverOptions{});
  const double kink_depth =
      shooting.contact().kink_pivot().kink().depth * solver_scales(p).length_mm;
  const double flank = test::kHalfPi - 30.0 * test::kPi / 180.0;
  int before = 0, past = 0;
  for (std::size_t k = 1; k < curve.points.size(); ++k) {
    const auto& q = curve.points[k];
    EXPECT_EQ(q.stage, Stage::Stick);
    EXPECT_GT(q.force_n, curve.points[k - 1].force_n) << k;
    EXPECT_GE(q.corner_slope_rad, curve.points[k - 1].corner_slope_rad - 1e-12) << k;
    if (q.depth_mm < kink_depth * (1.0 - 1e-6) && q.corner_slope_rad >= flank - 1e-12) {
      EXPECT_NEAR(q.corner_slope_rad, flank, 1e-9) << k;
      ++before;
    }
    if (q.depth_mm > kink_depth * (1.0 + 1e-6)) {
      EXPECT_GT(q.corner_slope_rad, flank) << k;
      ++past;
      if (k % 20 == 0) {
        const auto e = solve_at_force(p, q.force_n, Stage::Stick);
        ASSERT_TRUE(e.ok()) << e.message;
        EXPECT_NEAR(e.depth_mm, q.depth_mm, 1e-7 * q.depth_mm) << k;
      }
    }
  }
  EXPECT_GT(before, 3);
  EXPECT_GT(past, 100);
  EXPECT_NEAR(
      curve.points.back().depth_mm, curve.puncture.depth_mm, 1e-9 * curve.puncture.depth_mm);
}

}  // namespace cone_kink_pivot_test
}  // namespace puncture::detail
