#include "output_options.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli_error.hpp"

namespace puncture::cli {

void add_output_options(CLI::App& app, OutputFlags& f) {
  constexpr const char* kOutput = "Output";
  app.add_option("--format",
                 f.format,
                 "summary: readable report with units; csv: one table with units\n"
                 "in the column names; json: every fact, machine-readable")
      ->group(kOutput)
      ->check(CLI::IsMember({"summary", "csv", "json"}))
      ->capture_default_str();
  app.add_option("--output,-o", f.path, "Write the result to FILE instead of standard output")
      ->group(kOutput)
      ->type_name("FILE");
}

Format format_of(const OutputFlags& f) {
  if (f.format == "csv") return Format::Csv;
  if (f.format == "json") return Format::Json;
  return Format::Summary;
}

void check_writable(const OutputFlags& f) {
  if (f.path.empty()) return;
  std::error_code ec;
  const bool existed = std::filesystem::exists(f.path, ec);
  {
    std::ofstream probe(f.path, std::ios::app);
    if (!probe)
      throw InputError(
          fmt::format("--output: cannot open '{}' for writing: {}", f.path, std::strerror(errno)));
  }
  if (!existed) std::filesystem::remove(f.path, ec);
}

void write_output(const OutputFlags& f, const std::string& text) {
  if (f.path.empty()) {
    std::cout << text << std::flush;
    if (!std::cout) throw InputError("cannot write to standard output");
    return;
  }
  std::ofstream file(f.path, std::ios::binary);
  if (!file)
    throw InputError(
        fmt::format("--output: cannot open '{}' for writing: {}", f.path, std::strerror(errno)));
  file << text;
  file.close();
  if (!file) throw InputError(fmt::format("--output: cannot write '{}'", f.path));
}

}  // namespace puncture::cli
