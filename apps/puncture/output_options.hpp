#pragma once
// --format and --output: how and where the finished result is written.
#include <CLI/CLI.hpp>
#include <string>

namespace puncture::cli {

enum class Format { Summary, Csv, Json };

struct OutputFlags {
  std::string format = "summary";
  std::string path;  // empty: standard output
};

void add_output_options(CLI::App& app, OutputFlags& flags);

Format format_of(const OutputFlags& flags);

// Fails early (InputError naming --output) when the output file cannot be created, before a
// long computation; leaves no new file behind.
void check_writable(const OutputFlags& flags);

// Writes the complete text to --output, or to stdout.  Throws InputError when the file cannot
// be written.  Called once, after every number has been checked, so a failure writes nothing.
void write_output(const OutputFlags& flags, const std::string& text);

}  // namespace puncture::cli
