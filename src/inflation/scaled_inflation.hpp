#pragma once
// The inflation solver in normalised variables (lengths / A, stresses / G, P = p A / (G H)),
// shared by the files of src/inflation.  One solve: the pressure P whose meridian, started at
// the pole with the given stretch, meets the clamp condition lambda2(1) = 1.
#include <string>
#include <vector>

#include "puncture/inflation.hpp"
#include "puncture/material.hpp"
#include "puncture/options.hpp"

namespace puncture::detail {

struct InflationSample {
  double r_ref;  // R / A
  double t;      // R s1 cos(phi)
  double l1, l2;
  double drop;  // h: drop below the pole / A
};

struct ScaledInflation {
  Status status = Status::NoConvergence;
  std::string message;
  double pole_stretch = 1.0;
  double pressure = 0.0;     // P = p A / (G H)
  double slope_rate = 0.0;   // c = dphi/dR at the pole
  double pole_stress = 0.0;  // s_eq(lambda0) / G
  double pole_height = 0.0;  // / A
  double volume = 0.0;       // / A^3
  double energy = 0.0;       // / (2 pi G H A^2)
  double clamp_l1 = 1.0;
  double clamp_slope = 0.0;
  double residual = 0.0;  // |lambda2(1) - 1|
  double max_i1 = 3.0;
  double max_i1_r_ref = 0.0;   // R / A
  double max_i1_radius = 0.0;  // r / A
  int evaluations = 0;
  std::vector<InflationSample> samples;  // from the first integration point to the clamp
  bool ok() const { return status == Status::Converged; }
};

// pressure_guess > 0 starts the bracket of P there (continuation along a curve); samples are
// kept when options.record_fields.
ScaledInflation solve_inflation(const MaterialLaw& law, double pole_stretch,
                                const SolverOptions& options, double pressure_guess = 0.0);

// Physical state (mm, MPa) of a normalised solution, with fields when it has samples.
InflationState to_physical(const InflationProblem& problem, const ScaledInflation& sol);

// Throws std::invalid_argument (naming `name`) unless pole_stretch is finite and >= 1.
void check_pole_stretch(double pole_stretch);

// Pole stretch at which the pole locks (infinity for laws that never lock).
double locking_pole_stretch(const MaterialLaw& law);

}  // namespace puncture::detail

namespace puncture::detail {

// Tolerances for the solves whose pressures are differenced (the extrema): at least 1e-12
// relative per step, so that a four-point difference with step 1e-2 keeps ~9 digits.
SolverOptions differencing_options(const SolverOptions& options);

// Throws std::invalid_argument for a max_pole_stretch that is neither 0 nor a finite number in
// (1, the locking pole stretch), or for point counts out of range.
void check_curve_options(const InflationProblem& problem, const InflationCurveOptions& curve);

}  // namespace puncture::detail
