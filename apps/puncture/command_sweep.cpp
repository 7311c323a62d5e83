#include "command_sweep.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <csignal>

#include "cli_error.hpp"
#include "puncture/sweep.hpp"
#include "sweep/design_map.hpp"
#include "sweep/mpi_sweep.hpp"
#include "sweep/problem_of_flags.hpp"
#include "sweep/resumable_csv.hpp"
#include "sweep/rows_csv.hpp"
#include "sweep/run_support.hpp"
#include "sweep/spec_file.hpp"
#include "sweep/statistics_report.hpp"

namespace puncture::cli {

void check_sweep_flags(const CLI::App& app, const OutputFlags& output) {
  for (const CLI::Option* o : app.get_options()) {
    if (o->count() == 0) continue;
    const std::string name = o->get_name();
    if (name == "--output" || name == "--plot") continue;
    if (name == "--format" && o->as<std::string>() == "csv") continue;
    throw InputError(fmt::format(
        "{}: does not apply to 'sweep'; the problem's flags go in the spec's [problem] (fixed) "
        "or [parameters] (swept) table, the rows to --output FILE as CSV",
        name));
  }
  if (output.path.empty())
    throw InputError("--output: 'sweep' writes its rows to a file (resumable): give -o FILE");
}

void add_sweep_command(CLI::App& app, SweepFlags& f) {
  f.command = app.add_subcommand(
      "sweep",
      "Many problems, one CSV row each: a grid, Latin hypercube, Sobol or Monte Carlo sweep of\n"
      "any of the problem's flags (SPEC.toml), solved on every core; -o FILE is required");
  f.command->add_option("spec", f.spec_path, "The sweep's spec (TOML); see below")
      ->required()
      ->type_name("SPEC.toml");
  f.command
      ->add_option("--threads",
                   f.threads,
                   "Threads solving points (0: every core); the file is\n"
                   "identical whatever the number")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  f.command->add_flag(
      "--resume", f.resume, "Continue the unfinished sweep in FILE.part: only the missing points");
  f.command->add_flag("--quiet", f.quiet, "No progress or summary on stderr");
  f.command->add_flag("--statistics",
                      f.statistics,
                      "When every point is written: for each output (puncture force [N] and\n"
                      "depth [mm], forces at depths [N]), its mean, sd, percentiles (5, 25,\n"
                      "50, 75, 95 %), histogram and the swept flags ranked by standardised\n"
                      "regression coefficient (SRC^2: share of the variance when R^2 ~ 1),\n"
                      "on stdout; failed points are counted, not used");
  f.command->footer(
      "SPEC.toml:\n"
      "  design = \"latin-hypercube\"   # grid, latin-hypercube, sobol or monte-carlo\n"
      "  samples = 200                # points (not for a grid)\n"
      "  seed = 1                     # latin-hypercube and monte-carlo\n"
      "  puncture = true              # the puncture point (default true)\n"
      "  force-at-depth = [10, 20]    # and/or the force at these depths [mm]\n"
      "  warm-start = true            # grid: each puncture search starts from its\n"
      "                               # neighbour's along the last flag's lines, in chains\n"
      "                               # of 16 points (16 to 50 % less CPU; force and depth\n"
      "                               # equal to cold solves within 1e-12 relative, not to\n"
      "                               # the last digit); default true, false: cold\n"
      "  [problem]                    # fixed flags (long names, as in --config)\n"
      "  friction = 0.5\n"
      "  [parameters]                 # swept flags, each one of:\n"
      "  thickness = { range = [0.15, 0.25] }               # uniform (grid: + levels = N)\n"
      "  indenter = { values = [\"flat\", \"sphere-tipped\"] }  # grid levels\n"
      "  critical-i1 = { distribution = \"normal\", mean = 95.2, sd = 3 }\n"
      "  shear-modulus = { distribution = \"lognormal\", mean = 0.06, sd = 0.006 }\n"
      "  friction = { distribution = \"truncated-normal\", mean = 0.18, sd = 0.05, range = [0, 1] "
      "}\n"
      "Units are the flags' (mm, N, MPa; see puncture --help).  Columns: point, the swept\n"
      "flags, status, failure_kind, puncture_force_n, puncture_depth_mm, part_three_stretch,\n"
      "max_i1, crack_reference_radius_mm, crack_radius_mm, crack_location,\n"
      "force_n_at_<D>_mm, message.  A failed point is a row with its status, its outputs empty.\n"
      "The rows go to FILE.part as they are solved; FILE.part becomes FILE when every point\n"
      "is written.  Ctrl-C stops after the points in hand; --resume continues.\n"
      "Exit codes: 0 every point written (failed points included), 1 invalid spec or flags,\n"
      "2 the file could not be written, 3 the --plot could not be drawn; interrupted: the\n"
      "signal's.\n"
      "--plot FILE (.png, .svg, .pdf): the design map of the finished sweep, the puncture\n"
      "force (else the first force at a depth) over the first two numeric swept flags, failed\n"
      "points marked.");
}

int run_sweep(const CLI::App& app, const SweepFlags& f, const OutputFlags& output) {
  if (launched_by_mpi()) return run_sweep_mpi(app, f, output);
  check_sweep_flags(app, output);
  const SweepFile file = read_sweep_file(f.spec_path);
  const auto plot = design_map_target(app);
  const std::string header = sweep_csv_header(file.spec);
  const std::string spec_text = file_text(f.spec_path);
  ResumableCsv csv = f.resume ? ResumableCsv::resume(output.path, header, spec_text)
                              : ResumableCsv::start(output.path, header, spec_text);
  const std::size_t total = point_count(file.spec);
  if (csv.rows() > total)
    throw InputError(fmt::format(
        "--resume: '{}' has {} rows, the sweep {} points", csv.part_path(), csv.rows(), total));

  SweepOptions options;
  options.threads = f.threads;
  options.first_point = csv.rows();
  options.on_row = [&csv](const SweepRow& row) { csv.append(sweep_csv_line(row)); };
  const bool terminal = isatty(STDERR_FILENO) == 1;
  if (!f.quiet) {
    options.progress = progress_line(terminal, csv.rows(), total);
    options.progress_every_s = terminal ? 0.5 : 10.0;
  }
  options.stop = &interrupt_flag();
  SweepSummary summary;
  {
    const StopOnSignals signals;
    try {
      summary = sweep(file.spec, problem_of_flags(file.spec, file.fixed), options);
    } catch (const InvalidInput& e) {
      csv.abandon_if_new_and_empty();
      throw InputError(e.what());
    } catch (const InputError&) {
      csv.abandon_if_new_and_empty();
      throw;
    }
  }
  if (!f.quiet) fmt::print(stderr, "{}{}\n", terminal ? "\r\033[K" : "", summary.brief_report());
  if (summary.ok()) {
    csv.finish();
    if (f.statistics) fmt::print("{}", sweep_statistics_report(output.path, file.spec));
    if (plot) draw_design_map(output.path, file.spec, *plot);
    return kExitOk;
  }
  fmt::print(stderr,
             "puncture: sweep interrupted: {} of {} points in '{}'; continue with --resume\n",
             csv.rows(),
             total,
             csv.part_path());
  end_by_interrupt();
  return kExitSolverFailure;  // not reached
}

}  // namespace puncture::cli
