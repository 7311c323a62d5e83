#pragma once
// The elastic energy a state's fields store, for the energy identities that need it (the energy
// to puncture over a sealed chamber, docs/model.md §17.1).
#include "puncture/membrane_fields.hpp"
#include "puncture/problem.hpp"

namespace puncture::detail {

// U = 2 pi H int W(lambda1, lambda2) R dR over every part [N mm], each part on its own samples
// (the stretches may jump where two parts meet), trapezoid rule extrapolated (Richardson), as
// enclosed_volume_mm3.
double stored_energy_nmm(const MembraneFields& fields, const Problem& problem);

}  // namespace puncture::detail
