#pragma once
// The probe's work along the sealed chamber's loading path, int_0^depth F d(depth) [mJ = N mm]
// (docs/model.md §17.1, "Energy"): with friction the work is not a change of the membrane's and
// the gas's energy (friction dissipates), so it is integrated along the path itself.  A sliding
// state depends on the force and the pressure alone, so each node is the sealed state at its
// depth (sealed_gas.hpp).
#include <optional>
#include <string>

#include "indentation/sealed_gas.hpp"

namespace puncture::detail {

struct SealedPathWork {
  std::optional<double> work_mj;  // empty when a state on the path does not solve
  std::string why;                // ... and why
  int states = 0;                 // sealed states solved (nodes and the onset's bisection)
};

// Composite 10-point Gauss-Legendre on [0, end_depth_mm] of the sealed path's force, split at
// Part II's onset (located by bisection on the configuration to 1e-9 of the depth when the state
// at `end_depth_mm` has Part II) and graded towards zero depth when the membrane is pre-tensioned
// (inflated or pre-stretched: F ~ depth / log(depth) there), `panels` panels per piece.
SealedPathWork sealed_path_work(const Problem& p, const SealedChamber& chamber, double end_depth_mm,
                                const SolverOptions& options, int panels = 12);

}  // namespace puncture::detail
