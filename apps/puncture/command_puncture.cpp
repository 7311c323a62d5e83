// `puncture puncture`: the predicted puncture point alone.
#include <fmt/format.h>

#include "cli_error.hpp"
#include "commands.hpp"
#include "output.hpp"
#include "progress.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::cli {

std::string run_puncture(const Problem& problem, Format format) {
  PunctureReport report{problem, {}};
  {
    Progress progress("puncture");
    progress.note("locating the puncture point");
    report.puncture = predict_puncture(problem);
  }
  if (!report.puncture.ok())
    throw SolveError("no puncture point found: " + report.puncture.message, report.puncture.status);
  return render(report, format);
}

}  // namespace puncture::cli
