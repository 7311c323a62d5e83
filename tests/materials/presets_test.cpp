// The named materials: each one's stresses at a few stretches against the published law
// evaluated here by hand from the source's own numbers and units, and each one a valid problem.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "puncture/material_presets.hpp"
#include "puncture/problem.hpp"

namespace puncture {
namespace {

TEST(MaterialPresets, SeedPaperSiliconeIsGentWithItsModulusAndJLim) {
  // Liu et al. 2018 §4.1: Gent, G = 0.06 MPa, J_lim = 125.  Uniaxial nominal stress
  // P = G (l - l^-2) / (1 - (l^2 + 2/l - 3) / J_lim); equibiaxial P = G (l - l^-5) / (1 - (2 l^2
  // + l^-4 - 3) / J_lim).
  const auto& m = material_preset("liu2018-silicone").material;
  for (const double l : {1.5, 3.0, 6.0}) {
    const double uni = 0.06 * (l - 1.0 / (l * l)) / (1.0 - (l * l + 2.0 / l - 3.0) / 125.0);
    EXPECT_NEAR(m.shear_modulus_mpa * uniaxial_stress(m.law, l), uni, 1e-13 * uni) << l;
  }
  for (const double l : {1.5, 3.0, 5.0}) {
    const double eq =
        0.06 * (l - std::pow(l, -5.0)) / (1.0 - (2.0 * l * l + std::pow(l, -4.0) - 3.0) / 125.0);
    EXPECT_NEAR(m.shear_modulus_mpa * equibiaxial_stress(m.law, l), eq, 1e-13 * eq) << l;
  }
}

TEST(MaterialPresets, OgdenTreloarIsOgdensThreeTermsInMpa) {
  // Ogden 1972: mu = 6.3, 0.012, -0.1 kgf/cm^2, alpha = 1.3, 5.0, -2.0; 1 kgf/cm^2 =
  // 0.0980665 MPa.  Uniaxial P = sum mu_p (l^(alpha_p - 1) - l^(-alpha_p/2 - 1)), equibiaxial
  // P = sum mu_p (l^(alpha_p - 1) - l^(-2 alpha_p - 1)).
  const auto& m = material_preset("ogden-1972-treloar").material;
  const double mu[] = {6.3 * 0.0980665, 0.012 * 0.0980665, -0.1 * 0.0980665};
  const double alpha[] = {1.3, 5.0, -2.0};
  // G = sum mu_p alpha_p / 2 = (8.19 + 0.06 + 0.2) / 2 kgf/cm^2 = 4.225 kgf/cm^2.
  EXPECT_NEAR(m.shear_modulus_mpa, 4.225 * 0.0980665, 1e-15);
  for (const double l : {1.2, 3.0585, 7.0}) {
    double uni = 0.0, eq = 0.0;
    for (int p = 0; p < 3; ++p) {
      uni += mu[p] * (std::pow(l, alpha[p] - 1.0) - std::pow(l, -alpha[p] / 2.0 - 1.0));
      eq += mu[p] * (std::pow(l, alpha[p] - 1.0) - std::pow(l, -2.0 * alpha[p] - 1.0));
    }
    EXPECT_NEAR(m.shear_modulus_mpa * uniaxial_stress(m.law, l), uni, 1e-13 * uni) << l;
    EXPECT_NEAR(m.shear_modulus_mpa * equibiaxial_stress(m.law, l), eq, 1e-13 * eq) << l;
  }
  // At Treloar's stretch 3.0585, by hand: 6.3 (1.39847 - 0.15809) + 0.012 (87.505 - 0.0200)
  // + 0.1 (1 - 0.03495) = 8.9607 kgf/cm^2 = 0.87874 MPa (the data: 0.8409 MPa, 4.5 % lower).
  EXPECT_NEAR(m.shear_modulus_mpa * uniaxial_stress(m.law, 3.0585), 0.87874, 2e-5);
}

TEST(MaterialPresets, EveryPresetIsAValidProblemWithASource) {
  std::set<std::string> names;
  for (const auto& p : material_presets()) {
    EXPECT_TRUE(names.insert(p.name).second) << p.name;
    EXPECT_FALSE(p.source.empty()) << p.name;
    EXPECT_NE(p.source.find("doi:"), std::string::npos) << p.name;
    Problem problem;
    problem.material = p.material;
    problem.critical_i1 = std::min(30.0, locking_first_invariant(p.material.law) - 1.0);
    EXPECT_TRUE(validation_errors(problem).empty()) << p.name;
  }
  try {
    material_preset("rubber");
    FAIL() << "an unknown preset was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.errors().front().parameter, "preset");
    EXPECT_NE(std::string(e.what()).find("ogden-1972-treloar"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace puncture
