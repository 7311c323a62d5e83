#pragma once
// Calibration: the model's parameters from the paper's experiments.
//
//   critical I1  from the marks of inflation (bulge) tests at burst        (paper §2.3)
//   G (J_lim, alpha) from a uniaxial tensile test, by least squares        (§4.1, Fig. 11)
//
// Inputs in mm, N and MPa like the rest of the library.  Invalid inputs throw
// std::invalid_argument naming the quantity; a target the model cannot reach is not an error:
// the result says "not found", why, and what the model can reach.
#include <optional>
#include <string>
#include <vector>

#include "puncture/csv.hpp"
#include "puncture/material.hpp"
#include "puncture/problem.hpp"

namespace puncture {

// ---------------------------------------------------------------------------------------------
// Critical I1 from inflation tests (§2.3).  At the pole of an inflated membrane the stretch is
// equibiaxial, lambda = (radius of the mark at burst) / (its initial radius), and with
// incompressibility I1 = 2 lambda^2 + lambda^-4.

struct BurstTest {
  double initial_radius_mm = 0.0;  // radius of the mark drawn on the flat membrane [mm]
  double burst_radius_mm = 0.0;    // its radius when the membrane bursts [mm]
};

struct CriticalI1Estimate {
  std::vector<double> stretches;             // per test: burst radius / initial radius
  std::vector<double> first_invariants;      // per test: 2 lambda^2 + lambda^-4
  double mean = 0.0;                         // mean of the per-test I1: the critical I1
  std::optional<double> standard_deviation;  // sample standard deviation (n - 1); needs 2 tests
  std::optional<double> standard_error;      // of the mean, sd / sqrt(n)
};

double equibiaxial_first_invariant(double stretch);  // 2 l^2 + l^-4
// The stretch >= 1 whose equibiaxial I1 is `i1` (>= 3); Boost's bracketed Newton.
double equibiaxial_stretch_for_first_invariant(double i1);

// Throws std::invalid_argument naming the test when a radius is not a finite number > 0 or the
// mark shrank (burst radius below the initial radius), or when there is no test.
CriticalI1Estimate critical_i1_from_inflation(const std::vector<BurstTest>& tests);

// The tests in a table with a column burst_radius_mm and either a column initial_radius_mm or,
// for every test, `mark_radius_mm`.  Throws CsvError (a missing column; a radius <= 0 or a
// shrinking mark, naming its line) or std::invalid_argument (the mark radius missing, or given
// as well as the column).
std::vector<BurstTest> burst_tests_from_table(const CsvTable& table,
                                              std::optional<double> mark_radius_mm);

// ---------------------------------------------------------------------------------------------
// Least-squares fit of a uniaxial tensile test (§4.1, Fig. 11): nominal stress
// P = G s_uni(lambda) (uniaxial_stress), by Eigen's Levenberg-Marquardt (MINPACK lmder).
// Gent is fitted in (G, c = 1/J_lim), which is linear near the neo-Hookean c = 0, so data that
// never reach the stiffening give c ~ 0 with a finite standard error instead of a runaway J_lim.

struct UniaxialPoint {
  double stretch = 1.0;             // lambda = current / initial gauge length
  double nominal_stress_mpa = 0.0;  // force / initial cross-section [MPa]
};

struct SpecimenGeometry {
  double width_mm = 0.0;
  double thickness_mm = 0.0;
  double gauge_length_mm = 0.0;
};

// lambda = 1 + displacement / gauge length, P = force / (width thickness).
std::vector<UniaxialPoint> uniaxial_points(const std::vector<double>& force_n,
                                           const std::vector<double>& displacement_mm,
                                           const SpecimenGeometry& specimen);
// From a table with columns stretch,nominal_stress_mpa, or force_n,displacement_mm and the
// specimen.  Throws CsvError (missing columns, a value out of range, with its line) or
// std::invalid_argument (specimen missing or given for stress data).
std::vector<UniaxialPoint> uniaxial_points_from_table(
    const CsvTable& table, const std::optional<SpecimenGeometry>& specimen);

enum class FitLaw { Gent, NeoHookean, MooneyRivlin };

struct FittedParameter {
  std::string name;                      // "G", "J_lim", "alpha"
  std::string unit;                      // "MPa" or "" (dimensionless)
  std::optional<double> value;           // empty when the data do not give one (J_lim, c <= 0)
  std::optional<double> standard_error;  // sigma sqrt((J^T J)^-1)_ii; empty when singular
  // The data determine the parameter: value and standard error exist and the value is more
  // than two standard errors from zero (relative error below 50 %; for Gent's c = 1/J_lim: the
  // data tell Gent from neo-Hookean at about 95 %).
  bool identifiable = false;
  std::string note;  // why not identifiable, or what the value means
};

struct UniaxialFit {
  bool converged = false;
  std::string message;  // the optimiser's stop reason when not converged
  FitLaw law = FitLaw::Gent;
  // The best fit as a material the solver accepts; empty when it is not one (Gent with
  // c = 1/J_lim <= 0, Mooney-Rivlin alpha outside [0, 1), G <= 0).
  std::optional<Material> material;
  std::vector<FittedParameter> parameters;  // G first
  // Gent: the fitted c = 1/J_lim and its standard error, and the lower bound of J_lim at two
  // standard errors, 1 / (c + 2 se_c), when c + 2 se_c > 0.
  std::optional<double> inverse_j_lim;
  std::optional<double> inverse_j_lim_se;
  std::optional<double> j_lim_lower_bound;
  // How far the data reach into the Gent stiffening: the largest I1 - 3 of the data, and
  // (Gent) the stress at the largest stretch over the neo-Hookean stress with the same G.
  double max_i1_minus_3 = 0.0;
  std::optional<double> stiffening_at_largest_stretch;
  double rms_residual_mpa = 0.0;  // sqrt(sum r^2 / n)
  double residual_sd_mpa = 0.0;   // sigma = sqrt(sum r^2 / (n - p))
  int points = 0;
  int iterations = 0;
  std::vector<double> fitted_stress_mpa;  // the model at each data point
};

struct UniaxialFitOptions {
  int max_function_evaluations = 2000;
};

// Needs more points than parameters, stretches > 0 and a positive stress somewhere; throws
// std::invalid_argument otherwise.
UniaxialFit fit_uniaxial(const std::vector<UniaxialPoint>& data, FitLaw law,
                         const UniaxialFitOptions& options = {});

std::string to_string(FitLaw law);

}  // namespace puncture
