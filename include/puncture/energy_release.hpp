#pragma once
// The energy balance of the energy-release criterion (CriticalEnergyRelease, docs/model.md §18)
// on a solved state of a frictionless flat punch: the elastic energy of the indented membrane,
// that of the same membrane cut through its thickness along the ring of material at the corner,
// at the same depth, and the tearing energy the cut costs.
#include <string>
#include <vector>

#include "puncture/equilibrium.hpp"
#include "puncture/outcome.hpp"
#include "puncture/problem.hpp"

namespace puncture {

struct EnergyRelease {
  // U: elastic energy of the intact membrane, from the stress-free disc (a pre-stretched
  // membrane's pre-stretch energy included) [mJ = N mm].
  double stored_energy_mj = 0.0;
  // U_cut: elastic energy of the cut membrane at the same depth [mJ]: the disc inside the cut is
  // free of stress, the annulus outside carries no axial force (frictionless rod) and lies in the
  // clamp plane, its material from R_c to R_j wrapped on the rod meridionally slack.
  double punctured_energy_mj = 0.0;
  double cut_energy_mj = 0.0;            // Gamma 2 pi R_c H, what the cut costs [mJ]
  double cut_reference_radius_mm = 0.0;  // R_c, reference radius of the cut: the corner's material
  // R_j: the cut annulus lies flat beyond it; R_c when the hole clears the rod (a pre-stretched
  // membrane opens its hole wider than the rod).
  double collar_reference_radius_mm = 0.0;
  double hole_radius_mm = 0.0;  // current radius of the flat annulus's free inner edge (>= a)
  double released_energy_mj() const { return stored_energy_mj - punctured_energy_mj; }
  // Released over cost: the membrane punctures at 1.
  double ratio() const { return released_energy_mj() / cut_energy_mj; }
};

// Why the energy-release criterion does not apply to `problem` (empty when it does): it needs a
// flat punch, no friction (friction 0 and no stick rule: friction dissipates, so the released
// energy would depend on the path), no pressure and the ring-balance Part II equation.
std::vector<std::string> energy_release_conflicts(const Problem& problem);

// The balance on `state` (which needs its fields) for the tearing energy Gamma [N/mm].  Throws
// InvalidInput ("criteria") where the criterion does not apply, ("state") for a state without
// fields or not usable, ("tearing_energy") for Gamma not finite and > 0.  The cut membrane's
// energy is NaN (and so the ratio) if its equilibrium is not found (its annulus would lock).
EnergyRelease energy_release(const Problem& problem, const Equilibrium& state,
                             double tearing_energy_n_per_mm);

}  // namespace puncture
