// The sphere-tipped probe with Coulomb slip on the cylinder side past the hemisphere's equator
// (docs/model.md §15, "Friction on the side"): the fillet's side friction (§19) with a face of
// zero radius.  Checks: continuity with the filleted punch as rho -> a at the same friction;
// mu -> 0 gives the frictionless side (with the measured order); the energy balance, the
// indenter's work = the change of stored energy + the friction's dissipation computed from the
// slip of each material point between neighbouring states; the contact tractions carry the force,
// with the contact pressure >= 0 on the cap and the side and no line force at the equator; the
// puncture and where it starts as the friction grows (the paper's membrane, a = 2 mm, and the ASTM
// F1306 probe); the ball and the cone keep their statuses past their equator and kink.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "indentation/dispatch.hpp"
#include "indentation/shooting.hpp"
#include "mechanics/inverse_stretch.hpp"
#include "numerics/trapezoid.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "solver_test_support.hpp"
#include "sphere_model_energy.hpp"

namespace puncture::detail {
namespace {

using test::record;

Problem rough_sphere_problem(double friction, double radius_mm = 2.0) {
  Problem p = test::paper_problem(Gent{125.0}, friction);
  p.indenter = SphereTipped{radius_mm};
  return p;
}

using RoughSphereShooting = IndentationShooting<SphereTippedContact<Gent>>;

RoughSphereShooting make_rough_sphere_shooting(const Problem& p, const SolverOptions& o) {
  return RoughSphereShooting(std::get<Gent>(p.material.law),
                             shooting_settings(o),
                             contact_settings(p, std::get<SphereTipped>(p.indenter)),
                             false);
}

// One sliding state with the contact on the side, re-marched from its pole stretch: the profile
// coordinate psi (polar angle on the hemisphere, pi/2 + height / a on the side) of the material
// point R, and the contact traction's magnitude per radian and unit R there, p r lambda1
// (sin(theta) (s1 lambda1 / lambda2 + s2) on the cap, s2 on the side; / (G H)).
struct SideStateProfile {
  const SphereTippedContact<Gent>* contact;
  double l = 0.0;      // pole stretch
  double depth = 0.0;  // / A
  double r_equator = 0.0, l1_equator = 0.0, r_top = 0.0;

  struct Point {
    double psi;
    double traction;
  };
  std::optional<Point> at(double r) const {
    const auto& law = contact->law();
    const auto& s = contact->settings();
    const IntegrationSettings integration{1e-13, 1e-15, 1000000};
    if (r <= r_equator) {
      const SphereCapSystem<Gent> cap{law, s.a, law.locking_i1(), s.mu};
      const double r0 = 1e-5 * s.a / l;
      SphereCapState y = sphere_cap_pole_state(law, s.a, l, std::min(r, r0), s.mu);
      if (r > r0) {
        const auto x = advance(cap, y, r0, r, integration);
        if (!x) return std::nullopt;
        y = *x;
      }
      const double l2 = s.a * std::sin(y[0]) / r;
      const auto st = membrane_stress(law, y[1], l2);
      return Point{y[0], std::sin(y[0]) * (st.s1 * y[1] / l2 + st.s2)};
    }
    const PartTwoSystem<Gent> side{law, s.a, s.mu, PartTwoEquation::RingBalance, law.locking_i1()};
    const auto x = advance(side, PartTwoState{l1_equator, 0.0}, r_equator, r, integration);
    if (!x) return std::nullopt;
    return Point{test::kHalfPi - (*x)[1] / s.a, membrane_stress(law, (*x)[0], s.a / r).s2};
  }
};

std::optional<SideStateProfile> side_state_profile(const RoughSphereShooting& shooting, double f) {
  const auto sol = shooting.solve(Stage::Slip, f, false);
  if (!sol.ok() || sol.configuration != Configuration::SlipWithPartTwo) return std::nullopt;
  const auto& contact = shooting.contact();
  const auto cap = contact.march(sol.parameter, std::numeric_limits<double>::infinity());
  const auto start = contact.free_start(Configuration::SlipWithPartTwo, f, sol.parameter);
  if (!cap || !cap->at_equator || !start) return std::nullopt;
  return SideStateProfile{&contact, sol.parameter, sol.depth, cap->r, cap->state[1], start->r0};
}

// The friction's dissipation per unit depth at force f, D = mu int p r lambda1 a (dpsi/ddelta)_R
// dR over the contact (/ (2 pi G H A)): each material point's slip along the probe between the
// states at f (1 -+ 1e-4), by the central difference (truncation ~1e-8; the few points that touch
// only in the deeper state, within ~1e-4 of the top, are left out).  `min_slip` gets the least
// dpsi/ddelta met (>= 0: every point slides away from the pole, as the friction's sign assumes).
std::optional<double> side_dissipation(const RoughSphereShooting& shooting, double f,
                                       double* min_slip) {
  const double h = 1e-4 * f;
  const auto lo = side_state_profile(shooting, f - h), mid = side_state_profile(shooting, f),
             hi = side_state_profile(shooting, f + h);
  if (!lo || !mid || !hi) return std::nullopt;
  const double a = shooting.contact().settings().a, mu = shooting.contact().settings().mu;
  const double d_depth = hi->depth - lo->depth;
  bool failed = false;
  *min_slip = std::numeric_limits<double>::infinity();
  auto integrand = [&](double r) {
    const auto m = mid->at(r), p = lo->at(r), q = hi->at(r);
    if (!m || !p || !q) {
      failed = true;
      return 0.0;
    }
    const double slip = (q->psi - p->psi) / d_depth;
    *min_slip = std::min(*min_slip, slip);
    return mu * m->traction * a * slip;
  };
  const double r_end = std::min({lo->r_top, mid->r_top, hi->r_top});
  using Quadrature = boost::math::quadrature::gauss_kronrod<double, 31>;
  const double cap = Quadrature::integrate(integrand, 0.0, mid->r_equator, 8, 1e-11);
  const double side = Quadrature::integrate(integrand, mid->r_equator, r_end, 8, 1e-11);
  if (failed) return std::nullopt;
  return cap + side;
}

// The energy balance with friction on the side: F = dU/ddelta + D.  dU/ddelta by the four-point
// difference of energy_at (step 1e-3 f: truncation ~1e-12, noise ~1e-10), D from the slips
// (above); their sum meets F to 1e-6 (measured 6e-9 to 1.8e-7), while D itself is 0.9-11 % of F: a
// dissipation missing, or counted on the cap only, would miss by far more.
TEST(SphereSideFriction, WorkIsStoredEnergyPlusDissipation) {
  for (const double mu : {0.18, 0.5}) {
    const auto shooting =
        make_rough_sphere_shooting(rough_sphere_problem(mu), test::tight_options());
    for (const double f : {0.2, 0.35}) {
      const double h = 1e-3 * f;
      std::vector<test::EnergyAndDepth> s;
      for (const double k : {-2.0, -1.0, 1.0, 2.0}) {
        const auto e = test::energy_at(shooting, f + k * h);
        ASSERT_TRUE(e.has_value()) << mu << " " << f + k * h;
        ASSERT_EQ(e->configuration, Configuration::SlipWithPartTwo) << mu << " " << f;
        s.push_back(*e);
      }
      auto derivative = [&](auto value) {
        return (value(s[0]) - 8.0 * value(s[1]) + 8.0 * value(s[2]) - value(s[3])) / (12.0 * h);
      };
      const double du = derivative([](const test::EnergyAndDepth& e) { return e.energy; });
      const double dd = derivative([](const test::EnergyAndDepth& e) { return e.depth; });
      double min_slip = 0.0;
      const auto dissipation = side_dissipation(shooting, f, &min_slip);
      ASSERT_TRUE(dissipation.has_value()) << mu << " " << f;
      const double stored = du / dd;
      const double balance = (stored + *dissipation) / f - 1.0;
      std::cout << fmt::format(
          "mu {:g}, f {:g} (depth {:.3f} mm): dU/ddelta / F = {:.8f}, D / F = {:.8f}, "
          "(dU/ddelta + D) / F - 1 = {:.2e}, least slip dpsi/ddelta {:.3e}\n",
          mu,
          f,
          0.5 * (s[1].depth + s[2].depth) * 25.0,
          stored / f,
          *dissipation / f,
          balance,
          min_slip);
      EXPECT_GT(*dissipation, 5e-3 * f);
      EXPECT_LT(std::abs(balance), 1e-6) << mu << " " << f;
      EXPECT_GE(min_slip, 0.0);
      record(fmt::format("energy_balance_mu{:g}_f{:g}", mu, f), std::abs(balance));
    }
  }
}

// Continuity: the filleted flat punch with rho = a - b is the sphere-tipped probe with a flat face
// of radius b; at the same friction (0.18) and a depth past the equator (25 mm, on the side) its
// force tends to the sphere's at first order in b (measured 7.0e-6, 7.0e-7, 7.0e-8 at b = 2e-4,
// 2e-5, 2e-6 mm; frictionless the same limit gave 2.7e-7 at b = 2e-6 mm,
// filleted_flat_punch_test.cpp).
TEST(SphereSideFriction, FilletToTheRadiusIsTheSphereWithFriction) {
  const double depth = 25.0;
  const auto sphere = solve_at_depth(rough_sphere_problem(0.18), depth, Stage::Slip);
  ASSERT_TRUE(sphere.ok()) << sphere.message;
  ASSERT_EQ(sphere.configuration, Configuration::SlipWithPartTwo);
  std::vector<double> differences;
  for (const double b : {2e-4, 2e-5, 2e-6}) {
    Problem fillet = rough_sphere_problem(0.18);
    fillet.indenter = FlatPunch{2.0, 2.0 - b};
    const auto e = solve_at_depth(fillet, depth, Stage::Slip);
    ASSERT_TRUE(e.ok()) << b << ": " << e.message;
    EXPECT_EQ(e.configuration, Configuration::SlipWithPartTwo);
    const double difference = std::abs(e.force_n / sphere.force_n - 1.0);
    differences.push_back(difference);
    std::cout << fmt::format(
        "mu 0.18, {} mm: face b = {:g} mm: F {:.12g} N, sphere {:.12g} N, "
        "relative difference {:.3e}\n",
        depth,
        b,
        e.force_n,
        sphere.force_n,
        difference);
    record(fmt::format("fillet_sphere_difference_b{:g}", b), difference);
  }
  EXPECT_LT(differences.back(), 1e-6);
  for (std::size_t k = 1; k < differences.size(); ++k)
    EXPECT_LT(differences[k], 0.2 * differences[k - 1]);  // first order: 0.1 per decade
}

// mu -> 0: the rough side's pole-stretch shooting tends to the frictionless model's top-stretch
// shooting (other code) at first order in mu, at 25 mm (on the side): measured 1.48e-3, 1.47e-4,
// 1.50e-5 relative at mu = 1e-2, 1e-3, 1e-4 (order 1.00, 0.99).
TEST(SphereSideFriction, FrictionToZeroIsTheFrictionlessSide) {
  const double depth = 25.0;
  const auto smooth = solve_at_depth(rough_sphere_problem(0.0), depth, Stage::Slip);
  ASSERT_TRUE(smooth.ok()) << smooth.message;
  ASSERT_EQ(smooth.configuration, Configuration::SlipWithPartTwo);
  std::vector<double> differences;
  for (const double mu : {1e-2, 1e-3, 1e-4}) {
    const auto e = solve_at_depth(rough_sphere_problem(mu), depth, Stage::Slip);
    ASSERT_TRUE(e.ok()) << mu << ": " << e.message;
    ASSERT_EQ(e.configuration, Configuration::SlipWithPartTwo);
    const double difference = e.force_n / smooth.force_n - 1.0;
    differences.push_back(difference);
    std::cout << fmt::format(
        "mu {:g}: F {:.12g} N at {} mm (frictionless {:.12g} N), relative difference {:.4e}\n",
        mu,
        e.force_n,
        depth,
        smooth.force_n,
        difference);
    EXPECT_GT(difference, 0.0);  // friction raises the force
  }
  for (std::size_t k = 1; k < differences.size(); ++k) {
    const double order = std::log10(differences[k - 1] / differences[k]);
    std::cout << fmt::format("order between mu = {:g} and {:g}: {:.4f}\n",
                             std::pow(10.0, -static_cast<double>(k) - 1.0),
                             std::pow(10.0, -static_cast<double>(k) - 2.0),
                             order);
    EXPECT_GT(order, 0.95);
    EXPECT_LT(order, 1.05);
  }
}

// The axial resultant [N] of the contact tractions of a state with its contact on the side, from
// its fields: int (p cos(theta) + mu p sin(theta)) r lambda1 dR over the cap plus int mu p r
// lambda1 dR over the side (theta = pi/2), by the trapezoid with Richardson's step on each part
// apart (p jumps at the equator, where the meridian's curvature does); the side from the equator,
// where its traction is mu (s2 H + P a lambda1) (the cap's last sample).  Checks on the way: p > 0
// on the cap and the side, the friction traction mu p, and no line force at the equator: R s1 grows
// from the cap's last sample (the equator) to the side's first as the side's ring balance says, by
// mu int (s2 + P a lambda1 / H) dR, to 1e-3 of that growth (a line force, a jump of R s1, would
// miss by its whole size).
double side_state_axial_resultant_n(const Equilibrium& e, const Problem& p) {
  const double mu = p.friction, h = p.geometry.thickness_mm, gas = p.preload.pressure_mpa;
  const double a = radius_mm(p.indenter);
  const auto& m = e.fields;
  // The equator's state is sampled twice (the cap's end and the side's start, labelled either
  // way): the cap is the Tip samples, ending there, the side the Side samples above it.
  const double r_equator = e.corner_reference_radius_mm;
  std::vector<std::size_t> cap, side;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m.part[i] == MembranePart::Tip) cap.push_back(i);
    if (m.part[i] == MembranePart::Side && m.reference_radius_mm[i] > r_equator * (1.0 + 1e-12))
      side.push_back(i);
  }
  EXPECT_GT(cap.size(), 10u);
  EXPECT_GT(side.size(), 10u);
  if (cap.empty() || side.empty()) return 0.0;
  const std::size_t last_cap = cap.back(), first_side = side.front();
  EXPECT_NEAR(m.reference_radius_mm[last_cap], r_equator, 1e-12 * r_equator);
  // The side's traction per unit R, mu p r lambda1 with p = s2 H / (lambda1 a) + P, at sample i.
  auto side_traction = [&](std::size_t i) {
    return mu * (m.hoop_stress_mpa[i] * h + gas * a * m.radial_stretch[i]);
  };
  double axial_n = 0.0;
  for (const auto* indices : {&cap, &side}) {
    std::vector<double> r, y;
    if (indices == &side) {  // from the equator
      r.push_back(m.reference_radius_mm[last_cap]);
      y.push_back(side_traction(last_cap));
    }
    for (const std::size_t i : *indices) {
      EXPECT_GT(m.contact_pressure_mpa[i], 0.0) << mu << " R " << m.reference_radius_mm[i];
      EXPECT_NEAR(m.friction_traction_mpa[i], mu * m.contact_pressure_mpa[i], 1e-15);
      const double theta = m.slope_rad[i];
      r.push_back(m.reference_radius_mm[i]);
      y.push_back((m.contact_pressure_mpa[i] * std::cos(theta) +
                   m.friction_traction_mpa[i] * std::sin(theta)) *
                  m.radius_mm[i] * m.radial_stretch[i]);
    }
    const double fine = detail::trapezoid(r, y, 1), coarse = detail::trapezoid(r, y, 2);
    axial_n += 2.0 * test::kPi * (fine + (fine - coarse) / 3.0);
  }
  // R s1 [MPa mm] across the equator and the first step up the side.
  const double r0 = m.reference_radius_mm[last_cap], r1 = m.reference_radius_mm[first_side];
  const double jump = r1 * m.radial_stress_mpa[first_side] - r0 * m.radial_stress_mpa[last_cap];
  const double growth = 0.5 * (side_traction(last_cap) + side_traction(first_side)) / h * (r1 - r0);
  EXPECT_GT(growth, 0.0);
  EXPECT_NEAR(jump, growth, 1e-3 * growth) << mu;
  std::cout << fmt::format(
      "mu {:g}, gas {:g} MPa: F {:.8g} N at {:.4g} mm, contact traction resultant / F - 1 = "
      "{:.2e}; R s1 from the equator to the side's first sample / the ring balance's growth - 1 "
      "= {:.1e}; side length {:.4f} mm\n",
      mu,
      gas,
      e.force_n,
      e.depth_mm,
      axial_n / e.force_n - 1.0,
      jump / growth - 1.0,
      e.part_two_length_mm);
  return axial_n;
}

// From the fields at 35 mm (on the side for each mu): the contact tractions carry the force (1e-6),
// with p > 0 and no line force at the equator (side_state_axial_resultant_n).
TEST(SphereSideFriction, ContactTractionsCarryTheForce) {
  for (const double mu : {0.18, 0.5, 1.0}) {
    SolverOptions o;
    o.field_points = 400;
    const Problem p = rough_sphere_problem(mu);
    const auto e = solve_at_depth(p, 35.0, Stage::Slip, o);
    ASSERT_TRUE(e.ok()) << mu << ": " << e.message;
    ASSERT_EQ(e.configuration, Configuration::SlipWithPartTwo);
    EXPECT_NEAR(side_state_axial_resultant_n(e, p), e.force_n, 1e-6 * e.force_n) << mu;
  }
}

// Under a constant gas pressure (docs/model.md §17; the paper's inflated membrane, P = 3e-4 MPa,
// 30 mm, on the side): the gas adds P to the contact pressure, hence mu P a lambda1 to the side's
// ring balance, and takes P a^2 / 2 of the force at the top.  The contact tractions carry the force
// (1e-6), and mu -> 0 tends to the frictionless pressurised side (other code) at first order.
TEST(SphereSideFriction, UnderGasPressure) {
  const double gas = 3e-4, depth = 30.0;
  auto inflated = [&](double mu) {
    Problem p = rough_sphere_problem(mu);
    p.preload.pressure_mpa = gas;
    return p;
  };
  SolverOptions o;
  o.field_points = 400;
  const Problem rough = inflated(0.18);
  const auto e = solve_at_depth(rough, depth, Stage::Slip, o);
  ASSERT_TRUE(e.ok()) << e.message;
  ASSERT_EQ(e.configuration, Configuration::SlipWithPartTwo);
  EXPECT_NEAR(side_state_axial_resultant_n(e, rough), e.force_n, 1e-6 * e.force_n);
  const auto smooth = solve_at_depth(inflated(0.0), depth, Stage::Slip);
  ASSERT_TRUE(smooth.ok()) << smooth.message;
  ASSERT_EQ(smooth.configuration, Configuration::SlipWithPartTwo);
  EXPECT_GT(e.force_n, smooth.force_n);
  std::vector<double> differences;
  for (const double mu : {1e-2, 1e-3, 1e-4}) {
    const auto r = solve_at_depth(inflated(mu), depth, Stage::Slip);
    ASSERT_TRUE(r.ok()) << mu << ": " << r.message;
    ASSERT_EQ(r.configuration, Configuration::SlipWithPartTwo);
    differences.push_back(r.force_n / smooth.force_n - 1.0);
    std::cout << fmt::format(
        "gas {:g} MPa, mu {:g}: F / frictionless F - 1 = {:.4e}\n", gas, mu, differences.back());
  }
  for (std::size_t k = 1; k < differences.size(); ++k) {
    const double order = std::log10(differences[k - 1] / differences[k]);
    EXPECT_GT(order, 0.95);
    EXPECT_LT(order, 1.05);
  }
}

// Where the puncture starts as the friction grows (the issue: "with friction the site moves from
// the pole to the contact edge"): the paper's membrane with a = 2 mm (A = 25 mm) and the ASTM F1306
// probe and opening (a = 1.6 mm, A = 17.45 mm), mu = 0, 0.18, 0.5, 1.  Each punctures with the
// contact on the side, the largest I1 the critical one: frictionless at the pole; with friction on
// the sphere, further from the pole as mu grows (0.18, 0.5), then on the cylinder side just above
// the equator (1), where the side's capstan-like growth of R s1 meets the hoop stretch a / R.
TEST(SphereSideFriction, PunctureSiteMovesWithFriction) {
  const std::vector<std::pair<double, double>> probes{{2.0, 25.0}, {1.6, 17.45}};
  const std::vector<std::string> sites{"the pole, under the tip of the sphere",
                                       "on the sphere, between the pole and the contact edge",
                                       "on the sphere, between the pole and the contact edge",
                                       "on the cylinder side of the probe"};
  const std::vector<double> frictions{0.0, 0.18, 0.5, 1.0};
  for (const auto& [radius, clamp] : probes) {
    double last_force = 0.0, last_crack_radius = -1.0;
    for (std::size_t k = 0; k < frictions.size(); ++k) {
      Problem p = rough_sphere_problem(frictions[k], radius);
      p.geometry.clamp_radius_mm = clamp;
      const auto pp = predict_puncture(p);
      ASSERT_TRUE(pp.ok()) << radius << " mu " << frictions[k] << ": " << pp.message;
      std::cout << fmt::format(
          "a {} mm, A {} mm, mu {:g}: puncture {:.6f} N at {:.4f} mm, {} (R = {:.4f} mm, r = "
          "{:.4f} mm)\n",
          radius,
          clamp,
          frictions[k],
          pp.force_n,
          pp.depth_mm,
          pp.crack_location,
          pp.crack_reference_radius_mm,
          pp.crack_radius_mm);
      EXPECT_EQ(pp.state.configuration, Configuration::SlipWithPartTwo);
      EXPECT_NEAR(pp.state.max_first_invariant, p.critical_i1, 1e-6 * p.critical_i1);
      EXPECT_EQ(pp.crack_location, sites[k]) << frictions[k];
      EXPECT_GT(pp.force_n, last_force) << frictions[k];
      EXPECT_GT(pp.crack_radius_mm, last_crack_radius) << frictions[k];
      last_force = pp.force_n;
      last_crack_radius = pp.crack_radius_mm;
      record(fmt::format("puncture_force_n_a{:g}_mu{:g}", radius, frictions[k]), pp.force_n);
    }
  }
}

// The ball and the cone are not the cylinder side's: with friction their contact past the ball's
// equator or onto the shank stays a status (docs/model.md §15.1, §15.2), never a number.
TEST(SphereSideFriction, BallAndConeKeepTheirStatuses) {
  Problem ball = rough_sphere_problem(0.18);
  ball.indenter = Ball{1.0, 2.0};
  const auto past_equator = solve_at_depth(ball, 25.0, Stage::Slip);
  EXPECT_EQ(past_equator.status, Status::OutsideModel);
  EXPECT_NE(past_equator.message.find("ball"), std::string::npos) << past_equator.message;
  Problem cone = rough_sphere_problem(0.18);
  cone.indenter = Cone{2.0, 30.0, 0.5};
  const auto on_shank = solve_at_depth(cone, 30.0, Stage::Slip);
  EXPECT_EQ(on_shank.status, Status::OutsideModel);
  EXPECT_NE(on_shank.message.find("shank"), std::string::npos) << on_shank.message;
}

}  // namespace
}  // namespace puncture::detail
