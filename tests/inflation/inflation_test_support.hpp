#pragma once
// Shared helpers of the inflation tests: the membrane with a chosen law, the laws every
// identity is checked for, and the energy density.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "puncture/inflation.hpp"

namespace puncture::test {

// The paper's membrane (A = 25 mm, H = 0.2 mm, G = 0.06 MPa) with the given law.
// A Gent law that locks below the paper's critical I1 gets a critical I1 of 3 + 0.8 J_lim.
inline InflationProblem membrane(MaterialLaw law = Gent{125.0}) {
  InflationProblem p;
  p.material.law = law;
  if (const auto* gent = std::get_if<Gent>(&law); gent && p.critical_i1 >= 3.0 + gent->j_lim)
    p.critical_i1 = 3.0 + 0.8 * gent->j_lim;
  return p;
}

// The laws the identities are checked for, with a readable name for the test's output.
inline std::vector<std::pair<std::string, MaterialLaw>> laws() {
  return {{"gent", Gent{125.0}},
          {"gent-stiff", Gent{20.0}},
          {"neo-hookean", NeoHookean{}},
          {"mooney-rivlin", MooneyRivlin{0.1}},
          {"yeoh", Yeoh{0.05, 0.001}},
          // Ogden's (1972) three-term fit to Treloar, as mu_p / G
          {"ogden", std::get<Ogden>(ogden_material({0.63, 0.0012, -0.01}, {1.3, 5.0, -2.0}).law)},
          {"arruda-boyce", ArrudaBoyce{50.0}},
          {"gent-gent", GentGent{125.0, 0.2}}};
}

// Strain energy per unit reference volume [MPa = mJ/mm^3] at stretches (l1, l2).
inline double energy_density_mpa(const InflationProblem& p, double l1, double l2) {
  return strain_energy_density(p.material.law, l1, l2) * p.material.shear_modulus_mpa;
}

inline bool all_finite(const std::vector<double>& v) {
  for (const double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

// Records a measured quantity (an error, a margin) in the test's XML report (--gtest_output=xml).
inline void record(const std::string& key, double value) {
  ::testing::Test::RecordProperty(key, fmt::format("{:.3e}", value));
}

// The state at pole stretch l0, which must converge.
inline InflationState solved(const InflationProblem& p, double l0, SolverOptions o = {}) {
  auto s = inflate_at_pole_stretch(p, l0, o);
  EXPECT_TRUE(s.ok()) << "pole stretch " << l0 << ": " << s.message;
  return s;
}

}  // namespace puncture::test
