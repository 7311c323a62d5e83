#pragma once
// `puncture verify`: the shooting solver's results for the user's membrane checked against
// independent methods (include/puncture/verification.hpp), as a table with verdicts.
#include <CLI/CLI.hpp>
#include <string>

#include "output_options.hpp"
#include "puncture/problem.hpp"

namespace puncture::cli {

// A check outside its tolerance, or one that could not be made: the output is written, then the
// program exits with this.
inline constexpr int kExitVerificationFailed = 4;

struct VerifyFlags {
  CLI::App* command = nullptr;
  int elements = 128;
  int depths = 4;
  bool parsed() const { return command && command->parsed(); }
};

void add_verify_command(CLI::App& app, VerifyFlags& flags);

struct VerifyOutcome {
  std::string text;
  bool passed = true;
  int failed = 0;
  std::string message;  // why not passed
};

VerifyOutcome run_verify(const Problem& problem, const VerifyFlags& flags, Format format);

}  // namespace puncture::cli
