#pragma once
// Pieces shared by the writers of the calibration results (critical_i1_output.cpp,
// friction_output.cpp, jlim_output.cpp, uniaxial_fit_output.cpp, band_output.cpp): numbers and
// lines of the summaries, the physical inputs, the inversions; and the writers each of those
// files defines for its report, which calibration_text (common_output.cpp) dispatches to.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "calibration_output.hpp"
#include "finite.hpp"
#include "json_helpers.hpp"
#include "puncture/calibration.hpp"
#include "puncture/problem.hpp"

namespace puncture::cli::calibration {

// ----- shared helpers -------------------------------------------------------------------------

std::string num_or(const std::optional<double>& x, std::string_view what,
                   std::string_view missing = "n/a");

void line(std::string& out, std::string_view label, std::string_view value);

// About `shown` evenly spaced rows, always the first and the last.
std::vector<std::size_t> sampled_rows(std::size_t n, std::size_t shown);

// The physical inputs; `calibrated` ("friction" or "jlim") is left out.
void problem_lines(std::string& out, const Problem& p, std::string_view calibrated);

std::optional<double> value_of(const Inversion& i);

json inversion_json(const Inversion& i, std::string_view what);

// "1.9923", or "not found: <why>"; a warning on a found value is kept.
std::string inversion_text(const Inversion& i, std::string_view what);

// ----- the writers of each calibration: readable summary, CSV and JSON --------------------------

// critical_i1_output.cpp
std::string summary(const CriticalI1Report& r);
std::string csv_text(const CriticalI1Report& r);
std::string json_text(const CriticalI1Report& r);

// friction_output.cpp
std::string summary(const FrictionReport& r);
std::string csv_text(const FrictionReport& r);
std::string json_text(const FrictionReport& r);

// jlim_output.cpp
std::string summary(const JLimReport& r);
std::string csv_text(const JLimReport& r);
std::string json_text(const JLimReport& r);

// uniaxial_fit_output.cpp
std::string summary(const UniaxialFitReport& r);
std::string csv_text(const UniaxialFitReport& r);
// Pieces of a fit that the comparison's writers share: "G = 0.06 +- 0.001 MPa"; the flags
// that give the fitted material to the model (empty without one); the correlation and the
// information-criteria lines; the fit's JSON object and the specimen's.
std::string parameter_text(const FittedParameter& p);
std::string model_flags(const UniaxialFit& fit);
void statistics_lines(std::string& out, const UniaxialFit& fit);
json fit_json(const UniaxialFit& fit);
json specimen_json(const std::optional<SpecimenGeometry>& specimen);
std::string json_text(const UniaxialFitReport& r);

// uniaxial_comparison_output.cpp
std::string summary(const UniaxialComparisonReport& r);
std::string csv_text(const UniaxialComparisonReport& r);
std::string json_text(const UniaxialComparisonReport& r);

// band_output.cpp
std::string summary(const BandReport& r);
std::string csv_text(const BandReport& r);
std::string json_text(const BandReport& r);

}  // namespace puncture::cli::calibration
