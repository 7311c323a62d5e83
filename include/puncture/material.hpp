#pragma once
// The membrane's material: a shear modulus and a strain-energy law chosen at run time.
// Adding a law: write a struct like materials/gent.hpp (name(), locking_i1(), and derivatives()
// of W(I1, I2), or, like materials/ogden.hpp, stresses() and energy() in principal stretches)
// and add it to MaterialLaw below.
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "puncture/materials/arruda_boyce.hpp"
#include "puncture/materials/gent.hpp"
#include "puncture/materials/gent_gent.hpp"
#include "puncture/materials/mooney_rivlin.hpp"
#include "puncture/materials/neo_hookean.hpp"
#include "puncture/materials/ogden.hpp"
#include "puncture/materials/yeoh.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture {

using MaterialLaw =
    std::variant<Gent, NeoHookean, MooneyRivlin, Yeoh, Ogden, ArrudaBoyce, GentGent>;

struct Material {
  double shear_modulus_mpa = 0.06;  // initial shear modulus G [MPa]; paper §4.1
  MaterialLaw law = Gent{125.0};    // the paper's Gent law with J_lim = 125
};

std::string law_name(const MaterialLaw& law);
// The law with its parameters as it holds them, e.g. "gent (J_lim = 125)",
// "yeoh (C20/G = 0.025, C30/G = 0.0005)".
std::string describe(const MaterialLaw& law);
// One-line description with parameters, e.g. "gent (J_lim = 125), G = 0.06 MPa"; Yeoh's and
// Ogden's as users give them, in MPa.
std::string describe(const Material& material);

// The Ogden material from its coefficients mu_p [MPa] and exponents alpha_p (1 to 3 of each):
// G = sum mu_p alpha_p / 2 and the law's mu_p / G.  Throws InvalidInput ("mu_mpa", "alpha") for
// lists of different lengths or of another size, and for G that is not > 0; the terms' own
// conditions are validation_errors()'s.
Material ogden_material(const std::vector<double>& mu_mpa, const std::vector<double>& alpha);
// The I1 at which the law locks: 3 + J_lim for Gent and Gent-Gent, 3 N for Arruda-Boyce,
// infinity for laws that do not lock.
double locking_first_invariant(const MaterialLaw& law);
// How messages name that limit: {"Gent", "3 + J_lim"} (Gent, Gent-Gent), {"Arruda-Boyce", "3 N"};
// empty for laws that do not lock.
std::pair<std::string, std::string> locking_limit_words(const MaterialLaw& law);

MembraneStress membrane_stress(const MaterialLaw& law, double l1, double l2);
// W / G at the stretches (lambda3 = 1 / (lambda1 lambda2)).
double strain_energy_density(const MaterialLaw& law, double l1, double l2);

// Inverse of s1(lambda1, lambda2) at fixed lambda2: the radial stretch lambda1 >= lambda2^(-1/2)
// whose radial nominal stress / G equals s1.  Empty when s1 < 0 (a membrane carries no
// compression) or when no stretch below the locking limit can carry s1 (never for Gent: s1 grows
// without bound towards the limit).
std::optional<double> radial_stretch_for_stress(const MaterialLaw& law, double s1, double l2);

// Equibiaxial nominal stress / G at stretch l (the stress in Part III).
double equibiaxial_stress(const MaterialLaw& law, double l);
// Uniaxial nominal stress / G at stretch l (lambda2 = lambda3 = l^(-1/2)).
double uniaxial_stress(const MaterialLaw& law, double l);

}  // namespace puncture
