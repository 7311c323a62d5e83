#pragma once
// Indentation over a sealed chamber (Preload::gas_volume_mm3, docs/model.md §17.1).  The chamber
// is closed at the inflated state of gauge pressure P, so the isothermal ideal gas keeps
// (p + p_atm)(V0 + V) = (P + p_atm)(V0 + V_s), V the volume between the membrane and its clamp
// plane (V_s the inflated dome's).  A state at a depth (or force) is the constant-pressure state
// at the pressure p that satisfies this law with that state's own V: one more unknown and one
// more equation, solved as a scalar root in p around the constant-pressure solver (TOMS 748,
// bracketed by a fixed-point step of the gas law).  Depths are measured from the sealed dome's
// pole, whatever the pressure does later.
#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::detail {

struct SealedChamber {
  double gas_volume_mm3 = 0.0;            // V0, under the flat membrane
  double atmospheric_pressure_mpa = 0.0;  // p_atm
  double sealed_pressure_mpa = 0.0;       // P, the gauge pressure at which it is closed
  double sealed_volume_mm3 = 0.0;         // V_s, the inflated dome's volume above the clamp plane
  double sealed_height_mm = 0.0;          // the inflated dome's height: depths count from its pole
  // (P + p_atm)(V0 + V_s), the same in every state [N mm].
  double gas_content_n_mm() const {
    return (sealed_pressure_mpa + atmospheric_pressure_mpa) * (gas_volume_mm3 + sealed_volume_mm3);
  }
  // The gas law's residual at gauge pressure p and enclosed volume V [N mm]: increasing in p.
  double residual(double pressure_mpa, double volume_mm3) const {
    return (pressure_mpa + atmospheric_pressure_mpa) * (gas_volume_mm3 + volume_mm3) -
           gas_content_n_mm();
  }
};

// The chamber of a problem with Preload::gas_volume_mm3 (the dome solved at the sealing
// pressure).  Throws PhysicalFailure when the dome does not solve.
SealedChamber sealed_chamber(const Problem& p, const SolverOptions& options);

// The problem at a constant gauge pressure: the sealed one with the chamber's pressure p held.
Problem at_held_pressure(const Problem& p, double pressure_mpa);

// The state at a depth (from the sealed dome's pole) or at a force over the chamber, with its
// gas; `pressure_guess_mpa` (>= P) starts the root search (a neighbouring state's pressure).
Equilibrium sealed_at_depth(const Problem& p, const SealedChamber& chamber, double depth_mm,
                            Stage stage, const SolverOptions& options, double pressure_guess_mpa);
Equilibrium sealed_at_force(const Problem& p, const SealedChamber& chamber, double force_n,
                            Stage stage, const SolverOptions& options);

// The puncture over the chamber: the constant-pressure puncture at the pressure its own state
// satisfies the gas law at (a state depends on the pressure and the force alone, not on the
// path: the problem slides, no stick stage).  energy_to_puncture, without friction, is the
// change of U + the gas's and the atmosphere's energy from the sealed dome; with friction the
// force integrated along the sealed path (sealed_path_work.hpp).
PuncturePrediction sealed_puncture(const Problem& p, const SolverOptions& options);

// The loading curve over the chamber, every point with its gas; Part II's onset by bisection
// between the points where it appears.
LoadingCurve sealed_loading_curve(const Problem& p, const CurveOptions& curve,
                                  const SolverOptions& options);

}  // namespace puncture::detail
