#pragma once
// The inflation solver in normalised variables (lengths / (A / L0), the stress-free clamp
// radius; stresses / G; P = p (A / L0) / (G H)), shared by the files of src/inflation.  One
// solve: the pressure P whose meridian, started at the pole with the given stretch, meets the
// clamp condition lambda2(1) = L0 (1 without pre-stretch: then every scale is A's, bit for bit).
#include <string>
#include <vector>

#include "puncture/inflation.hpp"
#include "puncture/material.hpp"
#include "puncture/options.hpp"

namespace puncture::detail {

struct InflationSample {
  double r_ref;  // R / (A / L0)
  double t;      // R s1 cos(phi)
  double l1, l2;
  double drop;  // h: drop below the pole / A
};

struct ScaledInflation {
  Status status = Status::NoConvergence;
  std::string message;
  double pole_stretch = 1.0;
  double pressure = 0.0;     // P = p (A / L0) / (G H)
  double slope_rate = 0.0;   // c = dphi/dR at the pole
  double pole_stress = 0.0;  // s_eq(lambda0) / G
  double pole_height = 0.0;  // / A
  double volume = 0.0;       // / A^3
  double energy = 0.0;       // / (2 pi G H A^2)
  double clamp_l1 = 1.0;
  double clamp_slope = 0.0;
  double residual = 0.0;  // |lambda2(1) - L0|
  double max_i1 = 3.0;
  double max_i1_r_ref = 0.0;   // R / A
  double max_i1_radius = 0.0;  // r / A
  int evaluations = 0;
  std::vector<InflationSample> samples;  // from the first integration point to the clamp
  bool ok() const { return status == Status::Converged; }
};

// The state of `problem`'s membrane (its law and pre-stretch) at `pole_stretch`;
// pressure_guess > 0 starts the bracket of P there (continuation along a curve); samples are
// kept when options.record_fields.
ScaledInflation solve_inflation(const InflationProblem& problem, double pole_stretch,
                                const SolverOptions& options, double pressure_guess = 0.0);

// The solver's units: the stress-free clamp radius A / L0 [mm] and the pressure G H / (A / L0)
// [MPa] (A and pressure_scale_mpa without pre-stretch).
double reference_clamp_radius_mm(const InflationProblem& problem);
double solver_pressure_scale_mpa(const InflationProblem& problem);

// Physical state (mm, MPa) of a normalised solution, with fields when it has samples.
InflationState to_physical(const InflationProblem& problem, const ScaledInflation& sol);

// Throws std::invalid_argument (naming "pole_stretch") unless pole_stretch is finite and >=
// the problem's pre-stretch (the flat state's pole stretch).
void check_pole_stretch(const InflationProblem& problem, double pole_stretch);

// Pole stretch at which the pole locks (infinity for laws that never lock).
double locking_pole_stretch(const MaterialLaw& law);

}  // namespace puncture::detail

namespace puncture::detail {

// Tolerances for the solves whose pressures are differenced (the extrema): at least 1e-12
// relative per step, so that a four-point difference with step 1e-2 keeps ~9 digits.
SolverOptions differencing_options(const SolverOptions& options);

// Throws std::invalid_argument for a max_pole_stretch that is neither 0 nor a finite number in
// (L0, the locking pole stretch), or for point counts out of range.
void check_curve_options(const InflationProblem& problem, const InflationCurveOptions& curve);

}  // namespace puncture::detail
