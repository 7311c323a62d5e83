// The ball on a rod and the cone with a spherical tip (docs/model.md, §15.1 and §15.2), both the
// sphere-tipped probe's contact model with another profile past the tip sphere: work conjugacy
// dU/ddelta = F, the reductions to the sphere-tipped probe, the small-deflection (Föppl) limit of
// the ball, the contact pressure and non-penetration along the cone, the statuses where the
// models end (the ball's equator, the cone's shank) and the refusal of bad dimensions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "foppl_sphere.hpp"
#include "indentation/dispatch.hpp"
#include "indentation/shooting.hpp"
#include "mechanics/free_membrane_ode.hpp"
#include "puncture/loading_curve.hpp"
#include "solver_test_support.hpp"
#include "sphere_model_energy.hpp"

namespace puncture::detail {
namespace cone_ball {

using test::record;

Problem with_probe(Indenter indenter) {
  Problem p = test::paper_problem(Gent{125.0}, 0.0);
  p.indenter = indenter;
  return p;
}

using Shooting = IndentationShooting<SphereTippedContact<Gent>>;

template <class Shape>
Shooting shooting_of(const Problem& p, const SolverOptions& o) {
  return Shooting(std::get<Gent>(p.material.law),
                  shooting_settings(o),
                  contact_settings(p, std::get<Shape>(p.indenter)),
                  false);
}

// The force (/ 2 pi G H A) at which the contact reaches the end of the probe's curved profile
// (the sphere-tipped probe's equator, the cone's kink onto the shank): Part I leaves there
// vertically with a clamp residual of 0 (the contact model's onset indicator).
double profile_end_force(const Shooting& shooting) {
  const auto& contact = shooting.contact();
  auto indicator = [&](double f) -> std::optional<double> {
    const auto onset = contact.equator_onset(f);
    if (!onset) return std::nullopt;
    return contact.side_indicator(f, *onset);
  };
  const auto f_on = onset_force(indicator, 200, 0.01);
  return f_on.value_or(std::nan(""));
}

// Stored energy (/ (2 pi G H A^2)) and depth (/ A) at force f on the cap (and the cone):
// the cap's int W R dR from its march, Part I's by the free-membrane system that carries it.
struct StoredEnergy {
  double energy;
  double depth;
  double slope;
  double on_cone;
};

std::optional<StoredEnergy> stored_energy_at(const Shooting& shooting, double f) {
  const auto sol = shooting.solve(Stage::Slip, f);
  if (!sol.ok() || sol.configuration != Configuration::SlipWithoutPartTwo) return std::nullopt;
  const auto& contact = shooting.contact();
  const Gent& law = contact.law();
  const auto st = contact.free_start(sol.configuration, f, sol.parameter);
  const auto cap = contact.march(sol.parameter, f);
  if (!st || !cap) return std::nullopt;
  const auto part_one = test::part_one_energy(law, f, *st);
  if (!part_one) return std::nullopt;
  return StoredEnergy{cap->state[2] + *part_one, sol.depth, sol.corner_slope, sol.part_two_length};
}

// Work conjugacy, frictionless: dU/ddelta = F (normalised de/dd = f), both differentiated in the
// force by the four-point central difference (step 1e-3 f: truncation ~1e-12, noise of the
// 1e-13 states ~1e-10).  The cone's forces put the contact edge on the tip sphere, on the cone
// and at the kink (Part I leaving over it with a line force); 1e-6 is the bound.
TEST(ConeProbe, WorkConjugacyOnTheTipTheConeAndTheKink) {
  const Problem p = with_probe(Cone{2.0, 30.0, 0.5});
  const auto shooting = shooting_of<Cone>(p, test::tight_options());
  const double tangency = std::numbers::pi / 2.0 - std::numbers::pi / 6.0;
  const double f_shank = profile_end_force(shooting);
  ASSERT_TRUE(std::isfinite(f_shank));
  bool on_tip = false, on_cone = false, at_kink = false;
  for (const double f : {1e-4, 3e-3, 3e-2, 0.97 * f_shank}) {
    const double h = 1e-3 * f;
    std::vector<StoredEnergy> s;
    for (const double k : {-2.0, -1.0, 1.0, 2.0}) {
      const auto e = stored_energy_at(shooting, f + k * h);
      ASSERT_TRUE(e.has_value()) << "f = " << f + k * h;
      s.push_back(*e);
    }
    auto derivative = [&](auto value) {
      return (value(s[0]) - 8.0 * value(s[1]) + 8.0 * value(s[2]) - value(s[3])) / (12.0 * h);
    };
    const double du = derivative([](const StoredEnergy& e) { return e.energy; });
    const double dd = derivative([](const StoredEnergy& e) { return e.depth; });
    const double relative = std::abs(du / dd - f) / f;
    const bool kink = s[1].slope > tangency + 1e-9;
    on_tip = on_tip || s[1].slope < tangency;
    on_cone = on_cone || (s[1].on_cone > 0.0 && !kink);
    at_kink = at_kink || kink;
    EXPECT_LT(relative, 1e-6) << "f = " << f;
    record(fmt::format("cone_dU_ddelta_relative_error_f{:g}", f), relative);
    std::cout << fmt::format(
        "cone f {:g}: depth {:.4f} mm, exit slope {:.4f} rad, on the cone {:.4f} mm: "
        "|dU/ddelta / F - 1| = {:.3e}\n",
        f,
        s[1].depth * p.geometry.clamp_radius_mm,
        s[1].slope,
        s[1].on_cone * p.geometry.clamp_radius_mm,
        relative);
  }
  EXPECT_TRUE(on_tip && on_cone && at_kink);
}

// While the contact stays on the tip sphere the cone probe is the sphere-tipped probe of the tip's
// radius: the same equations, marched the same way; only the shooting's bracket differs (its lower
// end is where the cone's contact would reach the shank), so the roots agree to the clamp
// tolerance's effect on the parameter, not to the bit: 1e-9 relative.
TEST(ConeProbe, OnTheTipSphereItIsTheSphereTippedProbe) {
  const Problem cone = with_probe(Cone{4.0, 30.0, 2.0});
  const Problem sphere = with_probe(SphereTipped{2.0});
  const auto cone_shooting = shooting_of<Cone>(cone, SolverOptions{});
  const auto sphere_shooting = shooting_of<SphereTipped>(sphere, SolverOptions{});
  for (const double f : {1e-4, 1e-3, 4e-3}) {
    const auto c = cone_shooting.solve(Stage::Slip, f);
    const auto s = sphere_shooting.solve(Stage::Slip, f);
    ASSERT_TRUE(c.ok() && s.ok()) << c.message << s.message;
    ASSERT_LT(c.corner_slope, std::numbers::pi / 3.0) << "the edge is past the tip sphere";
    EXPECT_NEAR(c.depth, s.depth, 1e-9 * s.depth) << f;
    EXPECT_NEAR(c.parameter, s.parameter, 1e-9 * s.parameter) << f;
    EXPECT_NEAR(c.max_i1, s.max_i1, 1e-9 * s.max_i1) << f;
    EXPECT_EQ(c.part_two_length, 0.0);
    record(fmt::format("depth_relative_difference_f{:g}", f), std::abs(c.depth / s.depth - 1.0));
  }
}

// A cone of half-angle alpha -> 0 whose tip sphere has the shank's radius tends to the
// sphere-tipped probe: the tip sphere ends at 90 deg - alpha, the cone is a ring of width
// ~ a alpha^2 / 2, and the force at which the contact reaches the shank tends to the force at
// which the sphere-tipped probe's reaches its equator, at the rate alpha (the kink's angle).
TEST(ConeProbe, ThinConeTendsToTheSphereTippedProbe) {
  const double f_equator =
      profile_end_force(shooting_of<SphereTipped>(with_probe(SphereTipped{2.0}), SolverOptions{}));
  ASSERT_TRUE(std::isfinite(f_equator));
  std::vector<double> gaps;
  for (const double alpha_deg : {4.0, 2.0, 1.0}) {
    const auto shooting = shooting_of<Cone>(with_probe(Cone{2.0, alpha_deg, 2.0}), SolverOptions{});
    const double f_shank = profile_end_force(shooting);
    ASSERT_TRUE(std::isfinite(f_shank)) << alpha_deg;
    gaps.push_back(std::abs(f_shank / f_equator - 1.0));
    std::cout << fmt::format(
        "half-angle {:g} deg: contact reaches the shank at f = {:.8f} "
        "(sphere-tipped equator {:.8f}), relative gap {:.3e}\n",
        alpha_deg,
        f_shank,
        f_equator,
        gaps.back());
  }
  // Halving alpha halves the gap (first order), within 20 %.
  EXPECT_NEAR(gaps[0] / gaps[1], 2.0, 0.4);
  EXPECT_NEAR(gaps[1] / gaps[2], 2.0, 0.4);
  EXPECT_LT(gaps[2], 0.05);
  // Below that force the contact is on the tip sphere, the sphere-tipped probe's state.
  const auto thin = shooting_of<Cone>(with_probe(Cone{2.0, 1.0, 2.0}), SolverOptions{});
  const auto sphere = shooting_of<SphereTipped>(with_probe(SphereTipped{2.0}), SolverOptions{});
  const auto c = thin.solve(Stage::Slip, 0.5 * f_equator);
  const auto s = sphere.solve(Stage::Slip, 0.5 * f_equator);
  ASSERT_TRUE(c.ok() && s.ok());
  EXPECT_NEAR(c.depth, s.depth, 1e-9 * s.depth);
}

// The contact pressure from normal balance is >= 0 along the cap and the cone, the cap lies on
// the tip sphere and the cone, and Part I never enters the probe (the sphere, the cone, the
// shank); hoop stress tensile everywhere (a wrinkled state would be Status::Wrinkles, not ok()).
// Geometric tolerance 1e-9 A.
TEST(ConeProbe, PressurePositiveOnTheProfileNoPenetration) {
  const Cone cone{2.0, 30.0, 0.5};
  const Problem p = with_probe(cone);
  const double rt = cone.tip_radius_mm, alpha = cone.half_angle_deg * std::numbers::pi / 180.0;
  const double r_tangency = rt * std::cos(alpha), shank = cone.radius_mm;
  const double tol = 1e-9 * p.geometry.clamp_radius_mm;
  // Height of the probe's surface above its tip at radius r (the shank: vertical at r = shank).
  auto surface = [&](double r) {
    if (r <= r_tangency) return rt - std::sqrt(rt * rt - r * r);
    return rt * (1.0 - std::sin(alpha)) + (r - r_tangency) / std::tan(alpha);
  };
  SolverOptions o;
  o.field_points = 400;
  double min_pressure = std::numeric_limits<double>::infinity();
  bool saw_cone = false;
  for (const double depth : {1.0, 4.0, 10.0, 14.0}) {
    const auto e = solve_at_depth(p, depth, Stage::Slip, o);
    ASSERT_TRUE(e.ok()) << depth << ": " << e.message;
    const auto& m = e.fields;
    for (std::size_t i = 0; i < m.size(); ++i) {
      const double r = m.radius_mm[i], height = e.depth_mm - m.deflection_mm[i];
      EXPECT_GT(m.hoop_stress_mpa[i], 0.0) << "R " << m.reference_radius_mm[i];
      if (m.part[i] == MembranePart::Tip) {
        EXPECT_GE(m.contact_pressure_mpa[i], 0.0) << "R " << m.reference_radius_mm[i];
        min_pressure = std::min(min_pressure, m.contact_pressure_mpa[i]);
        EXPECT_NEAR(height, surface(r), tol) << "off the profile at r " << r;
        EXPECT_LE(r, shank + tol);
        saw_cone = saw_cone || r > r_tangency + 1e-6;
      } else if (r < shank - tol) {  // free, under the probe: below its surface
        EXPECT_LE(height, surface(r) + tol) << "Part I enters the probe at r " << r;
      }
    }
  }
  EXPECT_TRUE(saw_cone);
  record("cone_min_contact_pressure_mpa", min_pressure);
}

// Puncture by the critical I1 on the cone with a 0.2 mm tip (docs/model.md, §15.2): at the pole,
// equibiaxial (2 L^2 + L^-4 = I1c), with Part I leaving over the kink; with a 0.5 mm tip the
// contact reaches the shank first, a status naming it, never a number.
TEST(ConeProbe, PunctureSiteAndTheShank) {
  const auto pp = predict_puncture(with_probe(Cone{2.0, 30.0, 0.2}));
  ASSERT_TRUE(pp.ok()) << pp.message;
  EXPECT_EQ(pp.crack_location, "the pole, under the tip sphere");
  const double l = pp.part_three_stretch;
  EXPECT_NEAR(2.0 * l * l + 1.0 / (l * l * l * l), 95.2, 1e-6 * 95.2);
  EXPECT_GT(pp.state.corner_slope_rad, std::numbers::pi / 3.0);  // over the kink
  EXPECT_LE(pp.state.corner_slope_rad, std::numbers::pi / 2.0);
  record("cone_puncture_force_n", pp.force_n);
  const auto blunt = predict_puncture(with_probe(Cone{2.0, 30.0, 0.5}));
  EXPECT_EQ(blunt.status, Status::OutsideModel);
  EXPECT_NE(blunt.message.find("reaches the shank"), std::string::npos) << blunt.message;
  std::cout << fmt::format(
      "cone tip 0.2 mm: puncture at {:.5f} N, {:.4f} mm, exit slope {:.4f} "
      "rad; tip 0.5 mm: {}\n",
      pp.force_n,
      pp.depth_mm,
      pp.state.corner_slope_rad,
      blunt.message);
}

// Coulomb slip on the tip, the cone and the kink (docs/model.md, §15.2): at a fixed depth the
// force grows with the friction and tends to the frictionless one as mu -> 0 (mu = 1e-4: O(mu),
// below 1e-3 relative); the indenter's work exceeds the stored energy (dU/ddelta < F, by more
// than the 1e-6 the frictionless check allows), on the cone and over the kink.
TEST(ConeProbe, CoulombSlipOnTheConeAndTheKink) {
  std::vector<double> forces;
  for (const double mu : {0.0, 1e-4, 0.18}) {
    Problem p = with_probe(Cone{2.0, 30.0, 0.5});
    p.friction = mu;
    const auto e = solve_at_depth(p, 10.0, Stage::Slip);
    ASSERT_TRUE(e.ok()) << mu << ": " << e.message;
    forces.push_back(e.force_n);
  }
  EXPECT_LT(std::abs(forces[1] / forces[0] - 1.0), 1e-3);
  EXPECT_GT(forces[1], forces[0]);
  EXPECT_GT(forces[2], forces[1]);
  Problem p = with_probe(Cone{2.0, 30.0, 0.5});
  p.friction = 0.18;
  const auto shooting = shooting_of<Cone>(p, test::tight_options());
  const double f_shank = profile_end_force(shooting);
  ASSERT_TRUE(std::isfinite(f_shank));
  for (const double f : {3e-2, 0.97 * f_shank}) {
    const double h = 1e-3 * f;
    std::vector<StoredEnergy> s;
    for (const double k : {-2.0, -1.0, 1.0, 2.0}) {
      const auto e = stored_energy_at(shooting, f + k * h);
      ASSERT_TRUE(e.has_value()) << "f = " << f + k * h;
      s.push_back(*e);
    }
    const double du = (s[0].energy - 8.0 * s[1].energy + 8.0 * s[2].energy - s[3].energy);
    const double dd = (s[0].depth - 8.0 * s[1].depth + 8.0 * s[2].depth - s[3].depth);
    const double dissipated = 1.0 - du / dd / f;
    EXPECT_GT(dissipated, 1e-4) << f;
    std::cout << fmt::format(
        "cone mu 0.18, f {:g}, exit slope {:.4f}: 1 - (dU/ddelta)/F = {:.4f}\n",
        f,
        s[1].slope,
        dissipated);
  }
  std::cout << fmt::format("cone at 10 mm: F = {:.6f} N (mu 0), {:.6f} N (1e-4), {:.6f} N (0.18)\n",
                           forces[0],
                           forces[1],
                           forces[2]);
}

// The ball is the sphere-tipped probe of its radius up to its equator: at a force, to the bit
// (the same contact model and plan); at a depth to the depth solve's 1e-9 (its path differs: the
// ball reports no configuration change at the equator, where its model ends).  Past the equator
// the model stops with a status naming the neck, and a depth it cannot reach is never answered
// by a number.
TEST(BallProbe, SphereTippedToTheEquatorThenAStatus) {
  const Problem ball = with_probe(Ball{1.0, 2.0});
  const Problem sphere = with_probe(SphereTipped{2.0});
  const auto ball_shooting = shooting_of<Ball>(ball, SolverOptions{});
  const auto sphere_shooting = shooting_of<SphereTipped>(sphere, SolverOptions{});
  for (const double f : {1e-4, 1e-2, 0.08}) {
    const auto b = ball_shooting.solve(Stage::Slip, f);
    const auto s = sphere_shooting.solve(Stage::Slip, f);
    ASSERT_TRUE(b.ok() && s.ok()) << b.message;
    EXPECT_EQ(b.depth, s.depth) << f;
    EXPECT_EQ(b.parameter, s.parameter) << f;
    EXPECT_EQ(b.max_i1, s.max_i1) << f;
  }
  for (const double depth : {2.0, 8.0, 14.0}) {
    const auto b = solve_at_depth(ball, depth, Stage::Slip);
    const auto s = solve_at_depth(sphere, depth, Stage::Slip);
    ASSERT_TRUE(b.ok() && s.ok()) << b.message;
    EXPECT_NEAR(b.force_n, s.force_n, 1e-9 * s.force_n) << depth;
  }
  const auto past = solve_at_depth(ball, 20.0, Stage::Slip);
  EXPECT_EQ(past.status, Status::OutsideModel);
  EXPECT_NE(past.message.find("neck"), std::string::npos) << past.message;
  const auto sphere_past = solve_at_depth(sphere, 20.0, Stage::Slip);
  EXPECT_TRUE(sphere_past.ok());
}

// A puncture search that closes on where the model ends (the ball's equator, the cone's shank)
// brackets that end to a few ulps, and its middle may land past it, where no state exists: the
// search steps below it (find_puncture_by), so that the curve's puncture reports the largest I1
// reached there, whichever side the solves' rounding put it on.  (The ball's curve below ended
// with the bare "before the states leave the model" when the equator onset's rounding changed.)
TEST(BallProbe, PunctureSearchEndingAtTheModelsEndReportsTheLargestI1Reached) {
  CurveOptions curve;
  curve.points = 60;
  curve.max_depth_mm = 15.0;
  const auto ball = loading_curve(with_probe(Ball{1.0, 3.0}), curve);
  ASSERT_TRUE(ball.ok()) << ball.message;
  EXPECT_EQ(ball.puncture.status, Status::OutsideModel);
  EXPECT_NE(ball.puncture.message.find("largest I1 reaches only 23.229919 (critical 95.2)"),
            std::string::npos)
      << ball.puncture.message;
  EXPECT_NE(ball.puncture.message.find("neck"), std::string::npos) << ball.puncture.message;
  curve.max_depth_mm = 20.0;
  const auto cone = loading_curve(with_probe(Cone{3.0, 30.0, 1.0}), curve);
  ASSERT_TRUE(cone.ok()) << cone.message;
  EXPECT_EQ(cone.puncture.status, Status::OutsideModel);
  EXPECT_NE(cone.puncture.message.find("largest I1 reaches only 58.867339 (critical 95.2)"),
            std::string::npos)
      << cone.puncture.message;
  EXPECT_NE(cone.puncture.message.find("reaches the shank"), std::string::npos)
      << cone.puncture.message;
}

// Small deflection of the frictionless ball: the Föppl sphere (foppl_sphere.hpp) at the same
// force, F A^2 / (E H delta^3) agreeing to O((delta/A)^2) as for the sphere-tipped probe.
TEST(BallProbe, SmallDeflectionMatchesFopplSphere) {
  const Problem p = with_probe(Ball{1.0, 3.0});
  const auto shooting = shooting_of<Ball>(p, test::tight_options());
  const double a = shooting.contact().settings().a;
  double last = 0.0;
  for (const double f : {1e-5, 1e-6, 1e-7}) {
    const auto sol = shooting.solve(Stage::Slip, f);
    ASSERT_TRUE(sol.ok()) << sol.message;
    const double d = sol.depth, d_foppl = foppl_sphere_depth(a, f);
    const double error = std::abs(std::pow(d_foppl / d, 3.0) - 1.0);
    EXPECT_LT(error, 5.0 * d * d) << f;
    if (last > 0.0) EXPECT_LT(error, last);
    last = error;
    std::cout << fmt::format(
        "ball f {:g}: delta/A {:.4g}, relative difference {:.3e} = {:.3f} (delta/A)^2\n",
        f,
        d,
        error,
        error / (d * d));
  }
  record("ball_foppl_relative_difference_smallest_force", last);
}

// Bad dimensions are refused naming the parameter: a ball no wider than its rod or wider than the
// opening, a cone angle outside (0, 90) degrees, a tip radius <= 0 or a tip sphere wider than the
// shank, a stick rule over a sealed gas chamber (a gas pressure alone is accepted, and a stick
// rule without one or under a held one).
TEST(ConeProbe, BadDimensionsNameTheParameter) {
  auto only_error = [](const Problem& p) {
    const auto errors = validation_errors(p);
    return errors.size() == 1 ? errors.front().parameter
                              : std::string("(") + std::to_string(errors.size()) + " errors)";
  };
  EXPECT_TRUE(validation_errors(with_probe(Ball{1.0, 2.0})).empty());
  EXPECT_TRUE(validation_errors(with_probe(Cone{2.0, 30.0, 0.5})).empty());
  EXPECT_EQ(only_error(with_probe(Ball{2.0, 2.0})), "indenter.ball_radius_mm");
  EXPECT_EQ(only_error(with_probe(Ball{2.0, 25.0})), "indenter.ball_radius_mm");
  for (const double alpha : {0.0, 90.0, -5.0, std::nan("")})
    EXPECT_EQ(only_error(with_probe(Cone{2.0, alpha, 0.5})), "indenter.half_angle_deg") << alpha;
  EXPECT_EQ(only_error(with_probe(Cone{2.0, 30.0, 0.0})), "indenter.tip_radius_mm");
  EXPECT_EQ(only_error(with_probe(Cone{2.0, 30.0, 2.5})), "indenter.tip_radius_mm");
  EXPECT_EQ(only_error(with_probe(Cone{30.0, 30.0, 0.5})), "indenter.radius_mm");
  Problem inflated = with_probe(Cone{2.0, 30.0, 0.5});
  inflated.preload.pressure_mpa = 3e-4;  // solved (pressurised_probes_test.cpp)
  EXPECT_TRUE(validation_errors(inflated).empty());
  // Held (docs/model.md §15.5): solved, under a held gas pressure too (§17.3,
  // pressurised_profile_stick_test.cpp); over a sealed chamber refused.
  Problem held = with_probe(Ball{1.0, 2.0});
  held.stick = {StickRule::Always, 0.0};
  EXPECT_TRUE(validation_errors(held).empty());
  held.preload.pressure_mpa = 3e-4;
  EXPECT_TRUE(validation_errors(held).empty());
  held.preload.gas_volume_mm3 = 2e6;
  const auto held_errors = validation_errors(held);
  EXPECT_TRUE(std::any_of(held_errors.begin(), held_errors.end(), [](const auto& e) {
    return e.parameter == "stick.rule";
  }));
  EXPECT_THROW(solve_at_depth(held, 5.0, Stage::Slip), InvalidInput);
}

}  // namespace cone_ball
}  // namespace puncture::detail
