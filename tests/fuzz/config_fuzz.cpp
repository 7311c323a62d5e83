// Fuzz target of the --config reader: the program's physical, curve, output and [state] flags read
// from a TOML/INI text through StrictConfig and CLI11, then made into a Problem as the CLI does.
// Any input either gives a valid problem or is refused with a CLI11 parse error or an InputError
// naming a flag; anything else (another exception, a crash, a sanitizer finding) is a finding.
#include <CLI/CLI.hpp>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <sstream>
#include <string>

#include "cli_error.hpp"
#include "commands.hpp"
#include "output_options.hpp"
#include "problem_options.hpp"
#include "strict_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace puncture::cli;
  CLI::App app{"config fuzz", "puncture"};
  app.set_config("--config");
  app.allow_config_extras(CLI::config_extras_mode::error);
  app.config_formatter(std::make_shared<StrictConfig>(app));
  app.fallthrough();
  ProblemFlags problem_flags;
  CurveFlags curve_flags;
  OutputFlags output_flags;
  StateFlags state_flags;
  add_problem_options(app, problem_flags);
  add_curve_options(app, curve_flags);
  add_output_options(app, output_flags);
  add_state_options(*app.add_subcommand("state"), state_flags);
  std::istringstream config(std::string(reinterpret_cast<const char*>(data), size));
  try {
    app.parse_from_stream(config);
    make_problem(problem_flags);
    format_of(output_flags);
  } catch (const CLI::ParseError&) {
  } catch (const InputError&) {
  }
  return 0;
}
