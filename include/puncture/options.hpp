#pragma once
// How the equations are solved: tolerances and limits.  Defaults give every point of a loading
// curve converged to better than 1e-8 relative.

namespace puncture {

struct SolverOptions {
  double integration_rel_tol = 1e-10;  // Runge-Kutta-Fehlberg 7(8) local relative error per step
  double integration_abs_tol = 1e-12;  // ... and absolute error (dimensionless variables)
  double shooting_tol = 1e-10;         // clamp residual |lambda2(A) - 1| accepted by the shooting
  double curve_tol = 1e-9;             // loading-curve points: Newton stops when the clamp residual
                                       // and the relative depth residual are below this
  int field_points = 200;              // at least this many samples of Part I (and II) in fields
  int max_shooting_iterations = 100;   // per boundary-value solve
  int max_steps = 100000;              // integration steps per part before giving up
  bool record_fields = true;           // fill Equilibrium::fields (off in inner loops)
};

}  // namespace puncture
