// `puncture inflate`: the inflation (bulge) test.
#include "command_inflate.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "cli_error.hpp"
#include "inflation_output.hpp"
#include "parameter_flags.hpp"
#include "progress.hpp"

namespace puncture::cli {

namespace {

constexpr const char* kFooter =
    "The membrane comes from the physical flags: --clamp-radius (the paper's inflation tests\n"
    "used 30 mm), --thickness, --shear-modulus, --material, --jlim, --mr-alpha and\n"
    "--critical-i1 (the burst).  The indenter and contact flags (--indenter-radius,\n"
    "--friction, --stick, --part-two-equation) do not apply: there is no indenter.\n"
    "The pressure p is a follower load, normal to the deformed membrane.  It is not monotone\n"
    "in the deformation: a neo-Hookean membrane reaches a pressure maximum (a limit point;\n"
    "under pressure control it snaps through there) and Gent stiffens again after it, so the\n"
    "curve is parametrised by the pole stretch (the equibiaxial stretch at the centre), and\n"
    "--pressure reports every state carrying that pressure.\n"
    "Units: lengths in mm, pressure and stresses in MPa, volume in mm^3, energy in mJ (N mm).\n"
    "Output flags: --format summary|csv|json, --output FILE; --points sets the curve's states.\n"
    "Examples:\n"
    "  puncture inflate                                 curve to the burst, limit point\n"
    "  puncture inflate --clamp-radius 30 --format csv -o bulge.csv\n"
    "  puncture inflate --pressure 0.0009               every state at 0.0009 MPa\n"
    "  puncture inflate --pole-stretch 3 --format json  one state with its fields";

}  // namespace

void add_inflate_command(CLI::App& app, InflateFlags& f) {
  f.command = app.add_subcommand(
      "inflate",
      "Inflation (bulge) test: the clamped membrane under a uniform pressure, from\n"
      "flat to the burst (largest I1 = --critical-i1), its pressure maximum, one state\n"
      "(--pole-stretch) or every state at a pressure (--pressure)");
  f.command->footer(kFooter);
  f.pressure_option =
      f.command
          ->add_option("--pressure",
                       f.pressure_mpa,
                       "Every state at this pressure [MPa] (>= 0), up to the burst\n"
                       "(or --max-pole-stretch), in increasing pole stretch")
          ->type_name("P");
  f.pole_stretch_option =
      f.command
          ->add_option("--pole-stretch",
                       f.pole_stretch,
                       "The state whose pole (centre) is stretched equibiaxially by\n"
                       "this factor [dimensionless] (>= 1; >= L0 with --prestretch),\n"
                       "with its fields")
          ->type_name("L");
  f.pressure_option->excludes(f.pole_stretch_option);
  f.command
      ->add_option("--max-pole-stretch",
                   f.max_pole_stretch,
                   "End the curve (or the --pressure search) at this pole stretch\n"
                   "instead of at the burst [dimensionless] (> 1, below the Gent\n"
                   "locking; 0 = at the burst)")
      ->capture_default_str();
  f.command
      ->add_option("--scan-points",
                   f.scan_points,
                   "Pole stretches scanned for the pressure's extrema before each is\n"
                   "located precisely [count] (8 to 100000)")
      ->capture_default_str();
}

std::string run_inflate(const CLI::App& app, const ProblemFlags& pf, const CurveFlags& curve,
                        const InflateFlags& f, Format format) {
  for (const char* flag : {"--indenter",
                           "--indenter-radius",
                           "--friction",
                           "--stick",
                           "--part-two-equation",
                           "--test"})
    if (given(app, flag))
      throw InputError(fmt::format(
          "{}: does not apply to 'inflate', an inflation test has no indenter; remove it", flag));
  if (given(app, "--max-depth"))
    throw InputError(
        "--max-depth: does not apply to 'inflate'; end the curve with --max-pole-stretch");
  const auto problem = make_inflation_problem(pf);
  const bool by_pressure = f.pressure_option->count() > 0;
  const bool by_stretch = f.pole_stretch_option->count() > 0;
  if (by_stretch && given(*f.command, "--max-pole-stretch"))
    throw InputError("--max-pole-stretch: does not apply with --pole-stretch (one state)");
  InflationCurveOptions range;
  range.points = curve.points;
  range.max_pole_stretch = f.max_pole_stretch;
  range.scan_points = f.scan_points;
  try {
    if (by_stretch) {
      InflationStateReport report{problem, inflate_at_pole_stretch(problem, f.pole_stretch)};
      if (!report.state.ok())
        throw SolveError(fmt::format("no inflated state at pole stretch {} ({}): {}",
                                     f.pole_stretch,
                                     to_string(report.state.status),
                                     report.state.message),
                         report.state.status);
      return inflation_text(report, format);
    }
    Progress progress("inflate");
    if (by_pressure) {
      progress.note("locating the burst and the pressure's extrema");
      InflationPressureReport report{
          problem, f.max_pole_stretch == 0.0, inflate_at_pressure(problem, f.pressure_mpa, range)};
      if (!report.result.ok())
        throw SolveError(fmt::format("the states at pressure {} MPa could not be found ({}): {}",
                                     f.pressure_mpa,
                                     to_string(report.result.status),
                                     report.result.message),
                         report.result.status);
      return inflation_text(report, format);
    }
    progress.note("locating the burst");
    if (progress.enabled())
      range.progress = [&progress](int done, int total) { progress.update(done, total); };
    InflationCurveReport report{problem, f.max_pole_stretch == 0.0, {}};
    report.curve = inflation_curve(problem, range);
    if (!report.curve.ok())
      throw SolveError(fmt::format("the inflation curve failed ({}): {}",
                                   to_string(report.curve.status),
                                   report.curve.message),
                       report.curve.status);
    return inflation_text(report, format);
  } catch (const InvalidInput& e) {
    rethrow_with_flags(e);
  }
}

}  // namespace puncture::cli
