#pragma once
// Calibration: the model's parameters from the paper's experiments.
//
//   critical I1  from the marks of inflation (bulge) tests at burst        (paper §2.3)
//   friction mu' from the hole a dry membrane leaves: its size gives the Part III stretch
//                (indenter diameter / hole diameter)                        (§4.2)
//   J_lim        from the force of one puncture test and the critical I1    (§4.1)
//   G (J_lim, alpha) from a uniaxial tensile test, by least squares        (§4.1, Fig. 11)
//
// Inputs in mm, N and MPa like the rest of the library.  Invalid inputs throw
// std::invalid_argument naming the quantity; a target the model cannot reach is not an error:
// the result says "not found", why, and what the model can reach.
#include <optional>
#include <string>
#include <vector>

#include "puncture/csv.hpp"
#include "puncture/kinematics.hpp"
#include "puncture/loading_curve.hpp"
#include "puncture/material.hpp"
#include "puncture/outcome.hpp"
#include "puncture/problem.hpp"

namespace puncture {

// ---------------------------------------------------------------------------------------------
// Critical I1 from inflation tests (§2.3).  At the pole of an inflated membrane the stretch is
// equibiaxial, lambda = (radius of the mark at burst) / (its initial radius), and with
// incompressibility I1 = 2 lambda^2 + lambda^-4.  The paper takes that as the critical I1,
// which assumes the burst starts at the pole.  Given the membrane's law, the membrane inflated
// until its pole is stretched as the mark is solved instead, and each test's critical I1 is
// its largest I1, wherever it lies: for Gent and neo-Hookean the pole's, for Mooney-Rivlin
// near the clamp (docs/model.md §13.2, §14).

struct BurstTest {
  double initial_radius_mm = 0.0;  // radius of the mark drawn on the flat membrane [mm]
  double burst_radius_mm = 0.0;    // its radius when the membrane bursts [mm]
};

struct CriticalI1Estimate : Outcome {         // NoConvergence when an inflated state was not found
  std::vector<double> stretches;              // per test: burst radius / initial radius (pole)
  std::vector<double> pole_first_invariants;  // per test: 2 lambda^2 + lambda^-4, at the pole
  std::vector<double> first_invariants;       // per test: the largest I1 of the membrane
  // Per test: where that largest I1 lies, its reference radius over the clamp radius (R / A,
  // 0 = the pole).  Always 0 without the membrane's law.
  std::vector<double> largest_i1_radius_fractions;
  bool from_membrane = false;                // the membrane's law was solved (else the pole's I1)
  double mean = 0.0;                         // mean of the per-test I1: the critical I1
  std::optional<double> standard_deviation;  // sample standard deviation (n - 1); needs 2 tests
  std::optional<double> standard_error;      // of the mean, sd / sqrt(n)
};

// The paper's estimate, I1 at the pole.  Throws std::invalid_argument naming the test when a
// radius is not a finite number > 0 or the mark shrank (burst radius below the initial radius),
// or when there is no test.
CriticalI1Estimate critical_i1_from_inflation(const std::vector<BurstTest>& tests);
// Each test's largest I1 over the membrane of `law` inflated until its pole stretch is the
// mark's (the result does not depend on the clamp radius, thickness or modulus).  Throws as
// above, and std::invalid_argument for an invalid law or a mark stretched at or beyond the
// law's locking; a state the shooting does not find is a NoConvergence outcome naming the test.
CriticalI1Estimate critical_i1_from_inflation(const std::vector<BurstTest>& tests,
                                              const MaterialLaw& law);

// The tests in a table with a column burst_radius_mm and either a column initial_radius_mm or,
// for every test, `mark_radius_mm`.  Throws CsvError (a missing column; a radius <= 0 or a
// shrinking mark, naming its line) or std::invalid_argument (the mark radius missing, or given
// as well as the column).
std::vector<BurstTest> burst_tests_from_table(const CsvTable& table,
                                              std::optional<double> mark_radius_mm);

// ---------------------------------------------------------------------------------------------
// One model parameter inverted from one measured value by a scan and Boost's TOMS 748.

struct Inversion : Outcome {      // message: why not found, or a warning (several solutions)
  double value = 0.0;             // the parameter, when found
  std::vector<double> solutions;  // every solution in the searched range (value is the first)
  int evaluations = 0;            // model evaluations in the refinement
};

// A sampled point of the model on the scan, for transparency: `model` is empty where the
// solver failed.
struct ScanSample {
  double parameter = 0.0;
  std::optional<double> model;
};

// ---------------------------------------------------------------------------------------------
// Friction from the size of the hole (§4.2).  A dry membrane punctured by the flat tip leaves a
// round hole; the ratio indenter diameter / hole diameter is the Part III stretch at puncture.

enum class HoleMethod {
  // The paper's: at the measured puncture force, mu' such that the Part III stretch of the
  // sliding equilibrium (solve_at_force, Stage::Slip) equals the ratio.
  AtMeasuredForce,
  // Force-free: mu' such that the predicted puncture (predict_puncture) has the ratio as its
  // Part III stretch.  With the crack at the corner that stretch depends only on the material,
  // mu' and the critical I1 (docs/model.md §8), not on the force or the indenter.
  AtPredictedPuncture,
};

struct HoleMeasurement {
  double ratio = 0.0;                      // indenter diameter / hole diameter (the paper: 1.58)
  double ratio_sd = 0.0;                   // its standard deviation (the paper: 0.14); 0 for none
  std::optional<double> puncture_force_n;  // measured puncture force [N]; AtMeasuredForce only
};

struct FrictionOptions {
  double max_friction = 10.0;  // the model's limit (validation_errors)
  SolverOptions solver{};      // record_fields is switched off
};

struct FrictionEstimate {
  HoleMethod method = HoleMethod::AtMeasuredForce;
  double force_n = 0.0;  // AtMeasuredForce: the measured force
  // What the model can reach: the Part III stretch falls as the friction grows.
  // (empty where the solver failed)
  std::optional<double> stretch_at_zero_friction;  // the largest
  std::optional<double> stretch_at_max_friction;   // the smallest
  double max_friction = 0.0;
  Inversion friction;                     // for the ratio
  Inversion friction_for_ratio_plus_sd;   // ratio + sd: the lower end of the interval
  Inversion friction_for_ratio_minus_sd;  // ratio - sd: the upper end
  // At the fitted friction (when found and the solver converged there):
  std::optional<double> max_first_invariant;  // largest I1 at the force (AtMeasuredForce): above
                                              // the critical I1, the model punctures earlier
  std::optional<double> puncture_force_n;     // AtPredictedPuncture: the predicted force [N]
  std::optional<double> puncture_depth_mm;    // AtPredictedPuncture: the predicted depth [mm]
  std::vector<ScanSample> scan;               // (mu', Part III stretch)
};

// `problem` supplies everything but the friction (ignored).  Throws std::invalid_argument for
// an invalid problem, a ratio that is not finite and > 0, a negative sd, or a missing or
// non-positive force with AtMeasuredForce.
FrictionEstimate friction_from_hole(const Problem& problem, const HoleMeasurement& hole,
                                    HoleMethod method, const FrictionOptions& options = {});

// ---------------------------------------------------------------------------------------------
// J_lim from one puncture test (§4.1): the Gent J_lim for which the predicted puncture force
// (the largest I1 reaching the critical I1) equals the measured one.  The predicted force falls
// from infinity as J_lim -> critical I1 - 3 to the neo-Hookean force as J_lim -> infinity.

struct JLimOptions {
  // The scan: J_lim = (critical I1 - 3) (1 + g), g geometric in [min_gap, max_gap].
  double min_gap = 1e-5;
  double max_gap = 1e4;
  int points_per_decade = 4;
  SolverOptions solver{};
};

struct JLimEstimate {
  double force_n = 0.0;  // the measured puncture force
  Inversion j_lim;
  // What the model can reach on the scan, and as J_lim -> infinity.
  double smallest_force_n = 0.0;     // at the largest J_lim scanned
  double largest_force_n = 0.0;      // at the smallest J_lim scanned
  double neo_hookean_force_n = 0.0;  // the J_lim -> infinity limit (0 when it failed)
  double min_j_lim = 0.0;            // the scan's ends
  double max_j_lim = 0.0;
  PuncturePrediction puncture;                         // at the fitted J_lim
  std::optional<double> max_first_invariant_at_force;  // the paper's check: largest I1 of the
                                                       // sliding state at the measured force
  std::vector<ScanSample> scan;                        // (J_lim, predicted puncture force [N])
};

// `problem` must have the Gent law (its J_lim is ignored).  Throws std::invalid_argument for an
// invalid problem, another law, or a force that is not finite and > 0.
JLimEstimate j_lim_from_puncture_force(const Problem& problem, double puncture_force_n,
                                       const JLimOptions& options = {});

// ---------------------------------------------------------------------------------------------
// Least-squares fit of a uniaxial tensile test (§4.1, Fig. 11): nominal stress
// P = G s_uni(lambda) (uniaxial_stress), by Ceres' bounded Levenberg-Marquardt; or of an
// equibiaxial test, P = G s_eq(lambda) (equibiaxial_stress).  Every law is fitted.
// Gent is fitted in (G, c = 1/J_lim), which is linear near the neo-Hookean c = 0, so data that
// never reach the stiffening give c ~ 0 with a finite standard error instead of a runaway J_lim;
// Gent-Gent likewise, and Arruda-Boyce in (G, 1/N).

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

enum class FitLaw { Gent, NeoHookean, MooneyRivlin, Yeoh, Ogden, ArrudaBoyce, GentGent };
// Every law, in that order.
std::vector<FitLaw> all_fit_laws();

// The homogeneous test the data come from: which nominal stress of the law they are.
enum class StressTest {
  Uniaxial,     // lambda2 = lambda3 = lambda^-1/2: uniaxial_stress
  Equibiaxial,  // lambda1 = lambda2 = lambda, lambda3 = lambda^-2: equibiaxial_stress
};

// Information criteria of a least-squares fit with Gaussian errors of one unknown variance
// (Burnham & Anderson 2002, §2.2): with n points, the sum of squared residuals RSS and k
// estimated parameters (the law's p plus the variance, k = p + 1),
//   AIC = n ln(RSS / n) + 2 k,  AICc = AIC + 2 k (k + 1) / (n - k - 1),  BIC = n ln(RSS / n) + k ln
//   n.
// Only differences between fits of the same data mean anything: the lowest is preferred.
struct InformationCriteria {
  int points = 0;         // n
  int parameters = 0;     // k = the law's parameters + 1
  double rss_mpa2 = 0.0;  // sum of squared residuals [MPa^2]
  double aic = 0.0;
  std::optional<double> aicc;  // empty when n <= k + 1
  double bic = 0.0;
};
// Throws std::invalid_argument for n < 1, a law's parameter count < 0 or an RSS that is not a
// finite number > 0 (an exact fit has no information criterion: ln 0).
InformationCriteria information_criteria(int points, int law_parameters, double rss_mpa2);

struct FittedParameter {
  std::string name;                      // "G", "J_lim", "alpha", "C10", "mu_1", "alpha_1", "N",
                                         // "beta"
  std::string unit;                      // "MPa" or "" (dimensionless)
  std::optional<double> value;           // empty when the data do not give one (J_lim, c <= 0)
  std::optional<double> standard_error;  // sigma sqrt((J^T J)^-1)_ii; empty when singular
  // The data determine the parameter: value and standard error exist and the value is more
  // than two standard errors from zero (relative error below 50 %; for Gent's c = 1/J_lim: the
  // data tell Gent from neo-Hookean at about 95 %).
  bool identifiable = false;
  std::string note;  // why not identifiable, or what the value means
};

// status: Converged; OnBound (the best fit inside the law's range is on its edge: the law does
// not describe the data; the parameters are that edge's); NoConvergence (message: the
// optimiser's stop reason).
struct UniaxialFit : Outcome {
  FitLaw law = FitLaw::Gent;
  StressTest test = StressTest::Uniaxial;
  // The best fit as a material the solver accepts; empty when it is not one (Gent with
  // c = 1/J_lim <= 0, Mooney-Rivlin alpha outside [0, 1), G <= 0).
  std::optional<Material> material;
  // G first (Yeoh: C10, C20, C30 [MPa]; Ogden: mu_1..mu_N [MPa], then alpha_1..alpha_N).
  std::vector<FittedParameter> parameters;
  // Correlation coefficients between `parameters` (row i, column j), from the covariance
  // sigma^2 (J^T J)^-1 (for J_lim = 1/c and N = 1/(1/N) to first order: the sign of c's
  // correlations turns).  Empty when J^T J is singular.
  std::vector<std::vector<double>> correlation;
  // AIC, AICc, BIC of the fit (empty for an exact fit, RSS = 0).
  std::optional<InformationCriteria> information;
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
  int max_iterations = 500;                // Levenberg-Marquardt steps (a fit takes 5-30)
  StressTest test = StressTest::Uniaxial;  // the test the data are the nominal stress of
  // Ogden: the starting exponents alpha_p; their count is the number of terms N (1 to 3), and
  // each alpha_p keeps its sign (mu_p alpha_p > 0, |alpha_p| >= 1: the law's conditions).
  // Empty: ogden_terms terms from {2}, {3, -2} or Ogden's {1.3, 5, -2}.
  std::vector<double> ogden_alpha_start{};
  int ogden_terms = 3;  // 1 to 3; used when ogden_alpha_start is empty
};

// Needs more points than parameters, stretches > 0 and a positive stress somewhere; throws
// std::invalid_argument otherwise.  The parameters stay inside the law's validity range (G > 0,
// Mooney-Rivlin 0 <= alpha <= 1, Gent 0 <= 1/J_lim < 1/(I1 - 3) at the largest stretch); a
// best fit on one of these bounds is Status::OnBound, its message says which and why.
UniaxialFit fit_uniaxial(const std::vector<UniaxialPoint>& data, FitLaw law,
                         const UniaxialFitOptions& options = {});
// Every law of `laws` fitted to the same data, ranked by AIC (lowest first; fits without one,
// not converged or exact, last, in the order given).  Throws as fit_uniaxial for data that no law
// of the list can be fitted to (too few points for the one with most parameters).
std::vector<UniaxialFit> compare_uniaxial_fits(const std::vector<UniaxialPoint>& data,
                                               const std::vector<FitLaw>& laws,
                                               const UniaxialFitOptions& options = {});

std::string to_string(FitLaw law);
std::string to_string(StressTest test);
// The law of a name as to_string writes it ("gent", "ogden", ...); throws InvalidInput ("law")
// naming the laws for another.
FitLaw fit_law_of(const std::string& name);
std::string to_string(HoleMethod method);

}  // namespace puncture
