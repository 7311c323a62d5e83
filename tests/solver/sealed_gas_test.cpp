// Indentation over a sealed gas chamber (Problem::preload.gas_volume_mm3, docs/model.md §17.1):
// the contact-free state is the inflation solver's at the sealing pressure, a large chamber tends
// to the held pressure at the rate 1/V0, the energy balance dPi/ddelta = F with the gas's
// isothermal free energy, F = p pi c^2 on the flat face at the current pressure, the force
// growing faster than at a held pressure, the gas law at puncture, and invalid chambers.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "pressurised_support.hpp"
#include "puncture/inflation.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

constexpr double kAtmosphereMpa = 0.101325;

Problem sealed(double gas_volume_mm3, Problem p = pressurised()) {
  p.preload.gas_volume_mm3 = gas_volume_mm3;
  return p;
}

// The gas law's constant (P + p_atm)(V0 + V_s) of a problem [N mm], from its contact-free state.
double gas_content(const Problem& p, const SolverOptions& options) {
  const auto dome = solve_at_depth(p, 0.0, Stage::Slip, options);
  EXPECT_TRUE(dome.ok() && dome.gas) << dome.message;
  return (p.preload.pressure_mpa + p.preload.atmospheric_pressure_mpa) *
         (*p.preload.gas_volume_mm3 + dome.gas->volume_mm3);
}

TEST(SealedGas, ContactFreeStateIsTheInflationSolversAtTheSealingPressure) {
  Problem stretched = flat();
  stretched.preload.prestretch = 1.2;
  stretched.preload.pressure_mpa = 5e-4;
  for (const Problem& base : {pressurised(), flat(), stretched}) {
    SCOPED_TRACE(fmt::format("{}, L0 = {}", describe(base.indenter), base.preload.prestretch));
    const Problem p = sealed(2e5, base);
    const auto inflated = inflate_at_pressure(inflation_problem(base), base.preload.pressure_mpa);
    ASSERT_TRUE(inflated.ok()) << inflated.message;
    const InflationState& dome = inflated.states.front();
    const auto e = solve_at_depth(p, 0.0, Stage::Slip, sampled(2000));
    ASSERT_TRUE(e.ok()) << e.message;
    ASSERT_TRUE(e.gas.has_value());
    EXPECT_EQ(e.force_n, 0.0);
    EXPECT_EQ(e.gas->pressure_mpa, base.preload.pressure_mpa);
    EXPECT_NEAR(e.part_three_stretch, dome.pole_stretch, 1e-12);
    EXPECT_NEAR(e.max_first_invariant, dome.max_first_invariant, 1e-12);
    EXPECT_NEAR(e.fields.deflection_mm.back(), dome.pole_height_mm, 1e-9 * dome.pole_height_mm);
    // The volume from the fields against the inflation solver's integral of pi r^2 dz.
    EXPECT_NEAR(e.gas->volume_mm3, dome.volume_mm3, 1e-9 * dome.volume_mm3);
    record("relative_volume_difference_L0_" + std::to_string(base.preload.prestretch),
           std::abs(e.gas->volume_mm3 / dome.volume_mm3 - 1.0));
    // The held-pressure solver sees the same state.
    const auto held = solve_at_depth(base, 0.0, Stage::Slip, sampled(2000));
    ASSERT_TRUE(held.ok()) << held.message;
    EXPECT_EQ(held.gas, std::nullopt);
    EXPECT_EQ(e.part_three_stretch, held.part_three_stretch);
  }
}

// Every state over the chamber satisfies the gas law with its own enclosed volume, the pressure
// rises and the volume falls as the probe goes in.
TEST(SealedGas, StatesSatisfyTheIsothermalGasLaw) {
  for (const Problem& base : {pressurised(), flat()}) {
    SCOPED_TRACE(describe(base.indenter));
    const Problem p = sealed(1e6, base);
    const double content = gas_content(p, {});
    double last_p = p.preload.pressure_mpa, last_v = std::numeric_limits<double>::infinity();
    for (const double depth : {0.1, 2.0, 10.0, 25.0}) {
      const auto e = solve_at_depth(p, depth, Stage::Slip);
      ASSERT_TRUE(e.ok()) << e.message;
      EXPECT_NEAR(e.depth_mm, depth, 1e-9 * depth);
      const ChamberGas gas = *e.gas;
      const double law = (gas.pressure_mpa + kAtmosphereMpa) * (1e6 + gas.volume_mm3);
      EXPECT_NEAR(law, content, 1e-11 * content) << depth << " mm";
      EXPECT_GT(gas.pressure_mpa, last_p);
      EXPECT_LT(gas.volume_mm3, last_v);
      last_p = gas.pressure_mpa;
      last_v = gas.volume_mm3;
    }
  }
}

// V0 -> infinity: the pressure's rise is (P + p_atm)(V_s - V) / (V0 + V) ~ 1 / V0, and so is the
// force's excess over the held pressure's at the same depth: doubling V0 halves it (to the
// next order's share, ~ the relative rise of p).
TEST(SealedGas, LargeChamberTendsToTheHeldPressureAsOneOverV0) {
  for (const auto& [base, depth] : {std::pair{pressurised(), 10.0}, std::pair{flat(), 10.0}}) {
    SCOPED_TRACE(describe(base.indenter));
    const auto held = solve_at_depth(base, depth, Stage::Slip);
    ASSERT_TRUE(held.ok()) << held.message;
    std::vector<double> excess, rise;
    for (const double v0 : {1e8, 2e8, 4e8}) {
      const auto e = solve_at_depth(sealed(v0, base), depth, Stage::Slip);
      ASSERT_TRUE(e.ok()) << e.message;
      excess.push_back(e.force_n - held.force_n);
      rise.push_back(e.gas->pressure_mpa - base.preload.pressure_mpa);
      EXPECT_GT(excess.back(), 0.0);
    }
    // Measured: the ratios 1.983, 1.992 (sphere), 1.977, 1.989 (flat); their distance to 2 halves
    // with V0 as well (the next order, 1/V0^2).
    const double r0 = excess[0] / excess[1], r1 = excess[1] / excess[2];
    EXPECT_NEAR(r0, 2.0, 0.03);
    EXPECT_NEAR(r1, 2.0, 0.015);
    EXPECT_NEAR((r0 - 2.0) / (r1 - 2.0), 2.0, 0.2);
    EXPECT_NEAR(rise[0] / rise[1], 2.0, 0.03);
    EXPECT_NEAR(rise[1] / rise[2], 2.0, 0.015);
    record("force_excess_ratio_" + describe(base.indenter).substr(0, 4), excess[0] / excess[1]);
    record("force_excess_times_v0_n_mm3_" + describe(base.indenter).substr(0, 4), excess[2] * 4e8);
  }
}

// Pi = U + p_atm (V - V_s) - (P + p_atm)(V0 + V_s) ln((V0 + V) / (V0 + V_s)): the membrane's
// energy, the atmosphere's work and the isothermal gas's free energy (its work on the membrane
// is -int (p + p_atm) dV).  Frictionless, dPi/ddelta = F: the central difference extrapolated
// from steps h and h/2 (error O(h^4)) against the state's force.  U and V from the fields (2000
// samples).  The held-pressure potential U - P V misses the gas's stiffening.
double sealed_potential(const Problem& p, const Equilibrium& e, double sealed_volume_mm3) {
  Problem membrane = p;
  membrane.preload.pressure_mpa = 0.0;  // potential(): U - 0 V
  const double u = potential(membrane, e).value;
  const double v0 = *p.preload.gas_volume_mm3, dv = e.gas->volume_mm3 - sealed_volume_mm3;
  const double big_p = p.preload.pressure_mpa, p_atm = p.preload.atmospheric_pressure_mpa;
  // The same without the cancelling p_atm dV terms (each ~300 times the rest):
  // p_atm dV - C ln(1 + x) = -P dV - C (ln(1 + x) - x), x = dV / (V0 + V_s).
  const double x = dv / (v0 + sealed_volume_mm3);
  return u - big_p * dv - (big_p + p_atm) * (v0 + sealed_volume_mm3) * (std::log1p(x) - x);
}

TEST(SealedGas, ForceIsTheDerivativeOfThePotentialWithTheGasFreeEnergy) {
  const SolverOptions fine = sampled(2000);
  for (const auto& [base, depth] :
       {std::pair{pressurised(), 8.0}, std::pair{flat(), 0.1}, std::pair{flat(), 8.0}}) {
    SCOPED_TRACE(fmt::format("{}, {} mm", describe(base.indenter), depth));
    const Problem p = sealed(1e6, base);
    const auto dome = solve_at_depth(p, 0.0, Stage::Slip, fine);
    ASSERT_TRUE(dome.ok()) << dome.message;
    const double vs = dome.gas->volume_mm3;
    auto pi_at = [&](double d) {
      const auto e = solve_at_depth(p, d, Stage::Slip, fine);
      EXPECT_TRUE(e.ok()) << e.message;
      return sealed_potential(p, e, vs);
    };
    const auto e = solve_at_depth(p, depth, Stage::Slip, fine);
    ASSERT_TRUE(e.ok()) << e.message;
    // h = depth / 100 keeps the flat punch at 8 mm on one side of Part II's onset (h = depth / 10
    // straddles it: 2e-5).  Measured: 1.2e-7 (sphere), 7e-8 and 8e-9 (flat, 0.1 and 8 mm).
    const double h = 0.01 * depth;
    const double d1 = (pi_at(depth + h) - pi_at(depth - h)) / (2.0 * h);
    const double d2 = (pi_at(depth + h / 2) - pi_at(depth - h / 2)) / h;
    const double slope = (4.0 * d2 - d1) / 3.0;
    EXPECT_NEAR(slope, e.force_n, 1e-6 * e.force_n) << "dPi/ddelta " << slope << " N";
    record(fmt::format("relative_difference_{}_{}mm", describe(base.indenter).substr(0, 4), depth),
           std::abs(slope / e.force_n - 1.0));
    // With the held-pressure potential U - P V the balance fails by far.
    Problem held = base;
    auto pi_held = [&](double d) {
      return potential(held, solve_at_depth(p, d, Stage::Slip, fine)).value;
    };
    const double held_slope = (pi_held(depth + h / 2) - pi_held(depth - h / 2)) / h;
    EXPECT_GT(std::abs(held_slope - e.force_n), 1e-3 * e.force_n);
  }
}

// On the flat face the contact disc's vertical balance is F = p pi c^2 exactly, with p the
// chamber's current pressure (not the sealing one).
TEST(SealedGas, FlatFaceCarriesTheCurrentPressureTimesTheContactArea) {
  const Problem p = sealed(2e4, flat());
  for (const double depth : {0.02, 0.1, 0.2}) {
    const auto e = solve_at_depth(p, depth, Stage::Slip, sampled(400));
    ASSERT_TRUE(e.ok()) << e.message;
    const auto tip = part_indices(e.fields, 3);
    ASSERT_FALSE(tip.empty());
    const double c = e.fields.radius_mm[tip.back()];
    ASSERT_LT(c, 2.0 * (1.0 - 1e-6)) << "the disc reached the corner";
    const double p_now = e.gas->pressure_mpa;
    EXPECT_NEAR(e.force_n, p_now * kPi * c * c, 1e-10 * e.force_n) << depth << " mm";
    // The sealing pressure instead would miss by far more than the tolerance.
    EXPECT_GT(std::abs(e.force_n - p.preload.pressure_mpa * kPi * c * c), 1e-6 * e.force_n);
  }
}

// The gas stiffens the membrane: along the curve the force exceeds the held pressure's and a
// smaller chamber's exceeds a larger one's, while the pressure rises.  (The excess over the
// held-pressure curve need not grow everywhere: the flat punch's, V0 = 1e7 mm^3, falls from
// 0.0110 N at 9 mm to 0.0096 N at 12 mm, across the onset of Part II (at 11.04 mm held), where
// the two curves' kinks lie at different depths.)
TEST(SealedGas, ForceExceedsTheHeldPressuresAlongTheCurve) {
  for (const Problem& base : {pressurised(), flat()}) {
    SCOPED_TRACE(describe(base.indenter));
    CurveOptions c;
    c.points = 9;
    c.max_depth_mm = 24.0;
    const auto held = loading_curve(base, c);
    const auto large = loading_curve(sealed(1e7, base), c);
    const auto small = loading_curve(sealed(1e6, base), c);
    ASSERT_TRUE(held.ok() && large.ok() && small.ok())
        << held.message << large.message << small.message;
    for (std::size_t k = 1; k < held.points.size(); ++k) {
      SCOPED_TRACE(fmt::format("{} mm", held.points[k].depth_mm));
      EXPECT_GT(large.points[k].force_n, held.points[k].force_n);
      EXPECT_GT(small.points[k].force_n, large.points[k].force_n);
      EXPECT_GT(small.points[k].gas->pressure_mpa, small.points[k - 1].gas->pressure_mpa);
      EXPECT_LT(small.points[k].gas->volume_mm3, small.points[k - 1].gas->volume_mm3);
      record(fmt::format("excess_force_n_{}_{}mm",
                         describe(base.indenter).substr(0, 4),
                         held.points[k].depth_mm),
             large.points[k].force_n - held.points[k].force_n);
    }
    if (!std::holds_alternative<FlatPunch>(base.indenter)) continue;
    // Part II's onset on the sealed curve: located between the points, the states just before
    // and after it on either side, its force continuous there.
    ASSERT_TRUE(large.part_two_onset_depth_mm && large.part_two_onset_force_n);
    const double onset = *large.part_two_onset_depth_mm;
    EXPECT_GT(onset, 9.0);
    EXPECT_LE(onset, 12.0);
    const auto before = solve_at_depth(sealed(1e7, base), onset * (1.0 - 1e-5), Stage::Slip);
    const auto after = solve_at_depth(sealed(1e7, base), onset * (1.0 + 1e-5), Stage::Slip);
    ASSERT_TRUE(before.ok() && after.ok()) << before.message << after.message;
    EXPECT_EQ(before.configuration, Configuration::SlipWithoutPartTwo);
    EXPECT_EQ(after.configuration, Configuration::SlipWithPartTwo);
    EXPECT_NEAR(*large.part_two_onset_force_n, after.force_n, 1e-4 * after.force_n);
    record("sealed_part_two_onset_mm", onset);
    record("held_part_two_onset_mm", *held.part_two_onset_depth_mm);
  }
}

// Through any state the sealed curve is steeper than the held-pressure curve at that state's own
// pressure: dF/ddelta = dF/ddelta|_p + dF/dp dp/ddelta, the gas's share positive.  The slopes from
// the depths at F (1 -+ 1e-3), central differences (the depth frames differ by a constant).
TEST(SealedGas, StifferThanTheHeldPressureThroughTheSameState) {
  for (const Problem& base : {pressurised(), flat()}) {
    const Problem p = sealed(1e6, base);
    for (const double depth : {2.0, 10.0, 20.0}) {
      SCOPED_TRACE(fmt::format("{}, {} mm", describe(base.indenter), depth));
      const auto e = solve_at_depth(p, depth, Stage::Slip);
      ASSERT_TRUE(e.ok()) << e.message;
      Problem held = base;
      held.preload.pressure_mpa = e.gas->pressure_mpa;
      auto compliance = [&](const Problem& q) {
        const double df = 1e-3 * e.force_n;
        const auto lo = solve_at_force(q, e.force_n - df, Stage::Slip);
        const auto hi = solve_at_force(q, e.force_n + df, Stage::Slip);
        EXPECT_TRUE(lo.ok() && hi.ok()) << lo.message << hi.message;
        return (hi.depth_mm - lo.depth_mm) / (2.0 * df);
      };
      const double sealed_stiffness = 1.0 / compliance(p), held_stiffness = 1.0 / compliance(held);
      EXPECT_GT(sealed_stiffness, held_stiffness * (1.0 + 1e-3));
      record(fmt::format("stiffness_ratio_{}_{}mm", describe(base.indenter).substr(0, 4), depth),
             sealed_stiffness / held_stiffness);
    }
  }
}

// The puncture is a state on the sealed path: at the critical I1 and in the gas law, earlier in
// depth and at a larger force than at the held pressure; the curve ends there.
TEST(SealedGas, PunctureLiesOnTheSealedPath) {
  for (const Problem& base : {pressurised(), flat()}) {
    SCOPED_TRACE(describe(base.indenter));
    const Problem p = sealed(1e6, base);
    const auto held = predict_puncture(base);
    const auto burst = predict_puncture(p);
    ASSERT_TRUE(held.ok() && burst.ok()) << held.message << burst.message;
    ASSERT_TRUE(burst.state.gas.has_value());
    const double content = gas_content(p, {});
    const ChamberGas gas = *burst.state.gas;
    EXPECT_NEAR(
        (gas.pressure_mpa + kAtmosphereMpa) * (1e6 + gas.volume_mm3), content, 1e-11 * content);
    EXPECT_NEAR(burst.state.max_first_invariant, p.critical_i1, 1e-6 * p.critical_i1);
    EXPECT_NEAR(burst.state.depth_mm, burst.depth_mm, 1e-9 * burst.depth_mm);
    // The state at the puncture depth solved directly is the same.
    const auto at_depth = solve_at_depth(p, burst.depth_mm, Stage::Slip);
    ASSERT_TRUE(at_depth.ok()) << at_depth.message;
    EXPECT_NEAR(at_depth.force_n, burst.force_n, 1e-7 * burst.force_n);
    EXPECT_GT(gas.pressure_mpa, base.preload.pressure_mpa);
    EXPECT_LT(burst.depth_mm, held.depth_mm);
    record("puncture_force_n_" + describe(base.indenter).substr(0, 4), burst.force_n);
    record("puncture_depth_mm_" + describe(base.indenter).substr(0, 4), burst.depth_mm);
    record("held_puncture_force_n_" + describe(base.indenter).substr(0, 4), held.force_n);
    record("held_puncture_depth_mm_" + describe(base.indenter).substr(0, 4), held.depth_mm);
    record("puncture_pressure_mpa_" + describe(base.indenter).substr(0, 4), gas.pressure_mpa);
  }
}

// Sealed flat (no pressure before contact): the probe compresses the gas from atmospheric.
TEST(SealedGas, SealedFlatIsPressurisedByTheProbe) {
  Problem base = paper_problem(Gent{125.0}, 0.0);
  const Problem p = sealed(2e4, base);
  const auto held = solve_at_depth(base, 3.0, Stage::Slip);
  const auto e = solve_at_depth(p, 3.0, Stage::Slip);
  ASSERT_TRUE(held.ok() && e.ok()) << held.message << e.message;
  EXPECT_GT(e.gas->pressure_mpa, 0.0);
  EXPECT_LT(e.gas->volume_mm3, 0.0);  // the membrane is pushed below its plane
  EXPECT_NEAR((e.gas->pressure_mpa + kAtmosphereMpa) * (2e4 + e.gas->volume_mm3),
              kAtmosphereMpa * 2e4,
              1e-11 * kAtmosphereMpa * 2e4);
  EXPECT_GT(e.force_n, held.force_n);
}

// The energy to puncture over the chamber is the change of U plus the gas's and the
// atmosphere's energy (dPi/d(depth) = F, tested above), against the held pressure's, which
// integrates F along its path (Gauss-Legendre): as V0 grows the excess falls as 1 / V0, halving
// as V0 doubles (1e8, 2e8, 4e8 mm^3).  With friction it is the path's work (checked in
// sealed_path_work_test.cpp).
TEST(SealedGas, EnergyToPunctureIsTheChangeOfThePotential) {
  const Problem base = pressurised();
  SolverOptions with_energy;
  with_energy.energy_to_puncture = true;
  const auto held = predict_puncture(base, with_energy);
  ASSERT_TRUE(held.ok() && held.energy_to_puncture_mj) << held.message;
  std::vector<double> excess;
  for (const double v0 : {1e8, 2e8, 4e8}) {
    const auto burst = predict_puncture(sealed(v0, base), with_energy);
    ASSERT_TRUE(burst.ok() && burst.energy_to_puncture_mj) << burst.message;
    excess.push_back(*burst.energy_to_puncture_mj - *held.energy_to_puncture_mj);
  }
  record("energy_excess_1e8_mj", excess[0]);
  record("energy_excess_ratio_1", excess[0] / excess[1]);
  record("energy_excess_ratio_2", excess[1] / excess[2]);
  // Measured 2.072 and 2.039: their distance from 2 halves too (the next order, 1 / V0^2), which
  // a constant error of either energy would not do.
  const double r1 = excess[0] / excess[1], r2 = excess[1] / excess[2];
  EXPECT_NEAR(r1, 2.0, 0.1);
  EXPECT_NEAR(r2, 2.0, 0.05);
  EXPECT_NEAR((r2 - 2.0) / (r1 - 2.0), 0.5, 0.1);
  const auto rough =
      predict_puncture(sealed(1e7, pressurised(kPressureMpa, 0.18, FlatPunch{2.0})), with_energy);
  ASSERT_TRUE(rough.ok()) << rough.message;
  // With friction it is the force integrated along the sealed path (sealed_path_work_test.cpp).
  ASSERT_TRUE(rough.energy_to_puncture_mj) << rough.message;
  EXPECT_GT(*rough.energy_to_puncture_mj, 0.0);
}

TEST(SealedGas, InvalidChambersAreRefusedNamingTheParameter) {
  for (const double v0 : {0.0, -1.0, std::nan("")}) {
    const auto errors = validation_errors(sealed(v0));
    ASSERT_EQ(errors.size(), 1u) << v0;
    EXPECT_EQ(errors.front().parameter, "preload.gas_volume_mm3");
  }
  Problem p = sealed(1e4);
  p.preload.atmospheric_pressure_mpa = 0.0;
  const auto errors = validation_errors(p);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors.front().parameter, "preload.atmospheric_pressure_mpa");
  Problem stuck = sealed(1e4, paper_problem(Gent{125.0}, 0.0));
  stuck.stick = {StickRule::Always, 0.0};
  ASSERT_EQ(validation_errors(stuck).size(), 1u);
  EXPECT_EQ(validation_errors(stuck).front().parameter, "stick.rule");
  EXPECT_THROW(solve_at_depth(sealed(-5.0), 1.0, Stage::Slip), std::invalid_argument);
}

}  // namespace
}  // namespace puncture::test
