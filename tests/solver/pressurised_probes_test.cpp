// The filleted flat punch and the cone under a held gas pressure (docs/model.md §15.2, §17, §19):
// on the fillet's flat face alone F = p pi c^2 (also with friction); the fillet shrinking to the
// sharp corner gives the sharp punch under pressure at first order; dPi/ddelta = F with Pi = U - p
// V (frictionless); a vanishing pressure gives the unpressurised probes; the contact pressure is at
// least the gas pressure along the contact and its axial resultant carries the force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

#include "indentation/face_slip.hpp"
#include "pressurised_support.hpp"
#include "puncture/inflation.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

Problem gas_fillet(double fillet_mm, double friction = 0.0, double pressure_mpa = kPressureMpa) {
  return pressurised(pressure_mpa, friction, FlatPunch{2.0, fillet_mm});
}

Problem gas_cone(double friction = 0.0, double pressure_mpa = kPressureMpa) {
  return pressurised(pressure_mpa, friction, Cone{2.0, 30.0, 0.5});
}

// The radius of the contact's outermost point (the largest r of the samples on the probe's tip).
double gas_probe_contact_radius_mm(const MembraneFields& m) {
  double c = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m.part[i] == MembranePart::Tip) c = std::max(c, m.radius_mm[i]);
  return c;
}

// While the membrane touches the fillet's flat face only (b = 1.5 mm, F < p pi b^2 = 2.1e-3 N),
// the gas alone carries the force on the contact disc: F = p pi c^2 with c from the fields, to
// rounding (1e-12); Part I leaves the face horizontally and stays below it.  With friction (mu' =
// 0.18) the face is not uniform (the hoop stretch grows outward) and the identity still holds:
// the traction is horizontal.
TEST(PressurisedProbes, OnTheFilletsFaceTheForceIsThePressureTimesTheContactArea) {
  for (const double friction : {0.0, 0.18}) {
    const Problem p = gas_fillet(0.5, friction);
    for (const double depth : {0.01, 0.05, 0.1}) {
      SCOPED_TRACE(fmt::format("mu' {}, depth {} mm", friction, depth));
      const auto e = solve_at_depth(p, depth, Stage::Slip, sampled(400));
      ASSERT_TRUE(e.ok()) << e.message;
      const auto& m = e.fields;
      const double c = gas_probe_contact_radius_mm(m);
      ASSERT_LT(c, 1.5);
      EXPECT_NEAR(e.force_n / (kPressureMpa * kPi * c * c), 1.0, 1e-12);
      const auto free = part_indices(m, 1);
      ASSERT_FALSE(free.empty());
      EXPECT_NEAR(m.slope_rad[free.front()], 0.0, 1e-12);
      for (const std::size_t i : free) EXPECT_GE(m.deflection_mm[i], e.depth_mm - 1e-12);
      for (std::size_t i = 0; i < m.size(); ++i) {
        if (m.part[i] != MembranePart::Tip) continue;
        EXPECT_NEAR(m.deflection_mm[i], e.depth_mm, 1e-12);  // flat, at the tip's depth
        EXPECT_NEAR(m.contact_pressure_mpa[i], kPressureMpa, 1e-15);
      }
      if (friction > 0.0) {  // the hoop stretch grows outward on the rough face
        const auto tip = part_indices(m, 3);
        ASSERT_GE(tip.size(), 3u);
        EXPECT_GT(m.hoop_stretch[tip.back()], m.hoop_stretch[tip.front()]);
        EXPECT_GT(m.radial_stretch[tip.back()], m.hoop_stretch[tip.back()]);
      }
    }
  }
}

// Past p pi b^2 the arc takes over continuously: the states just below and above have the same
// face stretch, the contact edge at the face's edge.
TEST(PressurisedProbes, TheFilletsArcTakesOverFromTheFaceContinuously) {
  const Problem p = gas_fillet(0.5);
  const double face_load = kPressureMpa * kPi * 1.5 * 1.5;
  const auto below = solve_at_force(p, face_load * (1.0 - 1e-7), Stage::Slip);
  const auto above = solve_at_force(p, face_load * (1.0 + 1e-7), Stage::Slip);
  ASSERT_TRUE(below.ok() && above.ok()) << below.message << above.message;
  EXPECT_NEAR(above.part_three_stretch, below.part_three_stretch, 1e-6);
  EXPECT_NEAR(above.depth_mm, below.depth_mm, 1e-6);
  EXPECT_NEAR(below.corner_reference_radius_mm * below.part_three_stretch, 1.5, 1e-6);
  EXPECT_LT(above.corner_slope_rad, 1e-3);
}

// The fillet shrinking to the sharp corner: the force at a depth tends to the sharp punch's under
// the same pressure (its own model, FlatPunchContact) at first order in rho, as without pressure
// (§19): on the face and the fillet (5 mm) and with the side wrapped (25 mm).
TEST(PressurisedProbes, VanishingFilletGivesTheSharpPunchUnderPressure) {
  for (const double depth : {5.0, 25.0}) {
    const auto sharp = solve_at_depth(gas_fillet(0.0), depth, Stage::Slip);
    ASSERT_TRUE(sharp.ok()) << sharp.message;
    std::vector<double> errors;
    for (const double rho : {0.2, 0.1, 0.05, 0.025}) {
      const auto e = solve_at_depth(gas_fillet(rho), depth, Stage::Slip);
      ASSERT_TRUE(e.ok()) << e.message;
      errors.push_back(std::abs(e.force_n / sharp.force_n - 1.0));
      std::cout << fmt::format("depth {} mm, rho {} mm: {:.10g} N (sharp {:.10g}), {:.3e}\n",
                               depth,
                               rho,
                               e.force_n,
                               sharp.force_n,
                               errors.back());
    }
    for (std::size_t k = 1; k < errors.size(); ++k) {
      const double rate = std::log2(errors[k - 1] / errors[k]);
      EXPECT_NEAR(rate, 1.0, 0.1) << "depth " << depth << ", halving " << k;
      record(fmt::format("rate_{}mm_{}", depth, k), rate);
    }
  }
}

// Constant pressure, frictionless: dPi/ddelta = F with Pi = U - p V from the fields, the central
// difference at h = delta / 100 and h/2 extrapolated (error O(h^4)), for the fillet on its face,
// on the arc and with the side, and for the cone on its tip sphere (1, 2 mm), on the cone (6 mm)
// and leaving over its kink (14 mm).  Tolerance 1e-6: the fields' quadrature (Richardson over 2000
// samples; on the cone's 0.5 mm tip at 1-2 mm it needs 8000: at 2 mm 1.5e-6, 2.0e-7, 2.6e-8 with
// 2000, 4000, 8000, the quadrature's order 3, not the model's).
TEST(PressurisedProbes, ForceIsTheDerivativeOfUMinusPV) {
  struct Case {
    Problem p;
    double depth;
    int samples;
  };
  for (const auto& [p, depth, samples] : {Case{gas_fillet(0.5), 0.05, 2000},
                                          Case{gas_fillet(0.5), 5.0, 2000},
                                          Case{gas_fillet(0.5), 25.0, 2000},
                                          Case{gas_cone(), 1.0, 8000},
                                          Case{gas_cone(), 2.0, 8000},
                                          Case{gas_cone(), 6.0, 2000},
                                          Case{gas_cone(), 14.0, 2000}}) {
    const SolverOptions fine = sampled(samples);
    SCOPED_TRACE(fmt::format("{}, {} mm", describe(p.indenter), depth));
    auto pi_at = [&](double d) {
      const auto e = solve_at_depth(p, d, Stage::Slip, fine);
      EXPECT_TRUE(e.ok()) << e.message;
      return potential(p, e).value;
    };
    const auto e = solve_at_depth(p, depth, Stage::Slip, fine);
    ASSERT_TRUE(e.ok()) << e.message;
    const double h = depth / 100.0;
    const double d1 = (pi_at(depth + h) - pi_at(depth - h)) / (2.0 * h);
    const double d2 = (pi_at(depth + h / 2) - pi_at(depth - h / 2)) / h;
    const double derivative = (4.0 * d2 - d1) / 3.0;
    const double relative = derivative / e.force_n - 1.0;
    std::cout << fmt::format("{}, {} mm ({}): F {:.10g} N, dPi/ddelta {:.10g}, {:.2e}\n",
                             describe(p.indenter),
                             depth,
                             to_string(e.configuration),
                             e.force_n,
                             derivative,
                             relative);
    EXPECT_NEAR(relative, 0.0, 1e-6);
  }
}

// The axial resultant of the contact pressure, pi int p d(r^2) over the probe's tip [N]: the
// trapezoid rule with Richardson's step on each smooth piece.  The pressure jumps where the
// profile's meridional curvature does, at the known radius `jump_mm` (the fillet's face edge b,
// the cone's tangency R_T cos(alpha)), between the two samples where it changes most; each piece
// is extended to that radius linearly from its last (first) two samples (on the face: constant).
// A contact that ends before that radius is one piece.
double gas_probe_axial_resultant_n(const MembraneFields& m, double jump_mm) {
  std::vector<double> r2, p;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m.part[i] != MembranePart::Tip) continue;
    r2.push_back(m.radius_mm[i] * m.radius_mm[i]);
    p.push_back(m.contact_pressure_mpa[i]);
  }
  if (!(r2.back() > jump_mm * jump_mm)) return kPi * integrate(r2, p).value;  // one piece
  std::size_t split = 1;  // the first sample of the outer piece
  for (std::size_t i = 1; i < p.size(); ++i)
    if (std::abs(p[i] - p[i - 1]) > std::abs(p[split] - p[split - 1])) split = i;
  const double x = jump_mm * jump_mm;
  std::vector<double> inner_r2(r2.begin(), r2.begin() + split),
      inner_p(p.begin(), p.begin() + split);
  std::vector<double> outer_r2(r2.begin() + split, r2.end()), outer_p(p.begin() + split, p.end());
  auto at = [x](double x0, double p0, double x1, double p1) {
    return x1 == x0 ? p1 : p0 + (p1 - p0) * (x - x0) / (x1 - x0);
  };
  if (inner_r2.back() < x) {
    const std::size_t n = inner_r2.size();
    inner_p.push_back(n < 2 ? inner_p.back()
                            : at(inner_r2[n - 2], inner_p[n - 2], inner_r2[n - 1], inner_p[n - 1]));
    inner_r2.push_back(x);
  }
  if (outer_r2.size() >= 2 && outer_r2.front() > x) {
    outer_p.insert(outer_p.begin(), at(outer_r2[0], outer_p[0], outer_r2[1], outer_p[1]));
    outer_r2.insert(outer_r2.begin(), x);
  }
  return kPi * (integrate(inner_r2, inner_p).value + integrate(outer_r2, outer_p).value);
}

// The contact pressure is Laplace's plus the gas pressure: >= p along the contact (p on the
// fillet's face), and its axial resultant over the contact (the edge on the fillet, or on the tip
// sphere and the cone: no line force) carries the force (frictionless; 2000 samples: 1e-6).
TEST(PressurisedProbes, ContactPressureAtLeastTheGasPressureAndCarryingTheForce) {
  struct Case {
    Problem p;
    double jump_mm;  // the fillet's face edge b, the cone's tangency R_T cos(alpha)
  };
  for (const auto& [p, jump] :
       {Case{gas_fillet(0.5), 1.5}, Case{gas_cone(), 0.5 * std::cos(kPi / 6.0)}}) {
    for (const double depth : {1.0, 3.0, 5.0, 8.0}) {
      SCOPED_TRACE(fmt::format("{}, {} mm", describe(p.indenter), depth));
      const auto e = solve_at_depth(p, depth, Stage::Slip, sampled(2000));
      ASSERT_TRUE(e.ok()) << e.message;
      ASSERT_EQ(e.configuration, Configuration::SlipWithoutPartTwo);
      const auto& m = e.fields;
      for (std::size_t i = 0; i < m.size(); ++i) {
        EXPECT_GT(m.hoop_stress_mpa[i], 0.0) << "R " << m.reference_radius_mm[i];
        if (m.part[i] == MembranePart::Tip)
          EXPECT_GE(m.contact_pressure_mpa[i], kPressureMpa * (1.0 - 1e-12));
      }
      const double resultant = gas_probe_axial_resultant_n(m, jump);
      std::cout << fmt::format("{}, {} mm: resultant / F - 1 = {:.2e}\n",
                               describe(p.indenter),
                               depth,
                               resultant / e.force_n - 1.0);
      EXPECT_NEAR(resultant / e.force_n, 1.0, 1e-6);
      record(fmt::format("resultant_relative_error_{}mm", depth),
             std::abs(resultant / e.force_n - 1.0));
    }
  }
}

// A vanishing pressure: with the tip at the same height (the unpressurised depth plus the dome's
// height) the force tends to the unpressurised probe's at first order in p (as the sphere's,
// pressurised_test.cpp): the fillet (with and without friction) and the cone.
TEST(PressurisedProbes, VanishingPressureGivesTheUnpressurisedProbes) {
  const double depth = 10.0;
  for (const Problem& base : {gas_fillet(0.5), gas_fillet(0.5, 0.18), gas_cone()}) {
    SCOPED_TRACE(fmt::format("{}, mu' {}", describe(base.indenter), base.friction));
    Problem unpressurised = base;
    unpressurised.preload.pressure_mpa = 0.0;
    const auto free = solve_at_depth(unpressurised, depth, Stage::Slip);
    ASSERT_TRUE(free.ok()) << free.message;
    double previous = std::numeric_limits<double>::infinity();
    for (const double pressure : {1e-8, 1e-9, 1e-10}) {
      Problem p = base;
      p.preload.pressure_mpa = pressure;
      const auto dome = inflate_at_pressure(inflation_problem(p), pressure);
      ASSERT_TRUE(dome.ok()) << dome.message;
      const auto e = solve_at_depth(p, depth + dome.states.front().pole_height_mm, Stage::Slip);
      ASSERT_TRUE(e.ok()) << e.message;
      const double difference = std::abs(e.force_n / free.force_n - 1.0);
      std::cout << fmt::format("p {:g} MPa: {:.10g} N (unpressurised {:.10g}), {:.3e}\n",
                               pressure,
                               e.force_n,
                               free.force_n,
                               difference);
      EXPECT_LT(difference, 0.15 * previous);  // first order: a factor 10 per decade
      EXPECT_LT(difference, 1e4 * pressure);
      previous = difference;
    }
  }
}

// Friction vanishing under pressure: the fillet's rough face (its own march) tends to the uniform
// face at first order in mu', on the face (0.05 mm) and on the arc (5 mm); the cone at 10 mm.
TEST(PressurisedProbes, VanishingFrictionGivesTheFrictionlessProbesUnderPressure) {
  struct Case {
    Problem frictionless;
    double depth;
  };
  for (const auto& [base, depth] :
       {Case{gas_fillet(0.5), 0.05}, Case{gas_fillet(0.5), 5.0}, Case{gas_cone(), 10.0}}) {
    SCOPED_TRACE(fmt::format("{}, {} mm", describe(base.indenter), depth));
    const auto smooth = solve_at_depth(base, depth, Stage::Slip);
    ASSERT_TRUE(smooth.ok()) << smooth.message;
    std::vector<double> differences;
    for (const double mu : {1e-2, 1e-3, 1e-4}) {
      Problem p = base;
      p.friction = mu;
      const auto e = solve_at_depth(p, depth, Stage::Slip);
      ASSERT_TRUE(e.ok()) << e.message;
      differences.push_back(std::abs(e.force_n / smooth.force_n - 1.0));
      std::cout << fmt::format("mu' {:g}: {:.10g} N (frictionless {:.10g}), {:.3e}\n",
                               mu,
                               e.force_n,
                               smooth.force_n,
                               differences.back());
    }
    for (std::size_t k = 1; k < differences.size(); ++k)
      EXPECT_NEAR(std::log10(differences[k - 1] / differences[k]), 1.0, 0.1);
  }
}

// Over a sealed chamber (docs/model.md §17.1) the probes follow the gas law: the state at 10 mm
// (10^6 mm^3 sealed at 0.3 kPa) has (p + p_atm)(V0 + V) equal to its sealing value to 1e-11 of it,
// a pressure risen above the sealing one, and a force above the held pressure's.
TEST(PressurisedProbes, OverASealedChamberTheGasLawHolds) {
  for (const Problem& held : {gas_fillet(0.5), gas_fillet(0.5, 0.18), gas_cone()}) {
    SCOPED_TRACE(fmt::format("{}, mu' {}", describe(held.indenter), held.friction));
    Problem p = held;
    p.preload.gas_volume_mm3 = 1e6;
    const double p_atm = p.preload.atmospheric_pressure_mpa;
    const auto dome = solve_at_depth(p, 0.0, Stage::Slip);
    ASSERT_TRUE(dome.ok() && dome.gas) << dome.message;
    const double content = (kPressureMpa + p_atm) * (1e6 + dome.gas->volume_mm3);
    const auto e = solve_at_depth(p, 10.0, Stage::Slip);
    ASSERT_TRUE(e.ok() && e.gas) << e.message;
    EXPECT_NEAR(
        (e.gas->pressure_mpa + p_atm) * (1e6 + e.gas->volume_mm3), content, 1e-11 * content);
    EXPECT_GT(e.gas->pressure_mpa, kPressureMpa);
    const auto at_held = solve_at_depth(held, 10.0, Stage::Slip);
    ASSERT_TRUE(at_held.ok()) << at_held.message;
    EXPECT_GT(e.force_n, at_held.force_n);
  }
}

// With friction the fillet's face and arc are modelled sliding outward, as the sharp punch's face
// (§17): the library checks the direction on the fillet too (face_slip.cpp compares the material
// on the tip in two nearby states).  Lubricated (mu' = 0.18) the material slides inward at 0.5 mm
// and outward at 3 mm, and the curve names the change between 1 and 2 mm (measured 1.47 mm on the
// default curve; the sharp punch's between 1 and 2 mm as well).
TEST(PressurisedProbes, TheFilletsFaceSlipDirectionIsChecked) {
  const Problem p = gas_fillet(0.5, 0.18);
  const auto early = detail::face_slip(p, 0.5), late = detail::face_slip(p, 3.0);
  ASSERT_TRUE(early && late);
  EXPECT_LT(early->least_mm, 0.0);
  EXPECT_GT(late->least_mm, 0.0);
  CurveOptions curve;
  curve.depths_mm = {0.5, 1.0, 1.5, 2.0, 3.0};
  const auto c = loading_curve(p, curve);
  ASSERT_TRUE(c.ok()) << c.message;
  ASSERT_TRUE(c.face_slides_outward_from_mm.has_value());
  EXPECT_GT(*c.face_slides_outward_from_mm, 1.0);
  EXPECT_LE(*c.face_slides_outward_from_mm, 2.0);
}

}  // namespace
}  // namespace puncture::test
