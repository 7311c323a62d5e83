#pragma once
// `puncture inflate`: the inflation (bulge) test of the clamped membrane under a uniform
// pressure (include/puncture/inflation.hpp): the curve from flat to the burst, the state at a
// pole stretch, or every state at a pressure.
#include <CLI/CLI.hpp>
#include <string>

#include "commands.hpp"
#include "output_options.hpp"
#include "problem_options.hpp"

namespace puncture::cli {

struct InflateFlags {
  CLI::App* command = nullptr;
  double pressure_mpa = 0.0;
  double pole_stretch = 1.0;
  double max_pole_stretch = 0.0;  // 0: to the burst
  int scan_points = 60;
  CLI::Option* pressure_option = nullptr;
  CLI::Option* pole_stretch_option = nullptr;

  bool parsed() const { return command && command->parsed(); }
};

// Registers `inflate` on `app`.
void add_inflate_command(CLI::App& app, InflateFlags& flags);

// Runs the parsed `inflate` and returns its output text.  `app` is asked which shared flags
// were given: the indenter's and the contact's do not apply.  `curve` supplies --points.
std::string run_inflate(const CLI::App& app, const ProblemFlags& problem, const CurveFlags& curve,
                        const InflateFlags& flags, Format format);

}  // namespace puncture::cli
