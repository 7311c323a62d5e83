#include "puncture/material.hpp"

#include <fmt/format.h>

#include "mechanics/inverse_stretch.hpp"

namespace puncture {

std::string law_name(const MaterialLaw& law) {
  return std::visit([](const auto& l) { return std::string(l.name()); }, law);
}

std::string describe(const MaterialLaw& law) {
  const std::string params = std::visit(
      [](const auto& l) -> std::string {
        using L = std::decay_t<decltype(l)>;
        if constexpr (std::is_same_v<L, Gent>) return fmt::format(" (J_lim = {:g})", l.j_lim);
        if constexpr (std::is_same_v<L, MooneyRivlin>)
          return fmt::format(" (alpha = {:g})", l.alpha);
        if constexpr (std::is_same_v<L, Yeoh>)
          return fmt::format(" (C20/G = {:g}, C30/G = {:g})", l.c2, l.c3);
        return "";
      },
      law);
  return law_name(law) + params;
}

std::string describe(const Material& material) {
  const double g = material.shear_modulus_mpa;
  std::string law = describe(material.law);
  if (const auto* yeoh = std::get_if<Yeoh>(&material.law))  // as users give it: G = 2 C10
    law = fmt::format("{} (C10 = {:g}, C20 = {:g}, C30 = {:g} MPa)",
                      law_name(material.law),
                      0.5 * g,
                      yeoh->c2 * g,
                      yeoh->c3 * g);
  return fmt::format("{}, G = {:g} MPa", law, g);
}

double locking_first_invariant(const MaterialLaw& law) {
  return std::visit([](const auto& l) { return l.locking_i1(); }, law);
}

MembraneStress membrane_stress(const MaterialLaw& law, double l1, double l2) {
  return std::visit([&](const auto& l) { return membrane_stress(l, l1, l2); }, law);
}

std::optional<double> radial_stretch_for_stress(const MaterialLaw& law, double s1, double l2) {
  return std::visit([&](const auto& l) { return detail::invert_radial_stress(l, s1, l2); }, law);
}

double equibiaxial_stress(const MaterialLaw& law, double l) {
  return membrane_stress(law, l, l).s1;
}

double uniaxial_stress(const MaterialLaw& law, double l) {
  return membrane_stress(law, l, 1.0 / std::sqrt(l)).s1;
}

}  // namespace puncture
