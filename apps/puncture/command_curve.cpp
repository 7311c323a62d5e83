// `puncture curve`: the displacement-controlled loading curve, by default up to puncture.
#include <fmt/format.h>

#include <cmath>

#include "cli_error.hpp"
#include "commands.hpp"
#include "output.hpp"
#include "progress.hpp"
#include "puncture/loading_curve.hpp"
#include "standard_test.hpp"

namespace puncture::cli {

void add_curve_options(CLI::App& app, CurveFlags& f) {
  constexpr const char* kCurve = "Curve (for 'curve', the default subcommand)";
  app.add_option("--points",
                 f.points,
                 "Number of equally spaced points of the curve [count] (2 to\n"
                 "100000): depths from zero to the end ('curve'), or pole\n"
                 "stretches from flat to the end ('inflate'); a curve to puncture\n"
                 "that snaps through at a fold has as many again after it (to\n"
                 "--max-depth: 2 more, the fold and the landing)")
      ->group(kCurve)
      ->check(CLI::Range(2, 100000).description(""))
      ->capture_default_str();
  app.add_option("--max-depth",
                 f.max_depth_mm,
                 "End the curve at this indentation depth instead of at puncture\n"
                 "[mm] (>= 0; 0 = at puncture)")
      ->group(kCurve)
      ->capture_default_str();
}

std::string run_curve(const Problem& problem, const CurveFlags& f, Format format,
                      const std::string& test) {
  if (!std::isfinite(f.max_depth_mm) || f.max_depth_mm < 0.0)
    throw InputError(fmt::format(
        "--max-depth: must be a finite number >= 0 mm (0 = to puncture), got {}", f.max_depth_mm));
  CurveReport report{problem, f.points, f.max_depth_mm, {}, {}};
  {
    Progress progress("curve");
    progress.note("locating the puncture point and the stage switch");
    CurveOptions options;
    options.points = f.points;
    options.max_depth_mm = f.max_depth_mm;
    if (progress.enabled())
      options.progress = [&progress](int done, int total) { progress.update(done, total); };
    SolverOptions solver;
    solver.energy_to_puncture = true;
    report.curve = loading_curve(problem, options, solver);
  }
  if (!report.curve.ok())
    throw SolveError(fmt::format("the loading curve failed ({}): {}",
                                 to_string(report.curve.status),
                                 report.curve.message),
                     report.curve.status);
  if (test == kAstmF1306) report.astm_f1306 = astm_f1306_outputs(report.curve);
  return render(report, format);
}

}  // namespace puncture::cli
