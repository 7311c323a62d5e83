// The small-strain limit: as the pressure goes to zero the large-strain solver must approach
// the Föppl-Hencky membrane (hencky_membrane.hpp, an independent solver) with nu = 1/2 and
// E = 3 G, the incompressible rubber's small-strain constants.
#include <cmath>

#include "hencky_membrane.hpp"
#include "inflation_test_support.hpp"

namespace puncture {
namespace {

using test::membrane;
using verification::hencky_constant;

TEST(HenckyMembrane, IndependentSolverGivesHenckysConstant) {
  // Hencky's exact solution for nu = 0.3: w0 = 0.653 A (q A / (E h))^(1/3) (Hencky 1915,
  // corrected by Chien 1948; Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, §
  // 103, quote 0.653 against 0.662 from their energy approximation).  Three digits given.
  EXPECT_NEAR(hencky_constant(0.3), 0.653, 5e-4);
  // A softer Poisson effect: the incompressible membrane deflects less at the same E.
  EXPECT_LT(hencky_constant(0.5), hencky_constant(0.3));
  test::record("hencky_constant_nu_0.5", hencky_constant(0.5));
}

// K = (w0 / A) / (p A / (E H))^(1/3) of the full solver at pole stretch l0.
double full_solver_constant(const InflationProblem& p, double l0) {
  const auto s = test::solved(p, l0);
  const double young = 3.0 * p.material.shear_modulus_mpa;
  return (s.pole_height_mm / p.clamp_radius_mm) /
         std::cbrt(s.pressure_mpa * p.clamp_radius_mm / (young * p.thickness_mm));
}

TEST(HenckyMembrane, FullSolverApproachesHenckyAsPressureVanishes) {
  const double k = hencky_constant(0.5);
  for (const auto& [name, law] : test::laws()) {
    SCOPED_TRACE(name);
    const auto p = membrane(law);
    // The relative deviation is the next order of the expansion, ~ strain ~ l0 - 1: a
    // hundredfold smaller pole strain must shrink it about a hundredfold (at least 30x here,
    // allowing for the next order), and at a pole strain of 1e-5 it must be ~1e-5.
    const double d_large = std::abs(full_solver_constant(p, 1.0 + 1e-3) / k - 1.0);
    const double d_small = std::abs(full_solver_constant(p, 1.0 + 1e-5) / k - 1.0);
    EXPECT_LT(d_small, 1e-4);
    EXPECT_LT(d_small, d_large / 30.0);
    EXPECT_GT(d_large, 1e-5);  // the finite-strain correction is visible at 1e-3 strain
    test::record(name + "_hencky_deviation_1e-3", d_large);
    test::record(name + "_hencky_deviation_1e-5", d_small);
  }
}

}  // namespace
}  // namespace puncture
