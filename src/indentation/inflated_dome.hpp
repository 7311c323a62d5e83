#pragma once
// The membrane inflated by a gas pressure before the indenter touches it (Problem::preload
// pressure_mpa): the state at zero force of an indentation under pressure, in the indentation
// solver's variables (docs/model.md §17).
#include <optional>

#include "indentation/scaled_solution.hpp"
#include "puncture/options.hpp"
#include "puncture/problem.hpp"

namespace puncture::detail {

struct InflatedDome {
  double pressure = 0.0;     // P = p (A / L0) / (G H)
  double height = 0.0;       // the pole's height above the clamp, / (A / L0)
  double clamp_slope = 0.0;  // the meridian's slope at the clamp [rad]: past pi/2 it overhangs
  // A later state than the first (Preload::inflated_state) that overhangs its clamp: followed in
  // depth control alone (ShootingSettings::dome_later_state).
  bool later_state = false;
  ScaledSolution state;  // Unloaded, all of it Part I from the pole to the clamp
};

// The inflated state at the problem's pressure that Preload::inflated_state chooses (the first,
// reached by inflating slowly from flat, by default); empty without pressure.  Throws
// PhysicalFailure (reported_failure.hpp) when no inflated state holds the pressure (it bursts or
// snaps through before contact).  The first state beyond a hemisphere (overhanging its clamp) is
// indented as it stands at a held pressure (docs/model.md §17); so is a later one that overhangs,
// in depth control alone (InflatedDome::later_state).
std::optional<InflatedDome> inflated_dome(const Problem& problem, const SolverOptions& options);

// Whether the dome's meridian overhangs its clamp (slope at the clamp >= pi/2).
bool overhangs_clamp(const InflatedDome& dome);

// Over a sealed chamber a trial gas pressure's dome must lie on the branch the chamber was sealed
// on (docs/model.md §17.1): one that overhangs its clamp does below the inflation's first limit
// point, and is indented as it stands; above it the first state at the pressure is the balloon
// past the limit point, another branch.  Throws PhysicalFailure (OutsideModel) naming the
// pressure and the limit point's when `dome` (of `held`, at a held pressure) is past it.
void refuse_dome_past_limit_point(const Problem& held, const InflatedDome& dome,
                                  const SolverOptions& options);

}  // namespace puncture::detail
