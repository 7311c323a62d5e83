// The full report of a verification (puncture/reports.hpp): every check in its group.
#include <fmt/format.h>

#include <cmath>

#include "puncture/reports.hpp"

namespace puncture {

namespace {

// The number in the column's format, or "n/a" right-aligned when it is not finite.
// `spec` is "{:>W.Pf}"; "n/a" takes the same width.
std::string column(double x, const std::string& spec) {
  if (std::isfinite(x)) return fmt::format(fmt::runtime(spec), x);
  return fmt::format(fmt::runtime(spec.substr(0, spec.find('.')) + "}"), "n/a");
}

}  // namespace

std::string full_report(const VerificationReport& v) {
  std::string out;
  std::string group, condition;
  for (const VerificationCheck& c : v.checks) {
    if (c.group != group) {
      group = c.group;
      condition.clear();
      out += fmt::format("{}\n  {:<40}{:>17}{:>17}{:>10}{:>9}  {}\n",
                         group,
                         "quantity",
                         "shooting",
                         "2nd method",
                         "rel.diff",
                         "tol",
                         "verdict");
    }
    if (c.condition != condition) out += fmt::format("  {}\n", condition = c.condition);
    if (!has_numbers(c)) {
      out += fmt::format("  {:<40}  {}: {}\n", c.quantity, to_string(c.verdict), c.note);
      continue;
    }
    out += fmt::format("  {:<40}{}{}{}{}  {}\n",
                       c.quantity,
                       column(c.shooting, "{:>17.10g}"),
                       column(c.reference, "{:>17.10g}"),
                       column(c.difference, "{:>10.1e}"),
                       column(c.tolerance, "{:>9.0e}"),
                       to_string(c.verdict));
  }
  out += fmt::format("Result: {} passed, {} failed, {} skipped\n",
                     v.count(Verdict::Pass),
                     v.count(Verdict::Fail),
                     v.count(Verdict::Skipped));
  return out;
}

}  // namespace puncture
