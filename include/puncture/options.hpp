#pragma once
// How the equations are solved: tolerances and limits.  Defaults give every point of a loading
// curve converged to better than 1e-8 relative.
#include <optional>

namespace puncture {

struct SolverOptions {
  // Runge-Kutta-Fehlberg 7(8) local relative error per step, and absolute error (dimensionless
  // variables): 3e-11 keeps the reported depths and forces within ~2e-9 of a 1e-13 reference
  // (1e-10 left them within ~1e-8: the steps of a part accumulate its error).
  double integration_rel_tol = 3e-11;
  double integration_abs_tol = 3e-13;
  double shooting_tol = 1e-10;        // clamp residual |lambda2(A) - 1| accepted by the shooting
  double curve_tol = 1e-9;            // loading-curve points: Newton stops when the clamp residual
                                      // and the relative depth residual are below this
  int field_points = 200;             // fields: an indentation's Part I (and Part II) sampled
                                      // at this many intervals evenly spaced in the reference
                                      // radius; an inflation's membrane at least this many
  int max_shooting_iterations = 100;  // per boundary-value solve
  int max_steps = 100000;             // integration steps per part before giving up
  bool record_fields = true;          // fill Equilibrium::fields (off in inner loops)
  // Fill PuncturePrediction::energy_to_puncture_mj, the area under the force-depth curve to
  // puncture: it costs about a third of a 200-point loading curve, so it is off unless asked.
  bool energy_to_puncture = false;
  // Fill PuncturePrediction::failure_verdict for a pre-tensioned membrane (pressure, sealed gas
  // or pre-stretch): it follows the 200-point loading curve to find its force maxima, about as
  // costly as the puncture itself, so it is off unless asked (docs/model.md §8.1).
  bool failure_verdict = false;
  // A warm start for the puncture search: the hoop stretch at the top of Part II [-] of a
  // neighbouring problem's puncture (PuncturePrediction::part_two_top_stretch).  The flat punch's
  // corner solve polishes its root from there instead of bracketing it; the puncture then agrees
  // with the cold one to the shooting's tolerance, not bit for bit, and a start from which the
  // polish does not converge falls back to the cold search.  Unset: cold (a sweep's chains set
  // it, docs/sweeps.md).
  std::optional<double> puncture_top_stretch_start;
};

}  // namespace puncture
