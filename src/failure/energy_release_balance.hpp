#pragma once
// The energy-release criterion's balance on a state's fields (the puncture search's normalised
// solutions and an Equilibrium read the same fields, so both give the same number to the bit).
#include <optional>

#include "puncture/energy_release.hpp"
#include "puncture/failure.hpp"
#include "puncture/membrane_fields.hpp"

namespace puncture::detail {

// 2 pi H int W R dR [mJ] over the rows of `fields`, part by part: on a part's rows at even steps
// of R (the solver's samples), Simpson's rule extrapolated from every row and every other row;
// else Simpson's rule on uneven nodes (exact in Part III, where W R is linear).
double stored_energy_mj(const Problem& p, const MembraneFields& fields);

// The balance of a state with fields `fields` and Part III stretch `part_three_stretch`; the cut
// membrane's energy NaN when its equilibrium is not found.
EnergyRelease energy_release_of(const Problem& p, const MembraneFields& fields,
                                double part_three_stretch, double tearing_energy_n_per_mm);

// The criterion as an assessment of the balance: the energy released per unit reference area of
// the cut [N/mm] against the tearing energy, at the cut ring.
FailureAssessment energy_release_assessment(const Problem& p, const EnergyRelease& balance,
                                            const CriticalEnergyRelease& criterion);

}  // namespace puncture::detail
