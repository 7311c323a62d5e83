// "Did you mean" for misspelt flags and config keys.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace puncture::cli {

// Every long option name (without "--") of the program and of its subcommands.
std::vector<std::string> long_option_names(const CLI::App& app);

// The closest of `candidates` to `word` when it is a plausible misspelling (an edit distance of
// at most a third of the word's length, and at least 1); none otherwise.
std::optional<std::string> closest_name(const std::string& word,
                                        const std::vector<std::string>& candidates);

// The option with that long name (without "--") in the program or a subcommand, and the
// subcommand that holds it ("" for the program itself); none when no command has it.
std::optional<std::string> command_holding(const CLI::App& app, const std::string& name);

// For each argument of argv that looks like a long flag no command knows: "--frction: unknown
// flag (did you mean --friction?)"; empty when every flag is known.
std::string unknown_flags_report(const CLI::App& app, int argc, const char* const* argv);

}  // namespace puncture::cli
