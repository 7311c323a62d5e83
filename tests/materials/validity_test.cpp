// The new laws' validity conditions (validation_errors and ogden_material): each refused input
// names its attribute, and the conditions are the ones the solver needs (checked on the laws'
// own stresses where a condition is sufficient for them).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mechanics/falling_stress.hpp"
#include "puncture/material.hpp"
#include "puncture/problem.hpp"

namespace puncture {
namespace {

std::vector<std::string> parameters_of(const MaterialLaw& law) {
  Problem p;
  p.material.law = law;
  std::vector<std::string> out;
  for (const auto& e : validation_errors(p)) out.push_back(e.parameter);
  return out;
}

using Names = std::vector<std::string>;

TEST(OgdenValidity, ListsOfDifferentLengthsOrSizesAreRefused) {
  EXPECT_EQ(parameters_of(Ogden{{1.0, 0.5}, {2.0}}), Names{"material.law.alpha"});
  EXPECT_EQ(parameters_of(Ogden{{}, {}}), Names{"material.law.mu"});
  EXPECT_EQ(parameters_of(Ogden{{0.5, 0.5, 0.5, 0.5}, {1.0, 1.0, 1.0, 1.0}}),
            Names{"material.law.mu"});
  EXPECT_THROW(ogden_material({0.1, 0.2}, {2.0}), InvalidInput);
  EXPECT_THROW(ogden_material({}, {}), InvalidInput);
  try {
    ogden_material({0.1}, {2.0, 3.0});
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.errors().front().parameter, "alpha");
  }
}

TEST(OgdenValidity, TheConsistencyConditionAndEachTermsSignAreRequired) {
  // sum mu_p alpha_p <= 0: no positive shear modulus
  EXPECT_THROW(ogden_material({0.1, 0.1}, {2.0, -2.0}), InvalidInput);
  EXPECT_THROW(ogden_material({-0.1}, {2.0}), InvalidInput);
  // G > 0 but one term with mu_p alpha_p < 0 (a softening term)
  const Material softening = ogden_material({0.2, 0.01}, {2.0, -2.0});
  EXPECT_EQ(parameters_of(softening.law), Names{"material.law.mu"});
  // |alpha_p| < 1
  EXPECT_EQ(parameters_of(ogden_material({0.1, 0.1}, {2.0, 0.5}).law), Names{"material.law.alpha"});
  // not normalised: sum mu_p alpha_p / G = 2.2
  EXPECT_EQ(parameters_of(Ogden{{1.1}, {2.0}}), Names{"material.law.mu"});
  // Ogden's Treloar fit is valid
  EXPECT_TRUE(parameters_of(ogden_material({0.63, 0.0012, -0.01}, {1.3, 5.0, -2.0}).law).empty());
}

// Why |alpha_p| >= 1: a term with |alpha| < 1 makes s1 fall at large stretch.  With the
// conditions (Treloar's fit) s1 grows everywhere on a wide grid.
TEST(OgdenValidity, TheRefusedTermsBreakWhatTheSolverNeeds) {
  const Ogden small_exponent{{4.0}, {0.5}};  // mu alpha = 2
  EXPECT_LT(membrane_stress(small_exponent, 20.0, 1.0).ds1_dl1, 0.0);
  const Ogden valid = std::get<Ogden>(ogden_material({0.63, 0.0012, -0.01}, {1.3, 5.0, -2.0}).law);
  for (double l1 = 0.5; l1 < 30.0; l1 *= 1.1)
    for (double l2 = 0.5; l2 < 30.0; l2 *= 1.1)
      EXPECT_GT(membrane_stress(valid, l1, l2).ds1_dl1, 0.0) << l1 << " " << l2;
}

TEST(ArrudaBoyceValidity, NMustExceedOne) {
  EXPECT_EQ(parameters_of(ArrudaBoyce{1.0}), (Names{"material.law.n", "critical_i1"}));
  EXPECT_EQ(parameters_of(ArrudaBoyce{std::nan("")}), Names{"material.law.n"});
  EXPECT_TRUE(parameters_of(ArrudaBoyce{40.0}).empty());
  // The critical I1 must be below its locking, 3 N
  Problem p;
  p.material.law = ArrudaBoyce{30.0};  // locks at 90 < 95.2
  const auto errors = validation_errors(p);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].parameter, "critical_i1");
  EXPECT_NE(errors[0].message.find("Arruda-Boyce locking limit 3 N = 90"), std::string::npos)
      << errors[0].message;
}

// Gent-Gent: beta in [0, 1), and small enough that s1 grows with lambda1 below locking.  For
// J_lim = 125 the scan's bound lies near beta = 0.40 (docs/model.md): 0.3 passes, 0.5 does not.
TEST(GentGentValidity, TheSecondInvariantsShareIsBounded) {
  EXPECT_EQ(parameters_of(GentGent{125.0, -0.1}), Names{"material.law.beta"});
  EXPECT_EQ(parameters_of(GentGent{125.0, 1.0}), Names{"material.law.beta"});
  EXPECT_EQ(parameters_of(GentGent{0.0, 0.1}), (Names{"material.law.j_lim", "critical_i1"}));
  EXPECT_TRUE(parameters_of(GentGent{125.0, 0.3}).empty());
  EXPECT_EQ(parameters_of(GentGent{125.0, 0.5}), Names{"material.law.beta"});
  // where the scan finds s1 falling, it does
  const auto at = detail::where_radial_stress_falls(GentGent{125.0, 0.5});
  ASSERT_TRUE(at.has_value());
  EXPECT_LE(membrane_stress(GentGent{125.0, 0.5}, at->first, at->second).ds1_dl1, 0.0);
  // and the laws proven monotone pass the same scan
  EXPECT_FALSE(detail::where_radial_stress_falls(Gent{125.0}).has_value());
  EXPECT_FALSE(detail::where_radial_stress_falls(ArrudaBoyce{30.0}).has_value());
}

}  // namespace
}  // namespace puncture
