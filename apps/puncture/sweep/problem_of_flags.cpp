#include "problem_of_flags.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>

#include "cli_error.hpp"
#include "problem_options.hpp"

namespace puncture::cli {

namespace {

std::string describe(const std::vector<std::string>& names, const SweepPoint& point) {
  std::vector<std::string> pairs;
  for (std::size_t j = 0; j < names.size(); ++j)
    pairs.push_back(fmt::format("{} = {}", names[j], point.texts[j]));
  return fmt::format("sweep point {} ({})", point.index, fmt::join(pairs, ", "));
}

}  // namespace

ProblemOfPoint problem_of_flags(const SweepSpec& spec,
                                std::vector<std::pair<std::string, std::string>> fixed) {
  std::vector<std::string> names;
  for (const SweepParameter& p : spec.parameters) names.push_back(p.name);
  return [names, fixed = std::move(fixed)](const SweepPoint& point) {
    CLI::App app;
    ProblemFlags flags;
    add_problem_options(app, flags);
    // '--flag=value' keeps a value such as -0.1 from reading as a flag; CLI11 takes the
    // arguments last first.
    std::vector<std::string> args;
    for (const auto& [flag, value] : fixed) args.push_back(fmt::format("--{}={}", flag, value));
    for (std::size_t j = 0; j < names.size(); ++j)
      args.push_back(fmt::format("--{}={}", names[j], point.texts[j]));
    std::reverse(args.begin(), args.end());
    try {
      app.parse(args);
      return make_problem(flags);
    } catch (const CLI::ParseError& e) {
      throw InputError(fmt::format("{}: {}", describe(names, point), e.what()));
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", describe(names, point), e.what()));
    }
  };
}

}  // namespace puncture::cli
