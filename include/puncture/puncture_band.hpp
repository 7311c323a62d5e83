#pragma once
// The puncture force and depth a problem's calibrated parameters allow: the prediction at the
// nominal values, its band over intervals of critical I1, friction mu', Gent J_lim and shear
// modulus G (mean +- sd, or lower and upper ends), and which parameter moves it most.
//
// How each parameter moves the predicted puncture (docs/model.md, "Calibration"; checked by
// tests/calibration/puncture_band_test.cpp):
//
//   parameter    force   depth
//   critical I1   up      up       the same loading path, followed further
//   friction mu'  up      up       the capstan holds more at the corner: Part III stretches less
//   J_lim         down    down     less Gent stiffening: lower stresses at the critical I1
//   G             up      none     F is proportional to G, the depth does not depend on it
//
// The band is the least and the largest value over every corner of the box of intervals (2^k
// solves for k parameters).  Along each interval, through the nominal point, the prediction is
// also sampled to check that it is monotone there: with every parameter monotone and the
// extreme corners where the directions above put them, the corners bound the whole box.
// Solver failures are reported with the evaluation where they happened, never left out
// silently: `complete` is false and `warnings` says where.
#include <optional>
#include <string>
#include <vector>

#include "puncture/options.hpp"
#include "puncture/outcome.hpp"
#include "puncture/problem.hpp"

namespace puncture {

enum class BandParameter { CriticalI1, Friction, JLim, ShearModulus };

// "critical_i1", "friction", "j_lim", "shear_modulus_mpa": the names used in CSV and JSON.
std::string to_token(BandParameter parameter);
// "critical I1", "friction mu'", "J_lim", "G": for text.
std::string to_string(BandParameter parameter);

// The documented direction in which the parameter moves the puncture force (+1 up, -1 down)
// and depth (+1, -1, or 0: no effect), as in the table above.
int documented_force_direction(BandParameter parameter);
int documented_depth_direction(BandParameter parameter);

struct ParameterRange {
  double lower = 0.0;
  double upper = 0.0;
};

// [mean - k sd, mean + k sd].
ParameterRange plus_minus(double mean, double sd, double k = 1.0);

// The intervals; a parameter without one keeps the problem's value.  Each must contain the
// problem's (nominal) value.
struct BandRanges {
  std::optional<ParameterRange> critical_i1;
  std::optional<ParameterRange> friction;
  std::optional<ParameterRange> j_lim;  // the Gent law only
  std::optional<ParameterRange> shear_modulus_mpa;
  // The interval of `parameter`.
  std::optional<ParameterRange>& of(BandParameter parameter);
  const std::optional<ParameterRange>& of(BandParameter parameter) const;
};

struct BandOptions {
  // Points along each interval, its ends included, where the one-at-a-time prediction is
  // evaluated to check its monotonicity (the nominal value is added when inside); >= 2.
  int samples_per_range = 5;
  SolverOptions solver{};  // record_fields is switched off
};

// The four parameters of one evaluation (j_lim empty when the law is not Gent).
struct BandParameters {
  double critical_i1 = 0.0;
  double friction = 0.0;
  std::optional<double> j_lim;
  double shear_modulus_mpa = 0.0;
  double value(BandParameter parameter) const;  // j_lim: 0 when empty
};

// The problem's values of the four parameters: the nominal point of a band.
BandParameters band_parameters(const Problem& problem);

// `problem` with one of the four parameters set to `value` (J_lim: the Gent law's).
Problem with_band_parameter(Problem problem, BandParameter parameter, double value);

// One predicted puncture (predict_puncture) at one parameter set.
struct BandEvaluation : Outcome {  // of predict_puncture at these parameters
  BandParameters parameters;
  double force_n = 0.0;
  double depth_mm = 0.0;
  double part_three_stretch = 1.0;
  std::string crack_location;
};

// One parameter varied over its interval, the others at their nominal values.
struct ParameterSensitivity {
  BandParameter parameter = BandParameter::CriticalI1;
  double nominal = 0.0;
  ParameterRange range;
  BandEvaluation at_lower;
  BandEvaluation at_upper;
  std::vector<BandEvaluation> samples;  // along the interval in increasing value, ends included
  // F(upper) - F(lower) and depth(upper) - depth(lower), when both were found.
  std::optional<double> force_change_n;
  std::optional<double> depth_change_mm;
  // Direction seen at the ends: +1, -1, or 0 when the change is within the solver's accuracy
  // (or the interval has zero width); empty when an end failed.
  std::optional<int> force_direction;
  std::optional<int> depth_direction;
  // Every sample found and the sequence monotone (non-decreasing or non-increasing, up to the
  // solver's accuracy).
  bool force_monotone = false;
  bool depth_monotone = false;
  // force_change_n^2 / the sum of them over the parameters: the parameter's part of the
  // first-order variance of the force (when every change was found and some is non-zero).
  std::optional<double> force_variance_share;
};

// ok() when every evaluation found a puncture point; else Incomplete, the message naming them.
struct PunctureBand : Outcome {
  BandEvaluation nominal;
  std::vector<ParameterSensitivity> sensitivities;  // critical I1, friction, J_lim, G: those given
  std::vector<BandEvaluation> corners;              // every corner of the box of intervals
  // Over the nominal point and every corner that was found; empty when none was.
  std::optional<double> force_min_n, force_max_n;
  std::optional<double> depth_min_mm, depth_max_mm;
  // The corners (indices into `corners`) with the least and the largest force and depth.
  std::optional<std::size_t> force_min_corner, force_max_corner;
  std::optional<std::size_t> depth_min_corner, depth_max_corner;
  // First-order spread of the force, sqrt(sum (force_change_n / 2)^2): with mean +- sd
  // intervals of independent parameters, the standard deviation of the force to first order.
  std::optional<double> force_half_range_rss_n;
  // The parameter whose interval moves the force most (largest |force_change_n|).
  std::optional<BandParameter> dominant;
  // Every sensitivity is monotone, moves the force as documented, and the extreme force
  // corners are those the documented directions give.
  bool consistent_with_documented_directions = false;
  std::vector<std::string> warnings;  // solver failures, non-monotone or unexpected directions
};

// Throws std::invalid_argument when the problem is invalid, a range is not finite, has
// lower > upper or does not contain the problem's value, a J_lim range is given for another
// law, or a corner of the box is not a valid problem (e.g. a critical I1 beyond 3 + J_lim):
// each message names the parameter and the end.
PunctureBand puncture_band(const Problem& problem, const BandRanges& ranges,
                           const BandOptions& options = {});

}  // namespace puncture
