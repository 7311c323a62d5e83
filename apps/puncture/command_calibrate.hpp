#pragma once
// `calibrate critical-i1|friction|jlim` and `fit uniaxial`: the model's parameters from the
// paper's experiments (include/puncture/calibration.hpp); `calibrate band`: the puncture band
// their uncertainties give (include/puncture/puncture_band.hpp).
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "command_fit_curve.hpp"
#include "output_options.hpp"
#include "problem_options.hpp"

namespace puncture::cli {

struct CalibrationFlags {
  CLI::App* calibrate = nullptr;
  CLI::App* fit = nullptr;

  // calibrate critical-i1
  CLI::App* critical_i1 = nullptr;
  double mark_radius_mm = 0.0;
  std::vector<double> burst_radii_mm;
  std::string burst_data;
  bool pole_only = false;      // the paper's estimate: I1 at the pole, without the membrane's law
  std::string measure = "i1";  // --measure: the criterion whose critical value is calibrated
  CLI::Option* mark_radius_option = nullptr;

  // calibrate friction, calibrate jlim
  CLI::App* friction = nullptr;
  CLI::App* jlim = nullptr;
  double puncture_force_n = 0.0;
  double puncture_force_sd_n = 0.0;
  double hole_ratio = 0.0;
  double hole_ratio_sd = 0.0;
  double critical_i1_sd = 0.0;
  CLI::Option* friction_force_option = nullptr;

  // calibrate band: per parameter (critical I1, friction, J_lim, G) an sd or a LO,HI range
  CLI::App* band = nullptr;
  double band_sd[4] = {0.0, 0.0, 0.0, 0.0};
  std::vector<double> band_range[4];
  CLI::Option* band_sd_option[4] = {nullptr, nullptr, nullptr, nullptr};
  CLI::Option* band_range_option[4] = {nullptr, nullptr, nullptr, nullptr};
  double band_sd_multiple = 1.0;
  CLI::Option* band_sd_multiple_option = nullptr;
  int band_samples = 5;
  std::string band_method = "corners";  // or monte-carlo (calibration/band_monte_carlo.hpp)
  std::uint64_t band_seed = 1;

  // fit uniaxial
  CLI::App* uniaxial = nullptr;
  std::string uniaxial_data;
  double specimen_width_mm = 0.0;
  double specimen_thickness_mm = 0.0;
  double gauge_length_mm = 0.0;
  std::vector<CLI::Option*> specimen_options;
  std::string fit_test = "uniaxial";  // or equibiaxial: which nominal stress the data are
  int ogden_terms = 3;
  CLI::Option* ogden_terms_option = nullptr;
  std::vector<std::string> compare_laws;  // --compare: law names, or "all"
  CLI::Option* compare_option = nullptr;

  FitCurveFlags curve;  // fit curve

  bool parsed() const { return calibrate->parsed() || fit->parsed(); }
};

// Registers `calibrate` (with critical-i1, friction, jlim, band) and `fit` (with uniaxial) on
// `app`.
void add_calibration_commands(CLI::App& app, CalibrationFlags& flags);

// Runs the parsed calibration and returns its output text.  `app` is asked which shared flags
// were given (e.g. --friction is refused by `calibrate friction`, which determines it).
std::string run_calibration(const CLI::App& app, const ProblemFlags& problem,
                            const CalibrationFlags& flags, Format format);

}  // namespace puncture::cli
