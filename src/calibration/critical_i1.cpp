// Critical I1 from the marks of inflation tests at burst (paper §2.3).
#include <fmt/format.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <stdexcept>

#include "puncture/calibration.hpp"

namespace puncture {

CriticalI1Estimate critical_i1_from_inflation(const std::vector<BurstTest>& tests) {
  if (tests.empty())
    throw std::invalid_argument("critical I1: at least one inflation test is needed, got none");
  CriticalI1Estimate out;
  for (std::size_t i = 0; i < tests.size(); ++i) {
    const auto& t = tests[i];
    for (const auto& [name, value] : {std::pair{"initial radius", t.initial_radius_mm},
                                      std::pair{"burst radius", t.burst_radius_mm}})
      if (!std::isfinite(value) || value <= 0.0)
        throw std::invalid_argument(fmt::format(
            "test {}: the mark's {} must be a finite number > 0 mm, got {}", i + 1, name, value));
    if (t.burst_radius_mm < t.initial_radius_mm)
      throw std::invalid_argument(
          fmt::format("test {}: the mark's radius at burst ({} mm) is below its initial radius "
                      "({} mm); an inflated membrane stretches the mark",
                      i + 1,
                      t.burst_radius_mm,
                      t.initial_radius_mm));
    const double stretch = t.burst_radius_mm / t.initial_radius_mm;
    out.stretches.push_back(stretch);
    out.first_invariants.push_back(equibiaxial_first_invariant(stretch));
  }
  const auto n = static_cast<double>(tests.size());
  double sum = 0.0;
  for (const double i1 : out.first_invariants) sum += i1;
  out.mean = sum / n;
  if (tests.size() >= 2) {
    double ss = 0.0;
    for (const double i1 : out.first_invariants) ss += (i1 - out.mean) * (i1 - out.mean);
    out.standard_deviation = std::sqrt(ss / (n - 1.0));
    out.standard_error = *out.standard_deviation / std::sqrt(n);
  }
  return out;
}

std::vector<BurstTest> burst_tests_from_table(const CsvTable& table,
                                              std::optional<double> mark_radius_mm) {
  const auto burst = table.column("burst_radius_mm");
  std::vector<double> initial;
  if (table.has("initial_radius_mm")) {
    if (mark_radius_mm)
      throw std::invalid_argument(fmt::format(
          "{}: the table has a column initial_radius_mm; give no mark radius too", table.source));
    initial = table.column("initial_radius_mm");
  } else {
    if (!mark_radius_mm)
      throw std::invalid_argument(
          fmt::format("{}: no column initial_radius_mm, so the mark's initial radius must be "
                      "given",
                      table.source));
    initial.assign(burst.size(), *mark_radius_mm);
  }
  std::vector<BurstTest> tests;
  for (std::size_t i = 0; i < burst.size(); ++i) {
    const int line = table.line_numbers[i];
    for (const auto& [name, value] :
         {std::pair{"initial_radius_mm", initial[i]}, std::pair{"burst_radius_mm", burst[i]}}) {
      const auto column = table.find(name);
      if (value <= 0.0)
        throw CsvError(fmt::format("{}:{}: {} must be > 0 mm, got {}",
                                   table.source,
                                   line,
                                   column ? fmt::format("column {} ({})", *column + 1, name)
                                          : std::string("the mark radius"),
                                   value),
                       line,
                       column ? static_cast<int>(*column) + 1 : 0);
    }
    if (burst[i] < initial[i])
      throw CsvError(fmt::format("{}:{}: the burst radius {} mm is below the initial radius {} "
                                 "mm; an inflated membrane stretches the mark",
                                 table.source,
                                 line,
                                 burst[i],
                                 initial[i]),
                     line);
    tests.push_back({initial[i], burst[i]});
  }
  return tests;
}

}  // namespace puncture
