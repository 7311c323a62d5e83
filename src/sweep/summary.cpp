// The sweep's reports.
#include <fmt/format.h>

#include "puncture/sweep.hpp"

namespace puncture {

double SweepSummary::points_per_second() const {
  return solve_s > 0.0 ? static_cast<double>(delivered) / solve_s : 0.0;
}

std::string SweepSummary::brief_report() const {
  return fmt::format(
      "sweep {}: {} of {} points ({} resumed), {} converged, {} failed; {:.3g} s on "
      "{} thread{} ({:.3g} points/s)",
      ok() ? "complete" : "incomplete",
      first_point + delivered,
      total_points,
      first_point,
      converged,
      delivered - converged,
      solve_s,
      threads,
      threads == 1 ? "" : "s",
      points_per_second());
}

std::string SweepSummary::full_report() const {
  std::string text = fmt::format("Sweep: {}\n", to_string(status));
  if (!message.empty()) text += fmt::format("  {}\n", message);
  text += fmt::format(
      "  points                 {} (first solved here: {})\n", total_points, first_point);
  text += fmt::format("  delivered this run     {}\n", delivered);
  text += fmt::format("  converged              {}\n", converged);
  text += fmt::format("  failed, physical       {}\n", failed_physical);
  text += fmt::format("  failed, numerical      {}\n", failed_numerical);
  text += fmt::format("  failed, outside model  {}\n", failed_outside_model);
  text += fmt::format("  threads                {}\n", threads);
  text += fmt::format("  checking the problems  {:.3g} s\n", validation_s);
  text += fmt::format("  solving                {:.3g} s ({:.3g} points/s, {:.3g} per thread)\n",
                      solve_s,
                      points_per_second(),
                      points_per_second() / threads);
  return text;
}

}  // namespace puncture
