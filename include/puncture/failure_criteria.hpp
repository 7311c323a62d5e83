#pragma once
// The failure criteria a problem may carry (docs/model.md, "Failure criteria"): a critical value
// of a local measure of the deformation, evaluated where that measure is largest, or the global
// energy balance of cutting the membrane (CriticalEnergyRelease).  The functions on them are in
// failure.hpp; the Problem holds a list of them.
#include <variant>

namespace puncture {

// The paper's criterion (§2.3): the membrane punctures where the first invariant I1 of the
// right Cauchy-Green tensor first reaches a critical value, measured in the inflation test.
struct CriticalFirstInvariant {
  double critical_i1 = 95.2;
};

// The largest principal stretch max(lambda1, lambda2, lambda3) reaches a critical value (the
// stretch at the tip, Nguyen & Vu-Khanh 2004; the maximum local deformation, Deris & Nadler
// 2015).  Dimensionless, > 1.
struct MaxPrincipalStretch {
  double critical_stretch = 0.0;
};

// The strain-energy density W per reference volume reaches a critical value [MPa = MJ/m^3].
struct CriticalEnergyDensity {
  double critical_mpa = 0.0;
};

// The largest principal true (Cauchy) stress reaches a critical value [MPa]: for the
// incompressible membrane sigma_i = t_i / h = lambda_i s_i, with t_i the line tension, h = H /
// (lambda1 lambda2) the current thickness and s_i the nominal stress.
struct CriticalTrueStress {
  double critical_mpa = 0.0;
};

// The energy (Griffith-type) criterion of Steigmann (2005) and Nadler & Steigmann (2006), in
// the rigorous frictionless form of docs/model.md §18: at the current depth, the membrane cut
// through its thickness along the ring of material at the flat punch's corner (reference radius
// R_c) would store less energy, by at least the tearing energy of the cut, Gamma 2 pi R_c H.
// Gamma is the tearing energy per unit reference area of the cut [N/mm = kJ/m^2], > 0.  Only for
// a frictionless flat punch without pressure (energy_release.hpp gives the balance).
struct CriticalEnergyRelease {
  double tearing_energy_n_per_mm = 0.0;
};

using FailureCriterion =
    std::variant<CriticalFirstInvariant, MaxPrincipalStretch, CriticalEnergyDensity,
                 CriticalTrueStress, CriticalEnergyRelease>;

}  // namespace puncture
