// `puncture puncture`: the predicted puncture point alone.
#include <fmt/format.h>

#include "cli_error.hpp"
#include "commands.hpp"
#include "output.hpp"
#include "progress.hpp"
#include "puncture/loading_curve.hpp"
#include "standard_test.hpp"

namespace puncture::cli {

std::string run_puncture(const Problem& problem, Format format, const std::string& test) {
  PunctureReport report{problem, {}, {}};
  {
    Progress progress("puncture");
    progress.note("locating the puncture point");
    SolverOptions options;
    options.energy_to_puncture = true;
    options.failure_verdict = true;  // a pre-tensioned membrane's: which failure comes first
    if (test == kAstmF1306) {
      // The standard's maximum force is the curve's: the puncture's with the loading curve.
      const auto curve = loading_curve(problem, CurveOptions{}, options);
      report.puncture = curve.ok() ? curve.puncture : PuncturePrediction{};
      if (!curve.ok()) {
        report.puncture.status = curve.status;
        report.puncture.message = curve.message;
      } else if (curve.puncture.ok()) {
        report.astm_f1306 = astm_f1306_outputs(curve);
        report.puncture.failure_verdict = curve.failure_verdict;
      }
    } else {
      report.puncture = predict_puncture(problem, options);
    }
  }
  if (!report.puncture.ok())
    throw SolveError("no puncture point found: " + report.puncture.message, report.puncture.status);
  return render(report, format);
}

}  // namespace puncture::cli
