#pragma once
// What the calibration commands computed, and their summary, CSV and JSON writers.  Every
// number written is checked finite (SolveError otherwise); a missing value is "n/a" in the
// summary, an empty cell in CSV and null in JSON.  The writers are in calibration/, one file per
// calibration and common_output.cpp for what they share.
#include <optional>
#include <string>
#include <vector>

#include "output_options.hpp"
#include "puncture/calibration.hpp"
#include "puncture/problem.hpp"
#include "puncture/puncture_band.hpp"

namespace puncture::cli {

struct CriticalI1Report {
  std::string source;  // "--burst-radii" or the CSV file
  std::vector<BurstTest> tests;
  std::optional<MaterialLaw> law;  // the membrane solved; none: the pole's I1 (--pole-only)
  CriticalI1Estimate estimate;
};

struct FrictionReport {
  Problem problem;  // its friction is what is calibrated
  HoleMeasurement hole;
  std::optional<FrictionEstimate> at_measured_force;  // with a measured force
  FrictionEstimate at_predicted_puncture;
};

struct JLimReport {
  Problem problem;  // Gent; its J_lim is what is calibrated
  double force_n = 0.0;
  std::optional<double> force_sd_n;
  std::optional<double> critical_i1_sd;
  JLimEstimate estimate;
  std::optional<JLimEstimate> force_plus_sd, force_minus_sd;  // with a force sd
  std::optional<JLimEstimate> i1_plus_sd, i1_minus_sd;        // with a critical I1 sd
};

struct UniaxialFitReport {
  std::string source;                        // the CSV file
  std::optional<SpecimenGeometry> specimen;  // when the data are forces and displacements
  std::vector<UniaxialPoint> data;
  UniaxialFit fit;  // converged
};

// `fit uniaxial --compare`: every law of the list fitted to the same data, ranked by AIC.
struct UniaxialComparisonReport {
  std::string source;
  std::optional<SpecimenGeometry> specimen;
  std::vector<UniaxialPoint> data;
  StressTest test = StressTest::Uniaxial;
  std::vector<UniaxialFit> fits;  // compare_uniaxial_fits: lowest AIC first
};

struct BandReport {
  Problem problem;  // the nominal parameters
  BandRanges ranges;
  // The standard deviation each range came from (mean +- sd_multiple sd), when it did; in the
  // order of BandParameter.
  std::optional<double> sd[4];
  double sd_multiple = 1.0;
  PunctureBand band;
};

std::string calibration_text(const CriticalI1Report& report, Format format);
std::string calibration_text(const FrictionReport& report, Format format);
std::string calibration_text(const JLimReport& report, Format format);
std::string calibration_text(const UniaxialFitReport& report, Format format);
std::string calibration_text(const UniaxialComparisonReport& report, Format format);
std::string calibration_text(const BandReport& report, Format format);

}  // namespace puncture::cli
