#pragma once
// The subcommands.  Each registers its own flags and returns the complete output text.
#include <CLI/CLI.hpp>
#include <string>

#include "output_options.hpp"
#include "puncture/problem.hpp"

namespace puncture::cli {

// `curve` (the default): the loading curve from zero depth to puncture.
struct CurveFlags {
  int points = 200;
  double max_depth_mm = 0.0;  // 0: to puncture
};
void add_curve_options(CLI::App& app, CurveFlags& flags);
// `test`: the --test the problem was set up for ("none", or a standard whose outputs the report
// adds, standard_test.hpp); likewise for run_puncture.
std::string run_curve(const Problem& problem, const CurveFlags& flags, Format format,
                      const std::string& test = "none");

// `state`: one equilibrium at a force or a depth.
struct StateFlags {
  double force_n = 0.0;
  double depth_mm = 0.0;
  std::string stage = "auto";
  CLI::Option* force_option = nullptr;
  CLI::Option* depth_option = nullptr;
};
void add_state_options(CLI::App& state, StateFlags& flags);
std::string run_state(const Problem& problem, const StateFlags& flags, Format format);

// `puncture`: the predicted puncture point alone.
std::string run_puncture(const Problem& problem, Format format, const std::string& test = "none");

}  // namespace puncture::cli
