// A sealed chamber beyond a hemisphere (docs/model.md §17.1, "Beyond a hemisphere"): the gas
// sealed at 0.85 kPa, where the paper's membrane overhangs its clamp, below its inflation limit
// point (0.935 kPa).  The state before contact is the inflation solver's overhanging dome, every
// state satisfies the gas law, dPi/d(depth) = F with the gas's isothermal free energy, a large
// chamber tends to the held pressure as 1/V0, and a gas compressed past the limit point is
// outside the model, never another branch's state.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "pressurised_support.hpp"
#include "puncture/inflation.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

constexpr double kSealedOverhangMpa = 8.5e-4;  // the first state overhangs (slope past pi/2)

Problem sealed_overhang(double gas_volume_mm3, Indenter indenter) {
  Problem p = pressurised(kSealedOverhangMpa, 0.0, indenter);
  p.preload.gas_volume_mm3 = gas_volume_mm3;
  return p;
}

// Pi = U - P (V - V_s) - C (ln(1 + x) - x), x = (V - V_s) / (V0 + V_s), C = (P + p_atm)(V0 + V_s):
// the membrane's energy plus the gas's and the atmosphere's, the p_atm dV terms cancelled (as
// sealed_gas_test.cpp); U from 2000-sample fields.
double overhang_sealed_potential(const Problem& p, const Equilibrium& e, double sealed_volume_mm3) {
  Problem membrane = p;
  membrane.preload.pressure_mpa = 0.0;  // potential(): U alone
  const double u = potential(membrane, e).value;
  const double v0 = *p.preload.gas_volume_mm3, dv = e.gas->volume_mm3 - sealed_volume_mm3;
  const double big_p = p.preload.pressure_mpa, p_atm = p.preload.atmospheric_pressure_mpa;
  const double x = dv / (v0 + sealed_volume_mm3);
  return u - big_p * dv - (big_p + p_atm) * (v0 + sealed_volume_mm3) * (std::log1p(x) - x);
}

// Before contact the sealed state is the inflation solver's first state at the sealing pressure,
// overhanging its clamp, at exactly that pressure.
TEST(SealedOverhang, BeforeContactTheStateIsTheInflationSolversOverhangingDome) {
  const Problem p = sealed_overhang(1e7, FlatPunch{2.0});
  const auto at = inflate_at_pressure(inflation_problem(p), kSealedOverhangMpa);
  ASSERT_TRUE(at.ok()) << at.message;
  const InflationState& dome = at.states.front();
  ASSERT_GT(dome.clamp_slope_rad, std::numbers::pi / 2);  // it overhangs
  const auto e = solve_at_depth(p, 0.0, Stage::Slip, sampled(2000));
  ASSERT_TRUE(e.ok()) << e.message;
  ASSERT_TRUE(e.gas.has_value());
  EXPECT_EQ(e.force_n, 0.0);
  EXPECT_EQ(e.gas->pressure_mpa, kSealedOverhangMpa);
  EXPECT_NEAR(e.part_three_stretch, dome.pole_stretch, 1e-12 * dome.pole_stretch);
  EXPECT_NEAR(e.fields.deflection_mm.back(), dome.pole_height_mm, 1e-9 * dome.pole_height_mm);
  EXPECT_NEAR(e.gas->volume_mm3, dome.volume_mm3, 1e-9 * dome.volume_mm3);
  record("relative_volume_difference", std::abs(e.gas->volume_mm3 / dome.volume_mm3 - 1.0));
}

// Every state satisfies the gas law with its own volume (the pressure rising with the depth),
// and dPi/d(depth) = F: central differences at h and h/2 (h = depth / 100), extrapolated.
TEST(SealedOverhang, StatesSatisfyTheGasLawAndTheEnergyBalance) {
  const SolverOptions fine = sampled(2000);
  for (const auto& [p, depth] : {std::pair{sealed_overhang(1e7, FlatPunch{2.0}), 5.0},
                                 std::pair{sealed_overhang(1e7, SphereTipped{2.0}), 8.0}}) {
    SCOPED_TRACE(fmt::format("{}, {} mm", describe(p.indenter), depth));
    const auto dome = solve_at_depth(p, 0.0, Stage::Slip, fine);
    ASSERT_TRUE(dome.ok()) << dome.message;
    const double vs = dome.gas->volume_mm3;
    const double content = (kSealedOverhangMpa + p.preload.atmospheric_pressure_mpa) * (1e7 + vs);
    auto pi_at = [&](double d) {
      const auto e = solve_at_depth(p, d, Stage::Slip, fine);
      EXPECT_TRUE(e.ok()) << e.message;
      if (!e.ok()) return 0.0;
      const double law =
          (e.gas->pressure_mpa + p.preload.atmospheric_pressure_mpa) * (1e7 + e.gas->volume_mm3);
      EXPECT_NEAR(law, content, 1e-11 * content) << d << " mm";
      EXPECT_GT(e.gas->pressure_mpa, kSealedOverhangMpa);
      return overhang_sealed_potential(p, e, vs);
    };
    const auto e = solve_at_depth(p, depth, Stage::Slip, fine);
    ASSERT_TRUE(e.ok()) << e.message;
    const double h = 0.01 * depth;
    const double d1 = (pi_at(depth + h) - pi_at(depth - h)) / (2.0 * h);
    const double d2 = (pi_at(depth + h / 2) - pi_at(depth - h / 2)) / h;
    const double slope = (4.0 * d2 - d1) / 3.0;
    std::printf("dPi/ddelta %s: %.3e\n", describe(p.indenter).c_str(), slope / e.force_n - 1.0);
    EXPECT_NEAR(slope, e.force_n, 1e-6 * e.force_n);
    record(fmt::format("relative_difference_{}", describe(p.indenter).substr(0, 4)),
           std::abs(slope / e.force_n - 1.0));
  }
}

// V0 -> infinity: the force's excess over the held pressure's at the same depth halves as V0
// doubles (1e8, 2e8, 4e8 mm^3), as below a hemisphere.
TEST(SealedOverhang, LargeChamberTendsToTheHeldPressureAsOneOverV0) {
  const Problem base = pressurised(kSealedOverhangMpa, 0.0, FlatPunch{2.0});
  const auto held = solve_at_depth(base, 10.0, Stage::Slip);
  ASSERT_TRUE(held.ok()) << held.message;
  std::vector<double> excess;
  for (const double v0 : {1e8, 2e8, 4e8}) {
    const auto e = solve_at_depth(sealed_overhang(v0, FlatPunch{2.0}), 10.0, Stage::Slip);
    ASSERT_TRUE(e.ok()) << e.message;
    excess.push_back(e.force_n - held.force_n);
    EXPECT_GT(excess.back(), 0.0);
  }
  const double r0 = excess[0] / excess[1], r1 = excess[1] / excess[2];
  std::printf(
      "ratios %.4f %.4f, excess at 1e8 %.4e N of %.5f N\n", r0, r1, excess[0], held.force_n);
  EXPECT_NEAR(r0, 2.0, 0.05);
  EXPECT_NEAR(r1, 2.0, 0.025);
  EXPECT_NEAR((r0 - 2.0) / (r1 - 2.0), 2.0, 0.3);
  record("force_excess_ratio_0", r0);
  record("force_excess_ratio_1", r1);
}

// A small chamber: the probe compresses the gas past the inflation limit point, where the first
// state at the pressure is a balloon of another branch: OutsideModel naming the limit point,
// never that branch's numbers.
TEST(SealedOverhang, GasCompressedPastTheLimitPointIsOutsideTheModel) {
  const auto e = solve_at_depth(sealed_overhang(2e4, FlatPunch{2.0}), 20.0, Stage::Slip);
  EXPECT_EQ(e.status, Status::OutsideModel) << e.message;
  EXPECT_NE(e.message.find("past its inflation limit point"), std::string::npos) << e.message;
}

}  // namespace
}  // namespace puncture::test
