// The probe's work along a sealed chamber's path (docs/model.md §17.1, "Energy"): with friction
// the energy to puncture over the chamber is the force integrated along the sealed path
// (indentation/sealed_path_work.hpp).  Frictionless, the same quadrature equals the change of the
// potential with the gas's isothermal free energy (an independent route: two states' fields);
// with friction it exceeds that change by what the friction dissipates, converges with its
// panels, and tends to the frictionless work at first order in mu'.
#include "indentation/sealed_path_work.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "indentation/sealed_gas.hpp"
#include "pressurised_support.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

Problem sealed_path(double gas_volume_mm3, double friction, Indenter indenter) {
  Problem p = pressurised(kPressureMpa, friction, indenter);
  p.preload.gas_volume_mm3 = gas_volume_mm3;
  return p;
}

double path_work_mj(const Problem& p, double depth_mm, int panels) {
  const SolverOptions options;
  const auto chamber = detail::sealed_chamber(p, options);
  const auto work = detail::sealed_path_work(p, chamber, depth_mm, options, panels);
  EXPECT_TRUE(work.work_mj.has_value()) << work.why;
  return work.work_mj.value_or(0.0);
}

// Frictionless the path's work to the puncture is the energy to puncture the solver computes
// from the potential's change (U and V of two states, 2000-sample fields).
TEST(SealedPathWork, FrictionlessItIsTheChangeOfThePotential) {
  const Problem p = sealed_path(1e6, 0.0, SphereTipped{2.0});
  SolverOptions with_energy;
  with_energy.energy_to_puncture = true;
  const auto puncture = predict_puncture(p, with_energy);
  ASSERT_TRUE(puncture.ok() && puncture.energy_to_puncture_mj) << puncture.message;
  const double work = path_work_mj(p, puncture.depth_mm, 12);
  std::printf("path work %.10g mJ, potential change %.10g mJ: %.2e\n",
              work,
              *puncture.energy_to_puncture_mj,
              work / *puncture.energy_to_puncture_mj - 1.0);
  EXPECT_NEAR(work, *puncture.energy_to_puncture_mj, 1e-6 * work);
  record("relative_difference", std::abs(work / *puncture.energy_to_puncture_mj - 1.0));
}

// With friction (mu' = 0.18, flat punch, 1e7 mm^3) the prediction carries the path's work, the
// quadrature converged (6 against 12 panels per piece), and above the change of the potential
// from the dome to the puncture state (the friction dissipates).
TEST(SealedPathWork, WithFrictionTheEnergyToPunctureIsThePathsWork) {
  const Problem p = sealed_path(1e7, 0.18, FlatPunch{2.0});
  SolverOptions with_energy;
  with_energy.energy_to_puncture = true;
  const auto puncture = predict_puncture(p, with_energy);
  ASSERT_TRUE(puncture.ok()) << puncture.message;
  ASSERT_TRUE(puncture.energy_to_puncture_mj) << puncture.message;
  const double coarse = path_work_mj(p, puncture.depth_mm, 6);
  std::printf("energy %.10g mJ, 6 panels %.10g: %.2e\n",
              *puncture.energy_to_puncture_mj,
              coarse,
              coarse / *puncture.energy_to_puncture_mj - 1.0);
  EXPECT_NEAR(coarse, *puncture.energy_to_puncture_mj, 1e-6 * coarse);
  // The potential's change to the same state: U, V from the fields of the states at zero depth
  // and at the puncture depth.
  const auto dome = solve_at_depth(p, 0.0, Stage::Slip, sampled(2000));
  const auto at = solve_at_depth(p, puncture.depth_mm, Stage::Slip, sampled(2000));
  ASSERT_TRUE(dome.ok() && at.ok()) << dome.message << at.message;
  Problem membrane = p;
  membrane.preload.pressure_mpa = 0.0;
  const double du = potential(membrane, at).value - potential(membrane, dome).value;
  const double vs = dome.gas->volume_mm3, dv = at.gas->volume_mm3 - vs;
  const double gas = 1e7 + vs, x = dv / gas;
  const double change =
      du - kPressureMpa * dv -
      (kPressureMpa + p.preload.atmospheric_pressure_mpa) * gas * (std::log1p(x) - x);
  std::printf("work %.6g mJ, change of Pi %.6g mJ: dissipated %.4g %%\n",
              *puncture.energy_to_puncture_mj,
              change,
              100.0 * (*puncture.energy_to_puncture_mj / change - 1.0));
  EXPECT_GT(*puncture.energy_to_puncture_mj, change * (1.0 + 1e-3));
  record("dissipated_fraction", *puncture.energy_to_puncture_mj / change - 1.0);
}

// mu' -> 0: the path's work to 10 mm tends to the frictionless one at first order (the
// difference shrinks tenfold with mu').
TEST(SealedPathWork, VanishingFrictionTendsToTheFrictionlessWork) {
  const double frictionless = path_work_mj(sealed_path(1e6, 0.0, FlatPunch{2.0}), 10.0, 4);
  std::vector<double> excess;
  for (const double mu : {1e-2, 1e-3, 1e-4})
    excess.push_back(path_work_mj(sealed_path(1e6, mu, FlatPunch{2.0}), 10.0, 4) - frictionless);
  std::printf("excess %.4e %.4e %.4e of %.6g mJ\n", excess[0], excess[1], excess[2], frictionless);
  EXPECT_NEAR(excess[0] / excess[1], 10.0, 0.5);
  EXPECT_NEAR(excess[1] / excess[2], 10.0, 0.5);
  record("excess_ratio_0", excess[0] / excess[1]);
  record("excess_ratio_1", excess[1] / excess[2]);
}

}  // namespace
}  // namespace puncture::test
