#pragma once
// The finite elements over a sealed gas chamber (Preload::gas_volume_mm3, docs/model.md §17.2,
// "Over a sealed chamber").  The potential is U + p_atm (V - V_s) - C ln((V0 + V) / (V0 + V_s)),
// C = (P + p_atm)(V0 + V_s) the gas's content; at a fixed depth its stationary points are those of
// U - p V at the pressure p = C / (V0 + V) - p_atm of their own volume.  So a state is the
// elements' constant-pressure state (smooth_probe.hpp, from their own dome at p) at the pressure
// whose volume satisfies the gas law: a scalar root in p around the elements' minimisation, with
// the elements' own volume and dome, nothing of the shooting's.
#include <vector>

#include "puncture/finite_element.hpp"
#include "puncture/problem.hpp"

namespace puncture::fe {

// States at the given depths [mm] (increasing, > 0; from the sealed dome's pole) over the
// chamber of `problem` (sealed at pressure_mpa > 0), frictionless; each with gas_pressure_mpa
// and volume_mm3 of its gas law.
std::vector<FeState> solve_sealed_chamber(const Problem& problem,
                                          const std::vector<double>& depths_mm,
                                          const FeOptions& options);

}  // namespace puncture::fe
