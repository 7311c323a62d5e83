#include "problem_of_flags.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <memory>

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

// Registering the problem's flags (add_problem_options) is three quarters of building a
// point's problem through them: each thread registers them once per 1024 points and parses each
// point from the defaults (a parse clears the previous one's results; `flags_ = defaults_` its
// values).  Renewed because CLI11 2.1 never clears an App's parse order: it keeps a pointer per
// flag parsed (3 MB over 10^5 two-flag points before the renewal).
class FlagParser {
 public:
  Problem problem_of(std::vector<std::string>& args) {
    if (parses_++ % kParsesPerApp == 0) renew();
    flags_ = defaults_;
    app_->parse(args);
    return make_problem(flags_);
  }

 private:
  static constexpr std::size_t kParsesPerApp = 1024;
  void renew() {
    app_ = std::make_unique<CLI::App>();
    flags_ = defaults_;  // the defaults (default-constructed at first)
    add_problem_options(*app_, flags_);
    defaults_ = flags_;  // the options' pointers included
  }
  std::unique_ptr<CLI::App> app_;
  ProblemFlags flags_, defaults_;
  std::size_t parses_ = 0;
};

// The probe shape a dimension flag belongs to, or null for the other flags.
const char* shape_of_dimension(const std::string& flag) {
  if (flag == "fillet-radius") return "flat";
  if (flag == "ball-radius") return "ball";
  if (flag == "cone-half-angle" || flag == "tip-radius") return "cone";
  return nullptr;
}

// With the indenter among the swept parameters, a fixed dimension describes one of the shapes
// (e.g. the cone's tip radius in a flat / sphere-tipped / cone grid): it applies to that shape's
// points only.  A fixed indenter keeps every dimension, so a mismatch is still refused.
bool applies_to_point(const std::string& flag, const std::vector<std::string>& names,
                      const SweepPoint& point) {
  const char* shape = shape_of_dimension(flag);
  if (!shape) return true;
  const auto swept = std::find(names.begin(), names.end(), "indenter");
  if (swept == names.end()) return true;
  return point.texts[static_cast<std::size_t>(swept - names.begin())] == shape;
}

}  // namespace

ProblemOfPoint problem_of_flags(const SweepSpec& spec,
                                std::vector<std::pair<std::string, std::string>> fixed) {
  std::vector<std::string> names;
  for (const SweepParameter& p : spec.parameters) names.push_back(p.name);
  return [names, fixed = std::move(fixed)](const SweepPoint& point) {
    thread_local FlagParser parser;
    // '--flag=value' keeps a value such as -0.1 from reading as a flag; CLI11 takes the
    // arguments last first.
    std::vector<std::string> args;
    for (const auto& [flag, value] : fixed)
      if (applies_to_point(flag, names, point)) args.push_back(fmt::format("--{}={}", flag, value));
    for (std::size_t j = 0; j < names.size(); ++j)
      args.push_back(fmt::format("--{}={}", names[j], point.texts[j]));
    std::reverse(args.begin(), args.end());
    try {
      return parser.problem_of(args);
    } catch (const CLI::ParseError& e) {
      throw InputError(fmt::format("{}: {}", describe(names, point), e.what()));
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", describe(names, point), e.what()));
    }
  };
}

}  // namespace puncture::cli
