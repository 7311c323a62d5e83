#pragma once
// `puncture sweep SPEC.toml -o results.csv`: many problems, one CSV row each
// (sweep/spec_file.hpp describes the spec; sweep/rows_csv.hpp the columns).
#include <CLI/CLI.hpp>
#include <string>

#include "output_options.hpp"

namespace puncture::cli {

struct SweepFlags {
  CLI::App* command = nullptr;
  std::string spec_path;
  int threads = 0;  // 0: every core
  bool resume = false;
  bool quiet = false;
  bool statistics = false;

  bool parsed() const { return command && command->parsed(); }
};

// Registers `sweep` on `app`.
void add_sweep_command(CLI::App& app, SweepFlags& flags);

// The flags `sweep` takes besides its own: --output (required) and --format csv.  The problem's
// flags belong in the spec: refused on the command line (and in --config).  Throws InputError.
void check_sweep_flags(const CLI::App& app, const OutputFlags& output);

// Runs the parsed sweep (the rows go to --output; `app` is asked which other flags were given:
// the problem's belong in the spec).  Returns the exit code.
int run_sweep(const CLI::App& app, const SweepFlags& flags, const OutputFlags& output);

}  // namespace puncture::cli
