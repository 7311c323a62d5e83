// `puncture state`: one equilibrium at a given force or depth, with every field.
#include <fmt/format.h>

#include <cmath>

#include "cli_error.hpp"
#include "commands.hpp"
#include "output.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::cli {

namespace {

struct StageChoice {
  Stage stage;
  std::string reason;
};

// --stage auto: the stage the problem's stick criterion gives at this load.
StageChoice automatic_stage(const Problem& problem, const StateFlags& f, bool by_force) {
  const auto b = stick_slip_boundary(problem);
  // Outside the model is the problem's own verdict (e.g. an overhanging inflated dome), not a
  // failure to find the switch.
  if (b.status == Status::OutsideModel) throw SolveError(b.message, b.status);
  if (b.status != Status::Converged)
    throw SolveError(
        fmt::format(
            "cannot locate the stick -> slip switch ({}): {}", to_string(b.status), b.message),
        b.status);
  if (b.first_stage == Stage::Slip)
    return {Stage::Slip,
            problem.stick.rule == StickRule::None
                ? "auto: with --stick none the membrane slides from the first touch"
                : "auto: the --stick rule releases at the first touch (as coulomb does on a "
                  "stress-free membrane: friction cannot hold the first material touched, "
                  "docs/model.md section 15.4): the membrane slides from the first touch"};
  if (!b.switches) return {Stage::Stick, "auto: with --stick always the membrane is held"};
  if (by_force) {
    const bool stuck = f.force_n <= b.force_stuck_n;
    return {stuck ? Stage::Stick : Stage::Slip,
            fmt::format("auto: force {} the switch force {:.5g} N",
                        stuck ? "at or below" : "above",
                        b.force_stuck_n)};
  }
  const bool stuck = f.depth_mm <= b.depth_mm;
  return {stuck ? Stage::Stick : Stage::Slip,
          fmt::format("auto: depth {} the switch depth {:.5g} mm",
                      stuck ? "at or below" : "above",
                      b.depth_mm)};
}

StageChoice choose_stage(const Problem& problem, const StateFlags& f, bool by_force) {
  if (f.stage == "stick") return {Stage::Stick, "set by --stage stick"};
  if (f.stage == "slip") return {Stage::Slip, "set by --stage slip"};
  return automatic_stage(problem, f, by_force);
}

void check_load(double value, const char* flag, const char* unit) {
  if (!std::isfinite(value) || value < 0.0)
    throw InputError(fmt::format("{}: must be a finite number >= 0 {}, got {}", flag, unit, value));
}

}  // namespace

void add_state_options(CLI::App& state, StateFlags& f) {
  f.force_option = state.add_option(
      "--force", f.force_n, "Indenter force F [N] (>= 0); give --force or --depth");
  f.depth_option = state.add_option("--depth",
                                    f.depth_mm,
                                    "Indentation depth of the tip below the clamp plane [mm]\n"
                                    "(>= 0); give --force or --depth");
  f.force_option->excludes(f.depth_option);
  state
      .add_option("--stage",
                  f.stage,
                  "stick (membrane held at the indenter's edge), slip (sliding), or\n"
                  "auto: the stage the --stick criterion gives at this load")
      ->check(CLI::IsMember({"stick", "slip", "auto"}))
      ->capture_default_str();
}

std::string run_state(const Problem& problem, const StateFlags& f, Format format) {
  const bool by_force = f.force_option->count() > 0;
  if (!by_force && f.depth_option->count() == 0)
    throw InputError("state: give the load as --force N or --depth MM");
  if (by_force)
    check_load(f.force_n, "--force", "N");
  else
    check_load(f.depth_mm, "--depth", "mm");
  const auto choice = choose_stage(problem, f, by_force);
  StateReport report{problem, {}, {}, choice.reason, {}};
  if (by_force) {
    report.requested_force_n = f.force_n;
    report.state = solve_at_force(problem, f.force_n, choice.stage);
  } else {
    report.requested_depth_mm = f.depth_mm;
    report.state = solve_at_depth(problem, f.depth_mm, choice.stage);
  }
  if (!report.state.ok())
    throw SolveError(fmt::format("no equilibrium in the {} stage ({}): {}",
                                 to_string(choice.stage),
                                 to_string(report.state.status),
                                 report.state.message),
                     report.state.status);
  return render(report, format);
}

}  // namespace puncture::cli
