#pragma once
// How the equations are solved: tolerances and limits.  Defaults give every point of a loading
// curve converged to better than 1e-8 relative.

namespace puncture {

struct SolverOptions {
  double integration_rel_tol = 1e-11;  // Dormand-Prince local relative error per step
  double integration_abs_tol = 1e-13;  // ... and absolute error (dimensionless variables)
  double shooting_tol = 1e-12;         // clamp residual |lambda2(A) - 1| accepted by the shooting
  int max_shooting_iterations = 100;   // per boundary-value solve
  int max_steps = 100000;              // integration steps per part before giving up
  bool record_fields = true;           // fill Equilibrium::fields (off in inner loops)
};

}  // namespace puncture
