#include "puncture/material.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <vector>

#include "mechanics/inverse_stretch.hpp"
#include "puncture/outcome.hpp"

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
        if constexpr (std::is_same_v<L, Ogden>)
          return fmt::format(
              " (mu/G = {:g}; alpha = {:g})", fmt::join(l.mu, ", "), fmt::join(l.alpha, ", "));
        if constexpr (std::is_same_v<L, ArrudaBoyce>)
          return fmt::format(" (N = {:g}, chain locking stretch {:g})", l.n, l.chain_stretch());
        if constexpr (std::is_same_v<L, GentGent>)
          return fmt::format(" (J_lim = {:g}, beta = {:g})", l.j_lim, l.beta);
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
  if (const auto* ogden = std::get_if<Ogden>(&material.law)) {  // mu_p = (mu_p / G) G
    std::vector<double> mu_mpa;
    for (const double m : ogden->mu) mu_mpa.push_back(m * g);
    law = fmt::format("{} (mu = {:g} MPa; alpha = {:g})",
                      law_name(material.law),
                      fmt::join(mu_mpa, ", "),
                      fmt::join(ogden->alpha, ", "));
  }
  return fmt::format("{}, G = {:g} MPa", law, g);
}

Material ogden_material(const std::vector<double>& mu_mpa, const std::vector<double>& alpha) {
  if (mu_mpa.size() != alpha.size())
    throw InvalidInput("alpha",
                       fmt::format("Ogden needs one exponent alpha_p per coefficient mu_p: got {} "
                                   "mu and {} alpha",
                                   mu_mpa.size(),
                                   alpha.size()));
  if (mu_mpa.empty() || mu_mpa.size() > 3)
    throw InvalidInput(
        "mu_mpa", fmt::format("Ogden takes 1 to 3 terms (mu_p, alpha_p), got {}", mu_mpa.size()));
  double twice_g = 0.0;
  for (std::size_t p = 0; p < mu_mpa.size(); ++p) twice_g += mu_mpa[p] * alpha[p];
  if (!std::isfinite(twice_g) || !(twice_g > 0.0))
    throw InvalidInput("mu_mpa",
                       fmt::format("Ogden's shear modulus G = sum mu_p alpha_p / 2 must be a "
                                   "finite number > 0 MPa (the consistency condition), got {}",
                                   0.5 * twice_g));
  Material m;
  m.shear_modulus_mpa = 0.5 * twice_g;
  Ogden law{{}, alpha};
  for (const double mu : mu_mpa) law.mu.push_back(mu / m.shear_modulus_mpa);
  m.law = std::move(law);
  return m;
}

double locking_first_invariant(const MaterialLaw& law) {
  return std::visit([](const auto& l) { return l.locking_i1(); }, law);
}

std::pair<std::string, std::string> locking_limit_words(const MaterialLaw& law) {
  if (std::holds_alternative<ArrudaBoyce>(law)) return {"Arruda-Boyce", "3 N"};
  if (std::holds_alternative<Gent>(law) || std::holds_alternative<GentGent>(law))
    return {"Gent", "3 + J_lim"};
  return {};
}

MembraneStress membrane_stress(const MaterialLaw& law, double l1, double l2) {
  return std::visit([&](const auto& l) { return membrane_stress(l, l1, l2); }, law);
}

double strain_energy_density(const MaterialLaw& law, double l1, double l2) {
  const double i1 = first_invariant(l1, l2);
  return std::visit([&](const auto& l) { return strain_energy_density(l, l1, l2, i1); }, law);
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
