#pragma once
// The inflation (bulge) test: a flat circular membrane clamped at radius A and inflated by a
// uniform pressure p, a follower load normal to the deformed surface (paper §2.3, Fig. 6; the
// equations are in docs/model.md, "Inflation (bulge) test").
//
// The pressure is not a monotone function of the deformation: a neo-Hookean membrane has a
// pressure maximum (a limit point: under pressure control it snaps through), and Gent and
// Mooney-Rivlin membranes stiffen again after it.  The curve is therefore parametrised by the
// stretch at the pole, which grows monotonically along it; the states at a given pressure are
// every branch of that curve.
//
// Inputs in mm and MPa like the rest of the library.  Invalid input throws
// std::invalid_argument naming the parameter; a solver failure is a Status and a message,
// never a NaN.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "puncture/material.hpp"
#include "puncture/membrane_fields.hpp"
#include "puncture/options.hpp"
#include "puncture/outcome.hpp"
#include "puncture/problem.hpp"

namespace puncture {

struct InflationProblem {
  double clamp_radius_mm = 25.0;  // radius A of the clamped (free) membrane [mm]; the paper's
                                  // inflation tests used 30 mm (§2.3)
  double thickness_mm = 0.2;      // undeformed thickness H [mm]
  Material material;              // G and the strain-energy law (default: the paper's Gent)
  double critical_i1 = 95.2;      // the membrane bursts when its largest I1 reaches this
  // Equibiaxial pre-stretch L0 (>= 1): the stress-free disc of radius A / L0 is stretched by L0
  // and clamped at radius A, then inflated (1: mounted stress-free).  Stretches, I1 and the
  // pole stretch are measured from the stress-free disc, reference radii on it, and the stored
  // energy includes the pre-stretch's.  The flat state's pole stretch is L0.
  double prestretch = 1.0;
};

// The membrane of an indentation problem (clamp radius, thickness, material, critical I1).
InflationProblem inflation_problem(const Problem& problem);

// Every problem with the input, each with the attribute it is about ("clamp_radius_mm",
// "thickness_mm", "material.shear_modulus_mpa", "material.law.j_lim", "material.law.alpha",
// "critical_i1", "prestretch") and a message giving the allowed range; empty if valid.
std::vector<ValidationError> validation_errors(const InflationProblem& problem);
// Throws InvalidInput listing every problem.
void validate(const InflationProblem& problem);

// Pressure scale G H / A [MPa]: the normalised pressure is p A / (G H).
double pressure_scale_mpa(const InflationProblem& problem);

// One inflated equilibrium.
struct InflationState : Outcome {  // Converged, NoConvergence or BeyondLocking

  double pole_stretch = 1.0;           // equibiaxial stretch at the pole, lambda0
  double pressure_mpa = 0.0;           // p [MPa]
  double normalized_pressure = 0.0;    // p A / (G H)
  double pole_height_mm = 0.0;         // height of the pole above the clamp plane [mm]
  double volume_mm3 = 0.0;             // volume enclosed between the membrane and the clamp plane
  double stored_energy_mj = 0.0;       // elastic energy of the membrane [mJ = N mm]
  double pole_stress_mpa = 0.0;        // nominal stress at the pole, G s_eq(lambda0)
  double pole_tension_n_per_mm = 0.0;  // true line tension at the pole, H s_eq / lambda0
  double pole_curvature_radius_mm = 0.0;  // radius of curvature of the membrane at the pole
                                          // (infinite for the flat state)
  double clamp_radial_stretch = 1.0;      // lambda1 at the clamp
  double clamp_slope_rad = 0.0;           // phi at the clamp
  double max_first_invariant = 3.0;       // largest I1 in the membrane
  double max_first_invariant_reference_radius_mm = 0.0;  // where: R (0 = the pole)
  double max_first_invariant_radius_mm = 0.0;            // ... and r
  double clamp_residual = 0.0;                           // |lambda2(A) - 1| reached by the shooting
  int shooting_evaluations = 0;                          // integrations used
  MembraneFields fields;  // when SolverOptions::record_fields; every part Free, deflection = height
};

// The equilibrium whose pole stretch is `pole_stretch` (>= the pre-stretch, 1 by default).
// Throws std::invalid_argument for an invalid problem or a pole stretch that is not a finite
// number >= the pre-stretch; a pole stretch at
// or beyond the Gent locking limit gives Status::BeyondLocking.
InflationState inflate_at_pole_stretch(const InflationProblem& problem, double pole_stretch,
                                       const SolverOptions& options = {});

struct InflationCurveOptions {
  int points = 100;               // states on the curve, equally spaced in pole stretch (>= 2)
  double max_pole_stretch = 0.0;  // end of the curve (> the pre-stretch); 0: at the burst
  int scan_points = 60;           // pole stretches scanned for pressure extrema (>= 8)
  // Called after each state of the curve with (done, total), if set.
  std::function<void(int, int)> progress;
};

enum class ExtremumKind {
  Maximum,  // a limit point: under pressure control the membrane snaps through here
  Minimum,  // the pressure rises again beyond (stiffening)
};
std::string to_string(ExtremumKind kind);

struct PressureExtremum {
  ExtremumKind kind = ExtremumKind::Maximum;
  InflationState state;             // at the extremum (with fields if recorded)
  double pressure_slope_mpa = 0.0;  // dp/dlambda0 [MPa] evaluated at the located stretch
  double curvature_mpa = 0.0;       // d2p/dlambda0^2 [MPa] there (< 0 at a maximum)
};

struct InflationBurst : Outcome {
  InflationState state;  // the first state whose largest I1 reaches the critical I1
};

struct InflationCurve : Outcome {
  double end_pole_stretch = 1.0;          // the curve's last pole stretch
  std::vector<InflationState> states;     // equally spaced in pole stretch, without fields
  std::vector<PressureExtremum> extrema;  // in order of pole stretch
  InflationBurst burst;                   // where the largest I1 reaches the critical I1
};

// The inflation curve from the flat state to the burst (or to max_pole_stretch), its pressure
// extrema and the burst.  Throws std::invalid_argument for an invalid problem or options.
InflationCurve inflation_curve(const InflationProblem& problem,
                               const InflationCurveOptions& curve = {},
                               const SolverOptions& options = {});

// The first state whose largest I1 reaches problem.critical_i1 (a root search on the pole
// stretch; the largest I1 is not assumed to be at the pole).
InflationBurst inflation_burst(const InflationProblem& problem, const SolverOptions& options = {});

// The local maxima and minima of the pressure for pole stretches in (L0, max_pole_stretch]:
// a scan of `scan_points` stretches, then a root of dp/dlambda0 (a four-point central
// difference) by TOMS 748 in each bracket.  Converged with no extrema when the pressure is
// monotone (e.g. Mooney-Rivlin with alpha = 0.1 up to its burst).
struct PressureExtrema : Outcome {
  std::vector<PressureExtremum> extrema;
};
PressureExtrema pressure_extrema(const InflationProblem& problem, double max_pole_stretch,
                                 int scan_points = 60, const SolverOptions& options = {});

// Every state at pressure p [MPa] with a pole stretch up to the burst (or the range's
// max_pole_stretch), in increasing pole stretch: states[0] is the one reached by slowly
// inflating from flat; more than one exist where the pressure curve turns back.  NotReached, with
// no states and a message giving the highest pressure of the range, when no state in the range
// carries that pressure (e.g. above a limit point).
struct InflationAtPressure : Outcome {
  double pressure_mpa = 0.0;
  double max_pole_stretch = 1.0;  // the range searched
  std::vector<InflationState> states;
  std::vector<PressureExtremum> extrema;  // of the range searched
};
InflationAtPressure inflate_at_pressure(const InflationProblem& problem, double pressure_mpa,
                                        const InflationCurveOptions& range = {},
                                        const SolverOptions& options = {});

}  // namespace puncture
