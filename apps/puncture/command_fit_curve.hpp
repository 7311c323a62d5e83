#pragma once
// `puncture fit curve TEST.csv [TEST2.csv ...]`: the model fitted to measured force-depth
// records (include/puncture/curve_fit.hpp, force_depth_record.hpp).
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "output_options.hpp"
#include "problem_options.hpp"

namespace puncture::cli {

struct FitCurveFlags {
  CLI::App* app = nullptr;
  std::vector<std::string> files;
  std::string manifest;  // TOML: [[test]] tables with file = ... and per-test settings
  std::string free;      // comma-separated parameter names
  std::string depth_column = "depth_mm";
  std::string force_column = "force_n";
  std::string depth_unit = "mm";
  std::string force_unit = "N";
  std::string header = "auto";
  std::string separator = "auto";
  std::string decimal = "auto";
  double contact_depth = 0.0;
  CLI::Option* contact_depth_option = nullptr;
  double drop_fraction = 0.5;
  bool no_perforation_cut = false;
  bool ignore_puncture = false;
  double puncture_sd_fraction = 0.05;
  std::vector<std::string> bounds;  // NAME:LO:HI
  std::string loss = "none";
  double loss_scale_n = 0.0;
  double min_r_squared = 0.9;
};

void add_fit_curve_command(CLI::App& fit, FitCurveFlags& flags);

// The output text in `format`; with `json`, also the JSON output there (for --plot), without
// fitting twice.
std::string run_fit_curve(const ProblemFlags& problem, const FitCurveFlags& flags, Format format,
                          std::string* json = nullptr);

}  // namespace puncture::cli
