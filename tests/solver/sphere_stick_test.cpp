// The stick stage on the sphere-tipped probe (docs/model.md §15.4): each material point holds
// where it touched the sphere, the contact map built along the loading history.  Checks: work
// conjugacy (a held membrane dissipates nothing: dU/ddelta = F), the traction demand against the
// vertical balance, the history's convergence order, the stick -> slip switch through the
// unchanged curve driver, and the admissibility of the held states.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <iostream>
#include <optional>
#include <vector>

#include "indentation/dispatch.hpp"
#include "indentation/shooting.hpp"
#include "mechanics/free_membrane_ode.hpp"
#include "puncture/loading_curve.hpp"
#include "solver_test_support.hpp"
#include "sphere_model_energy.hpp"

namespace puncture::detail {
namespace {

Problem held_sphere_problem(StickCriterion stick = {StickRule::Always, 0.0}) {
  Problem p = test::paper_problem(Gent{125.0}, 0.0);
  p.indenter = SphereTipped{2.0};
  p.stick = stick;
  return p;
}

using HeldSphereShooting = IndentationShooting<SphereTippedContact<Gent>>;

HeldSphereShooting make_held_sphere_shooting(const Problem& p, const SolverOptions& o) {
  return HeldSphereShooting(std::get<Gent>(p.material.law),
                            shooting_settings(o),
                            contact_settings(p, std::get<SphereTipped>(p.indenter)),
                            false);
}

// The stored energy (/ (2 pi G H A^2)) of the held state at force f and its depth: the cap's
// int W(lambda1, a sin(theta) / R) R dR over the history's interpolant (10-point Gauss-Legendre
// on each grid interval, exact for its piecewise polynomials to ~1e-14), Part I's by the
// free-membrane system that carries the energy.  Apart from the solve's own bookkeeping.
struct HeldEnergy {
  double energy;
  double depth;
};

std::optional<HeldEnergy> held_energy_at(const HeldSphereShooting& shooting, double f) {
  const auto sol = shooting.solve(Stage::Stick, f);
  if (!sol.ok()) return std::nullopt;
  const auto& contact = shooting.contact();
  const auto& history = contact.held_profile_history();
  const auto& law = contact.law();
  const double a = contact.settings().a, r_edge = 1.0 / sol.parameter;
  auto density = [&](double r) {
    const double l1 = *history.stretch_at(r), l2 = a * std::sin(*history.psi_at(r)) / r;
    return strain_energy_density(law, l1, l2, first_invariant(l1, l2)) * r;
  };
  double energy = 0.0;
  for (double r = 0.0; r < r_edge; r += history.step()) {
    const double end = std::min(r + history.step(), r_edge);
    energy += boost::math::quadrature::gauss<double, 10>::integrate(density, r, end);
  }
  const auto st = contact.free_start(Configuration::Stick, f, sol.parameter);
  if (!st) return std::nullopt;
  const auto part_one = test::part_one_energy(law, f, *st);
  if (!part_one) return std::nullopt;
  return HeldEnergy{energy + *part_one, sol.depth};
}

// Work conjugacy of the held membrane: the probe's tractions act on material moving with it,
// and the point joining at the edge carries no line force, so the probe's work is the stored
// energy, dU/ddelta = F (normalised de/dd = f).  Four-point central differences in f (step 1e-3
// f, truncation ~1e-12); the held states solved to 1e-13.  The interpolated history's own
// consistency (the edge's lambda1 against a dtheta/dR between grid points, O(h^3) with h/a =
// 4e-3) bounds it by ~1e-7; measured 7e-10 at most; 1e-6 is the bound.  A missing
// tangential traction's work, or an edge whose stretch the history did not follow, would miss by
// far more.
TEST(SphereStick, WorkEqualsStoredEnergy) {
  const Problem p = held_sphere_problem();  // the shooting holds its law
  const auto shooting = make_held_sphere_shooting(p, test::tight_options());
  for (const double f : {0.002, 0.006, 0.012, 0.02}) {
    const double h = 1e-3 * f;
    std::vector<HeldEnergy> e;
    for (const double df : {-2.0 * h, -h, h, 2.0 * h}) {
      const auto x = held_energy_at(shooting, f + df);
      ASSERT_TRUE(x) << f;
      e.push_back(*x);
    }
    const double de = (e[0].energy - 8.0 * e[1].energy + 8.0 * e[2].energy - e[3].energy);
    const double dd = (e[0].depth - 8.0 * e[1].depth + 8.0 * e[2].depth - e[3].depth);
    const double ratio = de / dd / f;
    std::cout << fmt::format("f {:.4f}: (dU/ddelta) / F - 1 = {:.3e}\n", f, ratio - 1.0);
    EXPECT_NEAR(ratio, 1.0, 1e-6) << f;
  }
}

// The traction demand against the vertical balance: the cap's vertical resultant inside R is
// V(R) = R s1 sin(theta) (the edge's V is the force), and dV/dR = (p cos(theta) + tau
// sin(theta)) r lambda1.  The history's p (normal balance) and tau (tangential balance, with
// lambda1' by central differences) integrated by Simpson's rule over the grid give the force at
// each grid point (O(h^4): 1e-8 relative here; 1e-6 allows for the ends' second-order
// differences); pointwise, tau from dV/dR by central differences of V agrees to 1e-4.
TEST(SphereStick, TractionDemandMatchesTheVerticalBalance) {
  const Problem p = held_sphere_problem();  // the shooting holds its law
  const auto shooting = make_held_sphere_shooting(p, test::tight_options());
  const auto& history = shooting.contact().held_profile_history();
  const auto& pts = history.points();
  const double a = shooting.contact().settings().a, h = history.step();
  ASSERT_GT(pts.size(), 100u);
  auto dv = [&](std::size_t k) {
    const auto t = history.traction(k);
    const double theta = pts[k].theta;
    return (t.pressure * std::cos(theta) + t.tangential * std::sin(theta)) * a * std::sin(theta) *
           pts[k].l1;
  };
  double worst = 0.0;
  // Up to theta = 1.2 (lambda1 ~ 2.6): further on lambda1 steepens towards locking and the grid's
  // differences lose their order.
  for (std::size_t k = 20; k + 1 < pts.size() && pts[k].theta < 1.2; k += 20) {
    double simpson = dv(0) + dv(k);
    for (std::size_t j = 1; j < k; ++j) simpson += (j % 2 ? 4.0 : 2.0) * dv(j);
    simpson *= h / 3.0;
    worst = std::max(worst, std::abs(simpson / pts[k].f - 1.0));
    EXPECT_NEAR(simpson / pts[k].f, 1.0, 1e-6) << k;
  }
  std::cout << fmt::format("int (p cos + tau sin) r lambda1 dR / f - 1: at most {:.2e}\n", worst);
  const auto& law = shooting.contact().law();
  auto vertical = [&](std::size_t k) {
    const double l2 = a * std::sin(pts[k].theta) / pts[k].r;
    return pts[k].r * membrane_stress(law, pts[k].l1, l2).s1 * std::sin(pts[k].theta);
  };
  for (std::size_t k = 40; k + 2 < pts.size() && pts[k].theta < 1.2; k += 40) {
    const double slope =
        (vertical(k - 2) - 8.0 * vertical(k - 1) + 8.0 * vertical(k + 1) - vertical(k + 2)) /
        (12.0 * h);
    const double theta = pts[k].theta;
    const auto t = history.traction(k);
    const double tau = (slope / (a * std::sin(theta) * pts[k].l1) - t.pressure * std::cos(theta)) /
                       std::sin(theta);
    EXPECT_NEAR(tau, t.tangential, 1e-4 * std::abs(t.tangential)) << k;
    EXPECT_NEAR(vertical(k), pts[k].f, 1e-12 * pts[k].f);
  }
}

// The history converges at the fourth order of its Runge-Kutta march: the force and depth with
// the edge at a fixed material radius (a quarter of the grid's span, a grid point for every
// step count used), and the switch depth of a force rule (depth at F = threshold, cubic
// interpolation of the grid's (f, depth), also O(h^4)).  Errors against the finest grid
// (1600 steps) fall by about 16 per halving (measured 3.7, 3.8 for f and depth; 5.0, 3.3 for the
// switch depth, whose interpolation error is of the same order); asserted: order > 3.5 (> 3 for
// the switch depth).  (Below 100 steps the march's
// sub-steps near the first touch do not keep it stable.)
TEST(SphereStick, HistoryConvergesAtFourthOrder) {
  const Problem p = held_sphere_problem();
  SolverOptions o = test::tight_options();
  const FreePart<Gent> part_one(std::get<Gent>(p.material.law), shooting_settings(o));
  const double a = contact_settings(p, std::get<SphereTipped>(p.indenter)).a;
  struct Measured {
    double f, depth, theta, switch_depth;
  };
  const double f_switch = 0.01;
  auto measure = [&](int steps) {
    const ProfileStickHistory<Gent> history(part_one, HeldProfile{.arc = a}, steps);
    const auto& pts = history.points();
    const auto& q = pts[static_cast<std::size_t>(steps / 4)];
    std::size_t k = 1;
    while (pts[k + 2].f < f_switch) ++k;
    double d = 0.0;  // Lagrange through the grid points k - 1 .. k + 2, in f
    for (std::size_t i = k - 1; i <= k + 2; ++i) {
      double w = 1.0;
      for (std::size_t j = k - 1; j <= k + 2; ++j)
        if (j != i) w *= (f_switch - pts[j].f) / (pts[i].f - pts[j].f);
      d += w * pts[i].depth;
    }
    return Measured{q.f, q.depth, q.theta, d};
  };
  const Measured exact = measure(1600);
  std::vector<Measured> m;
  for (const int n : {100, 200, 400}) m.push_back(measure(n));
  for (std::size_t i = 0; i + 1 < m.size(); ++i) {
    auto order = [&](double Measured::*x) {
      return std::log2(std::abs(m[i].*x - exact.*x) / std::abs(m[i + 1].*x - exact.*x));
    };
    std::cout << fmt::format(
        "steps {} -> {}: order f {:.2f}, depth {:.2f}, theta {:.2f}, switch depth {:.2f} "
        "(error {:.2e} A)\n",
        100 << i,
        200 << i,
        order(&Measured::f),
        order(&Measured::depth),
        order(&Measured::theta),
        order(&Measured::switch_depth),
        std::abs(m[i + 1].switch_depth - exact.switch_depth));
    EXPECT_GT(order(&Measured::f), 3.5);
    EXPECT_GT(order(&Measured::depth), 3.5);
    EXPECT_GT(order(&Measured::switch_depth), 3.0);  // with the interpolation's own O(h^4)
  }
}

// The history's end: the edge marches to the sphere's equator (psi within 1e-6 of pi/2), the
// grid closed by a last, shorter interval (from 6.2 to 22.0 N: near the equator the force grows
// steeply with the edge).  States in that interval solve, at a force and at a depth (130 mm, past
// the last full grid point's 127 mm), with their edge inside it; past its end the held membrane
// would wrap the cylinder side (StickWrapsSide), a physical status, not a solver failure.
TEST(SphereStick, HistoryReachesTheEquatorAndItsLastIntervalSolves) {
  const Problem p = held_sphere_problem();
  const auto shooting = make_held_sphere_shooting(p, test::tight_options());
  const auto& history = shooting.contact().held_profile_history();
  const auto& pts = history.points();
  const std::size_t n = pts.size();
  ASSERT_GT(n, 100u);
  EXPECT_EQ(history.end(), ProfileHistoryEnd::ProfileEnd);
  EXPECT_LT(0.5 * test::kPi - pts.back().theta, 1e-6);
  EXPECT_LT(pts[n - 1].r - pts[n - 2].r, history.step());
  for (const double share : {0.01, 0.5, 0.99}) {
    const double f = pts[n - 2].f + share * (pts[n - 1].f - pts[n - 2].f);
    const auto sol = shooting.solve(Stage::Stick, f);
    ASSERT_TRUE(sol.ok()) << share << ": " << sol.message;
    EXPECT_EQ(sol.configuration, Configuration::Stick);
    EXPECT_NEAR(sol.f, f, 1e-12 * f);
    EXPECT_GT(1.0 / sol.parameter, pts[n - 2].r);
    EXPECT_LT(1.0 / sol.parameter, pts[n - 1].r);
    EXPECT_GT(sol.depth, pts[n - 2].depth);
    EXPECT_LT(sol.depth, pts[n - 1].depth);
  }
  const auto beyond = shooting.solve(Stage::Stick, 1.001 * pts.back().f);
  EXPECT_EQ(beyond.status, Status::StickWrapsSide) << beyond.message;
  const auto deep = solve_at_depth(p, 130.0, Stage::Stick);
  ASSERT_TRUE(deep.ok()) << deep.message;
  EXPECT_EQ(deep.configuration, Configuration::Stick);
  EXPECT_NEAR(deep.depth_mm, 130.0, 1e-9);
  std::cout << fmt::format(
      "held on the sphere: history to psi = pi/2 - {:.2e}, its last interval f {:.4f} .. {:.4f} "
      "(scaled); at 130 mm {:.6f} N\n",
      0.5 * test::kPi - pts.back().theta,
      pts[n - 2].f,
      pts[n - 1].f,
      deep.force_n);
}

// The admissibility of a held state (10 mm deep, paper's membrane): contact pressure >= 0 and
// hoop tension > 0 on the held cap (off the pole, where the stress-free pole's stresses are
// 0), Part I outside the probe (its distance from the sphere's centre >= a below the equator,
// its radius >= a above it; the fields' deflection is measured down from the clamp plane), and
// the cap lying on the sphere.
TEST(SphereStick, HeldStateIsAdmissible) {
  const Problem p = held_sphere_problem();
  const auto eq = solve_at_depth(p, 10.0, Stage::Stick);
  ASSERT_TRUE(eq.ok()) << eq.message;
  EXPECT_EQ(eq.configuration, Configuration::Stick);
  const auto& m = eq.fields;
  const double a = 2.0, centre = eq.depth_mm - a;  // the sphere's centre's deflection
  const auto cap = test::part_indices(m, 3), free = test::part_indices(m, 1);
  ASSERT_GT(cap.size(), 50u);
  ASSERT_GT(free.size(), 50u);
  for (const auto i : cap) {
    EXPECT_GE(m.contact_pressure_mpa[i], 0.0) << i;
    if (m.reference_radius_mm[i] > 0.0) EXPECT_GT(m.hoop_stress_mpa[i], 0.0) << i;
    const double dz = m.deflection_mm[i] - centre;
    EXPECT_NEAR(std::hypot(m.radius_mm[i], dz), a, 1e-9) << i;
  }
  double closest = 1e300;
  for (const auto i : free) {
    const double dz = m.deflection_mm[i] - centre;  // > 0: below the centre, on the tip's side
    const double gap = dz > 0.0 ? std::hypot(m.radius_mm[i], dz) - a : m.radius_mm[i] - a;
    closest = std::min(closest, gap);
  }
  EXPECT_GE(closest, -1e-9);
  std::cout << fmt::format(
      "depth 10 mm held: force {:.6f} N, Part I's closest approach {:.2e} mm\n",
      eq.force_n,
      closest);
}

// The stick -> slip switch through the unchanged curve driver (force rule, 0.1 N): the held state
// at the switch carries the threshold, the force drops to the sliding branch there, and past the
// switch the curve is the sliding one ('none') at the same depths.  The held branch is the
// stiffer one (material pinned where it touched cannot spread over the sphere).
TEST(SphereStick, ForceRuleSwitchesToTheSlidingCurve) {
  const Problem held = held_sphere_problem({StickRule::Force, 0.1});
  Problem sliding = held;
  sliding.stick = {};
  CurveOptions c;
  c.depths_mm = {2.0, 5.0, 8.0, 12.0, 16.0, 20.0};
  const auto lc = loading_curve(held, c);
  ASSERT_TRUE(lc.ok()) << lc.message;
  ASSERT_TRUE(lc.stick_slip.occurs);
  EXPECT_NEAR(lc.stick_slip.force_stuck_n, 0.1, 1e-9);
  EXPECT_LT(lc.stick_slip.force_sliding_n, lc.stick_slip.force_stuck_n);
  const auto ref = loading_curve(sliding, c);
  ASSERT_TRUE(ref.ok()) << ref.message;
  std::cout << fmt::format("force:0.1 on the sphere: switch at {:.4f} mm, {:.4f} -> {:.4f} N\n",
                           lc.stick_slip.depth_mm,
                           lc.stick_slip.force_stuck_n,
                           lc.stick_slip.force_sliding_n);
  std::size_t compared = 0;
  for (const auto& pt : lc.points) {
    for (const auto& q : ref.points)
      if (pt.stage == Stage::Slip && q.depth_mm == pt.depth_mm) {
        EXPECT_NEAR(pt.force_n, q.force_n, 1e-9 * q.force_n) << pt.depth_mm;
        ++compared;
      }
    if (pt.stage == Stage::Stick && pt.depth_mm < lc.stick_slip.depth_mm) {
      const auto* q = &ref.points.front();
      for (const auto& r : ref.points)
        if (r.depth_mm == pt.depth_mm) q = &r;
      EXPECT_GT(pt.force_n, q->force_n) << pt.depth_mm;
    }
  }
  EXPECT_GE(compared, 2u);
}

// The Coulomb stick rule on a pre-stretched membrane (L0 = 1.2, where the ratio |tau| / p starts
// at 0 at the pole, docs/model.md §15.4): a larger mu holds longer, mu -> 0 releases at once
// (the switch depth falls towards 0, about as mu^2: the ratio grows linearly with the edge, the
// depth as its square), mu = 0 slides from the first touch and gives the frictionless sliding
// curve; on a stress-free membrane no mu holds the first material touched.
TEST(SphereStick, CoulombHoldsLongerWithMoreFriction) {
  auto problem = [](double mu, double l0) {
    Problem p = held_sphere_problem({StickRule::Coulomb, 0.0});
    p.friction = mu;
    p.preload.prestretch = l0;
    return p;
  };
  double last = 0.0;
  std::vector<double> depths;
  for (const double mu : {0.02, 0.04, 0.3, 0.6, 1.0}) {
    const auto b = stick_slip_boundary(problem(mu, 1.2));
    ASSERT_TRUE(b.ok()) << mu << ": " << b.message;
    ASSERT_TRUE(b.switches) << mu;
    EXPECT_GT(b.depth_mm, last) << mu;
    last = b.depth_mm;
    depths.push_back(b.depth_mm);
    std::cout << fmt::format("coulomb, L0 1.2, mu {:.2f}: held to {:.5f} mm, {:.6f} N\n",
                             mu,
                             b.depth_mm,
                             b.force_stuck_n);
  }
  EXPECT_GT(depths[1] / depths[0], 3.0);  // ~ mu^2 as mu -> 0 (3.6 here: Part I adds to
  EXPECT_LT(depths[1] / depths[0], 4.5);  // the depth, ~ R^2 log R)
  const auto at_once = stick_slip_boundary(problem(0.0, 1.2));
  ASSERT_TRUE(at_once.ok());
  EXPECT_EQ(at_once.first_stage, Stage::Slip);
  EXPECT_FALSE(at_once.switches);
  const auto stress_free = stick_slip_boundary(problem(2.0, 1.0));
  ASSERT_TRUE(stress_free.ok());
  EXPECT_EQ(stress_free.first_stage, Stage::Slip);
  CurveOptions c;
  c.depths_mm = {1.0, 4.0, 9.0};
  Problem none = problem(0.0, 1.2);
  none.stick = {};
  const auto held = loading_curve(problem(0.0, 1.2), c), sliding = loading_curve(none, c);
  ASSERT_TRUE(held.ok() && sliding.ok());
  ASSERT_EQ(held.points.size(), sliding.points.size());
  for (std::size_t i = 0; i < held.points.size(); ++i)
    EXPECT_EQ(held.points[i].force_n, sliding.points[i].force_n);
}

}  // namespace
}  // namespace puncture::detail
