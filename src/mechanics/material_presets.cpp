#include "puncture/material_presets.hpp"

#include <fmt/format.h>

#include "puncture/outcome.hpp"

namespace puncture {

namespace {

// 1 kgf/cm^2 in MPa, exactly (standard gravity 9.80665 m/s^2): Treloar's and Ogden's unit.
constexpr double kMpaPerKgfPerCm2 = 0.0980665;

std::vector<MaterialPreset> make_presets() {
  std::vector<MaterialPreset> presets;
  presets.push_back({"liu2018-silicone",
                     "the seed paper's silicone: gent, G = 0.06 MPa, J_lim = 125",
                     "Liu et al., J. Mech. Phys. Solids 2018, doi:10.1016/j.jmps.2018.01.002, "
                     "section 4.1 and Fig. 11 (the library's default material)",
                     Material{0.06, Gent{125.0}}});
  // Ogden's three terms in kgf/cm^2: mu = 6.3, 0.012, -0.1; alpha = 1.3, 5.0, -2.0.
  presets.push_back(
      {"ogden-1972-treloar",
       "Ogden's 3-term fit to Treloar's natural rubber (G = 0.414 MPa)",
       "Ogden, Proc. R. Soc. Lond. A 326 (1972) 565-584, doi:10.1098/rspa.1972.0026, the "
       "three-term fit to Treloar's (1944) data",
       ogden_material({6.3 * kMpaPerKgfPerCm2, 0.012 * kMpaPerKgfPerCm2, -0.1 * kMpaPerKgfPerCm2},
                      {1.3, 5.0, -2.0})});
  return presets;
}

}  // namespace

const std::vector<MaterialPreset>& material_presets() {
  static const std::vector<MaterialPreset> presets = make_presets();
  return presets;
}

const MaterialPreset& material_preset(const std::string& name) {
  std::string names;
  for (const auto& p : material_presets()) {
    if (p.name == name) return p;
    names += (names.empty() ? "" : ", ") + p.name;
  }
  throw InvalidInput("preset",
                     fmt::format("unknown material preset '{}'; the presets are {}", name, names));
}

}  // namespace puncture
