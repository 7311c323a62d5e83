#pragma once
// Least-squares fit of the model to measured force-depth records of indentation tests
// (Ceres' bounded Levenberg-Marquardt; docs/model.md "Fitting force-depth curves").
//
//   CurveFitProblem  the tests: each a Problem (geometry, probe, lubrication, fixed parameters)
//                    with its measured (depth, force) points and, when the record runs to
//                    perforation, the measured puncture point
//   CurveFitOptions  which parameters are free (shared by every test), their bounds, the loss
//   CurveFit         estimates, standard errors, 95 % intervals, correlations, residuals
//
// The residuals are the model's force at each measured depth (one loading curve per test,
// evaluated at exactly the measured depths) minus the measured force [N]; with a puncture
// point, also the predicted puncture force and depth minus the measured ones, each over its
// standard deviation.  Inputs in mm, N and MPa.  Invalid input throws InvalidInput naming the
// test, point or parameter; a record the model cannot describe is a Status, never a number.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "puncture/options.hpp"
#include "puncture/outcome.hpp"
#include "puncture/problem.hpp"

namespace puncture {

// A parameter the fit can determine.  The shear modulus scales the force (F = 2 pi G H A f);
// J_lim (Gent) and the friction shape the curve; the critical I1 sets only where it ends (the
// puncture point); the stick threshold where the membrane starts to slide (the residuals are a
// step function of it: fitted by a profile over where the switch falls, not by gradients).
// The contact offset is each test's own: the model's depth is the measured depth minus it (a
// contact point found late by the record's reader is a negative offset).
enum class CurveParameter {
  ShearModulus,
  JLim,
  Friction,
  CriticalI1,
  StickThreshold,
  ContactOffset
};

// "shear-modulus", "jlim", "friction", "critical-i1", "stick-threshold", "contact-offset" (as on
// the command line).
std::string to_token(CurveParameter parameter);
std::optional<CurveParameter> curve_parameter_from_token(std::string_view token);
// Every token, comma-separated, for messages.
std::string curve_parameter_tokens();
// "MPa", "", "", "", the stick rule's unit (N, mm, N/mm), or "mm" (contact offset).
std::string unit_of(CurveParameter parameter, const Problem& problem);
// The parameter's value in the problem (throws InvalidInput when the problem has none: J_lim
// without the Gent law, a stick threshold without a threshold rule, the contact offset, which
// belongs to a test's record: CurveTest::contact_offset_mm).
double value_of(CurveParameter parameter, const Problem& problem);
void set_value(CurveParameter parameter, Problem& problem, double value);

struct MeasuredPuncture {
  double depth_mm = 0.0;  // depth at perforation (the last point before the force drops) [mm]
  double force_n = 0.0;   // force at perforation [N]
};

struct CurveTest {
  std::string name;  // names the test in messages and reports (e.g. its file)
  // Everything but the free parameters, whose values here are ignored (the first test's are the
  // starting point of the fit).
  Problem problem;
  std::vector<double> depth_mm;  // measured depths from the contact point, > 0, non-decreasing
  std::vector<double> force_n;   // measured force at each depth [N]
  std::optional<MeasuredPuncture> puncture;
  // The model's depth is depth_mm - contact_offset_mm (a point at a model depth <= 0 has no
  // force); the starting value when contact-offset is free [mm].
  double contact_offset_mm = 0.0;
};

struct CurveFitProblem {
  std::vector<CurveTest> tests;
};

struct ParameterBounds {
  CurveParameter parameter = CurveParameter::ShearModulus;
  double lower = 0.0;
  double upper = 0.0;
};

enum class RobustLoss { None, Huber, Cauchy };

struct CurveFitOptions {
  std::vector<CurveParameter> free;     // the fitted parameters (contact-offset: one per test)
  std::vector<ParameterBounds> bounds;  // overrides of the default bounds (default_bounds)
  RobustLoss loss = RobustLoss::None;   // on the curve residuals (ceres::HuberLoss, CauchyLoss)
  double loss_scale_n = 0.0;            // the loss's scale [N]; needed with a robust loss
  // Standard deviation of a measured puncture point, as a fraction of its value: the scatter of
  // puncture between nominally equal tests (a few %), far above the force noise of one record.
  double puncture_force_sd_fraction = 0.05;
  double puncture_depth_sd_fraction = 0.05;
  int max_iterations = 100;  // Levenberg-Marquardt steps, successful or not
  // Ceres' stops: a relative decrease of the cost below function_tolerance, or a relative step
  // below parameter_tolerance.  At the optimum the model's own noise (~1e-9 relative in the
  // force) makes the cost wander along a correlated valley: below 1e-8 the steps only dither
  // there (measured, G, J_lim and friction from one record: 4 steps and 30 curves at 1e-8, 16
  // steps and 135 curves at 1e-10, the estimates 1e-5 relative apart, ~1e-3 standard errors).
  double function_tolerance = 1e-8;
  double parameter_tolerance = 1e-9;
  // Central differences of the model in every parameter but the shear modulus (exact: the force
  // is proportional to it), with step relative_step max(|x|, typical scale).  The curve is
  // accurate to ~1e-9 relative, so 1e-3 balances truncation (~step^2) and noise (~1e-9 / step)
  // at ~1e-6 relative in the derivative.
  double relative_step = 1e-3;
  // Below this share of the force variance explained (R^2) the data are not a curve of the
  // model: Status::OutsideModel instead of Converged.
  double min_r_squared = 0.9;
  SolverOptions solver{};  // record_fields is switched off
};

// The bounds used when CurveFitOptions::bounds does not give them: G in [1e-6, 1e3] MPa, J_lim
// in (critical I1 - 3, 1e6], friction in [0, 10], critical I1 in (3, 1e4], a stick threshold in
// (0, 1e6], a contact offset in [-1e3, 1e3] mm (fit_curves narrows it to -+ half of each test's
// deepest measured depth).
ParameterBounds default_bounds(CurveParameter parameter, const Problem& problem);

struct FittedCurveParameter {
  CurveParameter parameter = CurveParameter::ShearModulus;
  std::string name;  // token, e.g. "jlim"
  std::string unit;  // e.g. "MPa", "" when dimensionless
  std::string test;  // the test of a per-test parameter (contact-offset); empty when shared
  double value = 0.0;
  // Empty when the covariance is rank-deficient, and for the stick threshold (a profile).
  std::optional<double> standard_error;
  // 95 % interval, value -+ t(0.975, n - p) se; for the stick threshold (profile_interval) the
  // thresholds at which the profile of the cost (the others re-fitted) rises by chi2(0.95, 1).
  std::optional<double> ci_lower;
  std::optional<double> ci_upper;
  bool profile_interval = false;
  bool on_bound = false;
  bool identifiable = true;
  std::string note;  // why not identifiable, and which test would identify it
};

struct CurveTestFit {
  std::string name;
  std::vector<double> depth_mm;       // the fitted points
  std::vector<double> force_n;        // measured
  std::vector<double> model_force_n;  // the fitted model at each depth
  std::vector<double> residual_n;     // model - measured
  double rms_residual_n = 0.0;
  std::optional<MeasuredPuncture> measured_puncture;
  std::optional<MeasuredPuncture> model_puncture;  // predicted at the fitted parameters
};

// status: Converged; OnBound (a parameter ends on a bound: the data want a value outside the
// range; message: which); OutsideModel (the fit explains less than min_r_squared of the force
// variance: the data are not a curve of this model); NoConvergence (message: why), also when
// the model fails at the starting point.
struct CurveFit : Outcome {
  // The shared parameters in CurveFitOptions::free order, then each test's contact offset.
  std::vector<FittedCurveParameter> parameters;
  // Empty when the covariance is rank-deficient; the stick threshold's row and column are 0 (its
  // interval is a profile, in which the others are re-fitted).
  std::vector<std::vector<double>> correlation;
  std::vector<CurveTestFit> tests;
  std::vector<std::string> warnings;  // not identifiable, |r| > 0.99, on a bound
  double residual_sd_n = 0.0;         // sqrt(sum r^2 / (n - p)) over the curve residuals
  double r_squared = 0.0;             // 1 - sum r^2 / sum (F - mean F)^2, pooled over the tests
  int points = 0;                     // curve residuals
  int iterations = 0;
  int curve_evaluations = 0;             // loading curves solved
  std::vector<Problem> fitted_problems;  // each test's problem at the estimates
};

// The stick threshold (one test, not with contact-offset; alone, a place is the curve): for each
// place of the switch between two measured depths the others are fitted with the switch there
// (a grid, then a Brent search over the place, the cost a step function of it); the estimate is the
// middle of the thresholds that put the switch between the best two depths, its interval the
// thresholds over which the cost rises by at most chi2(0.95, 1) = 3.84 residual variances, widened
// by 1.96 standard errors of the threshold at its ends from the other parameters' covariance.
// Throws InvalidInput: no test or no free parameter, a parameter twice, stick-threshold free
// with several tests or with contact-offset, a parameter the problems do not have (J_lim
// without Gent), the critical I1 free without a puncture point, a test with fewer points than free
// parameters + 1, mismatched lengths, a depth that is not finite and > 0 or decreases, a force that
// is not finite, bounds that are not finite with lower < upper, an invalid problem or options.  The
// start is clamped into the bounds.
CurveFit fit_curves(const CurveFitProblem& problem, const CurveFitOptions& options);

std::string to_string(RobustLoss loss);

}  // namespace puncture
