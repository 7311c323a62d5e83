// puncture: command-line front end of the membrane puncture solver.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <memory>

#include "cli_error.hpp"
#include "command_calibrate.hpp"
#include "command_inflate.hpp"
#include "command_sweep.hpp"
#include "command_verify.hpp"
#include "commands.hpp"
#include "figures.hpp"
#include "help_formatter.hpp"
#include "output_options.hpp"
#include "plot.hpp"
#include "problem_options.hpp"
#include "solve_failure.hpp"
#include "strict_config.hpp"
#include "suggest.hpp"

namespace {

constexpr const char* kDescription =
    "puncture: how a thin rubber membrane, clamped on a circle (flat, pre-stretched or\n"
    "inflated), deforms and punctures when a rigid probe is pushed into its centre: the\n"
    "paper's flat-ended cylinder (sharp or rounded corner), a sphere-tipped probe (ASTM\n"
    "F1306), a ball on a rod or a cone with a rounded tip (axisymmetric nonlinear membrane\n"
    "theory, Gent and other rubbers, Coulomb friction or a held contact on the probe).\n"
    "It computes the loading curve from zero depth to puncture (default), one equilibrium\n"
    "state with all its fields, or the puncture point alone: the puncture force, depth,\n"
    "stretch under the tip and where the crack starts.  `calibrate` and `fit` derive the\n"
    "model's parameters from the paper's experiments; `inflate` is the inflation (bulge)\n"
    "test of the same membrane under a uniform pressure; `verify` checks the solver for\n"
    "the membrane against independent methods.\n"
    "Units: lengths in mm, forces in N, moduli and stresses in MPa; line tension in N/mm;\n"
    "friction, stretches and the invariant I1 are dimensionless.  Defaults are the\n"
    "paper's lubricated silicone membrane (A = 25 mm, a = 2 mm, H = 0.2 mm, Gent with\n"
    "G = 0.06 MPa and J_lim = 125, mu' = 0.18, critical I1 = 95.2).\n";

constexpr const char* kFooter =
    "Physical and output flags may go before or after the subcommand.\n"
    "Examples:\n"
    "  puncture                                  paper's case: curve and puncture summary\n"
    "  puncture curve --friction 1.95 --format csv -o curve.csv\n"
    "  puncture state --force 2 --format json\n"
    "  puncture state --depth 8 --stick force:0.5 --stage auto\n"
    "  puncture puncture --indenter-radius 1 --material neo-hookean\n"
    "  puncture curve --plot curve.png            the curve drawn, stages shaded\n"
    "  puncture figures --out figures            the paper's Figs. 11-14, PNG and SVG\n"
    "  puncture calibrate friction --indenter-radius 1 --puncture-force 1.72 --hole-ratio 1.58\n"
    "  puncture fit uniaxial tensile.csv --material gent\n"
    "  puncture verify --indenter-radius 1        the solver checked for this membrane\n"
    "  puncture inflate --clamp-radius 30       bulge test: pressure to the burst\n"
    "Config file (--config FILE), one 'key = value' per line, keys are the long flag\n"
    "names, e.g.:\n"
    "  indenter-radius = 1\n"
    "  friction = 1.95\n"
    "  stick = \"force:0.5\"\n"
    "A command's own flags go below a line naming it, e.g. '[state]' then 'force = 2'.\n"
    "Plots (--plot, figures) run Python 3 with matplotlib (Debian: python3-matplotlib;\n"
    "another interpreter: PUNCTURE_PYTHON=/path/to/python3).\n"
    "Exit codes: 0 success, 1 invalid input, 2 the solver gave no usable result,\n"
    "3 the plot could not be drawn (no Python or matplotlib), 4 a `verify` check failed or\n"
    "could not be made.";

// The plot_cli.py figure of the parsed calibration, or none.
const char* calibration_plot_kind(const puncture::cli::CalibrationFlags& f) {
  if (f.uniaxial->parsed())
    return f.compare_option->count() > 0 ? "uniaxial-compare" : "uniaxial-fit";
  if (f.band->parsed()) return "band";
  if (f.jlim->parsed()) return "jlim";
  return nullptr;
}

constexpr const char* kSubcommandFooter =
    "The physical, curve and output flags (see puncture --help) may also be given.";

}  // namespace

int main(int argc, char** argv) {
  using namespace puncture::cli;
  OutputFlags output_flags;  // outside the try: a solve failure is written in the format asked
  try {
    CLI::App app{kDescription, "puncture"};
    app.fallthrough();  // parent flags are accepted after the subcommand too
    app.require_subcommand(0, 1);
    app.footer(kFooter);
    app.formatter(std::make_shared<HelpFormatter>());  // before the subcommands: they share it
    app.get_formatter()->column_width(34);
    app.set_version_flag("--version", "puncture " PUNCTURE_VERSION, "Print the version and exit");
    app.set_config("--config",
                   "",
                   "Read flags from a TOML/INI file of 'key = value' lines (keys:\n"
                   "long flag names); command-line flags override it")
        ->type_name("FILE");
    app.allow_config_extras(CLI::config_extras_mode::error);
    app.config_formatter(std::make_shared<StrictConfig>(app));

    ProblemFlags problem_flags;
    CurveFlags curve_flags;
    StateFlags state_flags;
    add_problem_options(app, problem_flags);
    add_curve_options(app, curve_flags);
    add_output_options(app, output_flags);
    std::string plot_path;
    auto* plot_option =
        app.add_option("--plot",
                       plot_path,
                       "Also draw the result to FILE (.png, .svg or .pdf) with matplotlib:\n"
                       "curve: force against depth, stages shaded, puncture marked;\n"
                       "state: deformed profile, stretches and I1 along the radius;\n"
                       "fit uniaxial: data, fit and residuals (with --compare: every\n"
                       "law's); fit curve: the\n"
                       "records, the fitted curves and residuals; calibrate band:\n"
                       "the ranges and puncture points; calibrate jlim: force\n"
                       "against J_lim")
            ->group("Output")
            ->type_name("FILE");
    app.add_subcommand("curve", "Loading curve from zero depth to puncture (the default)")
        ->footer(kSubcommandFooter);
    auto* state = app.add_subcommand(
        "state", "Equilibrium at --force N or --depth MM, with every field along the membrane");
    state->footer(kSubcommandFooter);
    add_state_options(*state, state_flags);
    auto* puncture = app.add_subcommand(
        "puncture",
        "The predicted puncture point alone (inflated or pre-stretched: which failure comes\n"
        "first, local puncture or global, from the loading curve)");
    puncture->footer(kSubcommandFooter);
    FiguresFlags figures_flags;
    auto* figures = app.add_subcommand(
        "figures",
        "The paper's analytical figures (Figs. 11, 12(a), 12(b), 13(a)-(e)) as PNG and SVG\n"
        "in --out DIR, with the ring-balance and the printed Eq. 18 Part II equations, and\n"
        "Fig. 14: a 1 mm flat punch on the inflated membrane, lubricated vs dry");
    figures->footer(
        "The membrane is the one the physical flags give (default: the paper's); each figure\n"
        "sets its own indenter radius and friction.  Fig. 14's gas pressure is --pressure\n"
        "(MPa), else 3e-4 MPa (the paper gives none).  Needs Python 3 with matplotlib.");
    add_figures_options(*figures, figures_flags);
    CalibrationFlags calibration_flags;
    add_calibration_commands(app, calibration_flags);
    InflateFlags inflate_flags;
    add_inflate_command(app, inflate_flags);
    VerifyFlags verify_flags;
    add_verify_command(app, verify_flags);
    SweepFlags sweep_flags;
    add_sweep_command(app, sweep_flags);

    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
      return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
      return app.exit(e);
    } catch (const CLI::ExtrasError& e) {
      // CLI11 names the stray words; a misspelt flag gets its closest name.
      const std::string unknown = unknown_flags_report(app, argc, argv);
      fmt::print(stderr,
                 "puncture: error: {}{}\nRun with --help for more information.\n",
                 e.what(),
                 unknown);
      return kExitBadInput;
    } catch (const CLI::ParseError& e) {
      fmt::print(stderr, "puncture: error: {}\nRun with --help for more information.\n", e.what());
      return kExitBadInput;
    }

    if (sweep_flags.parsed()) return run_sweep(app, sweep_flags, output_flags);
    if (calibration_flags.parsed() && plot_option->count() > 0 &&
        calibration_flags.curve.app->parsed()) {
      // `fit curve --plot`: the data and the fitted curves, drawn from the fit's JSON.
      check_plot_target(plot_path);
      const auto format = format_of(output_flags);
      check_writable(output_flags);
      std::string json;
      write_output(output_flags,
                   run_fit_curve(problem_flags, calibration_flags.curve, format, &json));
      run_plot_script("fit-curve", json, plot_path);
      return kExitOk;
    }
    if (calibration_flags.parsed()) {
      const bool plot = plot_option->count() > 0;
      const char* kind = calibration_plot_kind(calibration_flags);
      if (plot && kind == nullptr)  // refused rather than ignored
        throw InputError(
            "--plot: draws 'fit uniaxial', 'fit curve', 'calibrate band' and 'calibrate jlim'; "
            "this calibration's --format json output holds its numbers");
      if (plot) check_plot_target(plot_path);
      const auto format = format_of(output_flags);
      check_writable(output_flags);
      const std::string text = run_calibration(app, problem_flags, calibration_flags, format);
      write_output(output_flags, text);
      if (plot)
        run_plot_script(kind,
                        format == Format::Json
                            ? text
                            : run_calibration(app, problem_flags, calibration_flags, Format::Json),
                        plot_path);
      return kExitOk;
    }
    if (inflate_flags.parsed()) {
      if (plot_option->count() > 0)
        throw InputError(
            "--plot: 'inflate' has no plot here; draw it with puncture.plots.inflation_curve "
            "in Python");
      const auto format = format_of(output_flags);
      check_writable(output_flags);
      write_output(output_flags,
                   run_inflate(app, problem_flags, curve_flags, inflate_flags, format));
      return kExitOk;
    }
    const auto problem = make_problem(problem_flags);
    if (figures->parsed()) {
      for (const char* flag : {"--output", "--format", "--plot"})
        if (app.get_option(flag)->count() > 0)
          throw InputError(fmt::format(
              "{}: does not apply to 'figures', which writes its images and their data to "
              "--out DIR",
              flag));
      write_output(output_flags, run_figures(problem, curve_flags, figures_flags));
      return kExitOk;
    }
    const auto format = format_of(output_flags);
    check_writable(output_flags);
    if (verify_flags.parsed()) {
      if (plot_option->count() > 0)
        throw InputError("--plot: 'verify' writes a table; there is nothing to draw");
      const VerifyOutcome outcome = run_verify(problem, verify_flags, format);
      write_output(output_flags, outcome.text);
      if (outcome.passed) return kExitOk;
      fmt::print(stderr,
                 "puncture: verification {}: {}\n",
                 outcome.failed > 0 ? "failed" : "incomplete",
                 outcome.message);
      return kExitVerificationFailed;
    }
    const bool plot = plot_option->count() > 0;
    if (plot) {
      if (puncture->parsed())
        throw InputError(
            "--plot: draws a curve or a state; the 'puncture' subcommand has nothing to draw "
            "(use 'puncture curve --plot FILE')");
      check_plot_target(plot_path);
    }
    std::string text;
    if (state->parsed())
      text = run_state(problem, state_flags, format);
    else if (puncture->parsed())
      text = run_puncture(problem, format, problem_flags.test);
    else
      text = run_curve(problem, curve_flags, format, problem_flags.test);
    write_output(output_flags, text);
    if (plot) {
      // The plotting script reads the JSON output; computed again unless that is the format
      // asked for (the result is deterministic, and a curve takes milliseconds).
      const bool by_state = state->parsed();
      const std::string json =
          format == Format::Json ? text
          : by_state             ? run_state(problem, state_flags, Format::Json)
                     : run_curve(problem, curve_flags, Format::Json, problem_flags.test);
      run_plot_script(by_state ? "state" : "curve", json, plot_path);
    }
    return kExitOk;
  } catch (const InputError& e) {
    report_input_error(e, output_flags);
    return kExitBadInput;
  } catch (const SolveError& e) {
    report_solve_failure(e, output_flags);
    return kExitSolverFailure;
  } catch (const PlotError& e) {
    fmt::print(stderr, "puncture: plot failed: {}\n", e.what());
    return kExitPlotFailure;
  } catch (const std::exception& e) {
    fmt::print(stderr, "puncture: internal error: {}\n", e.what());
    return kExitSolverFailure;
  } catch (...) {
    fmt::print(stderr,
               "puncture: solver failure: the solver stopped with an unexpected internal "
               "error\n");
    return kExitSolverFailure;
  }
}
