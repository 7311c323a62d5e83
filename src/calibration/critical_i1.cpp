// Critical I1 from the marks of inflation tests at burst (paper §2.3).
#include <fmt/format.h>

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <stdexcept>

#include "calibration/sample_statistics.hpp"
#include "puncture/calibration.hpp"
#include "puncture/inflation.hpp"

namespace puncture {

namespace {

// The pole stretch of each test, checked.
std::vector<double> pole_stretches(const std::vector<BurstTest>& tests) {
  if (tests.empty())
    throw std::invalid_argument("critical I1: at least one inflation test is needed, got none");
  std::vector<double> stretches;
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
    stretches.push_back(t.burst_radius_mm / t.initial_radius_mm);
  }
  return stretches;
}

// Mean, and with two tests or more the sample standard deviation and the standard error.
void summarise(CriticalI1Estimate& out) { detail::summarise_sample(out.first_invariants, out); }

}  // namespace

CriticalI1Estimate critical_i1_from_inflation(const std::vector<BurstTest>& tests) {
  CriticalI1Estimate out;
  out.status = Status::Converged;
  out.stretches = pole_stretches(tests);
  for (const double stretch : out.stretches) {
    out.pole_first_invariants.push_back(equibiaxial_first_invariant(stretch));
    out.largest_i1_radius_fractions.push_back(0.0);
  }
  out.first_invariants = out.pole_first_invariants;
  summarise(out);
  return out;
}

CriticalI1Estimate critical_i1_from_inflation(const std::vector<BurstTest>& tests,
                                              const MaterialLaw& law) {
  CriticalI1Estimate out;
  out.stretches = pole_stretches(tests);
  out.from_membrane = true;
  InflationProblem membrane;
  membrane.material.law = law;
  // Not used by the states; only kept valid (below a Gent locking).
  const double locking = locking_first_invariant(law);
  if (std::isfinite(locking)) membrane.critical_i1 = std::min(95.2, 0.5 * (3.0 + locking));
  validate(membrane);
  SolverOptions options;
  options.record_fields = false;
  for (std::size_t i = 0; i < out.stretches.size(); ++i) {
    const double stretch = out.stretches[i];
    const double pole = equibiaxial_first_invariant(stretch);
    if (pole >= locking)
      throw std::invalid_argument(
          fmt::format("test {}: the mark's stretch {:.6g} gives I1 = {:.6g} at the pole, at or "
                      "beyond the material's locking value {:.6g}: this law cannot describe "
                      "the test",
                      i + 1,
                      stretch,
                      pole,
                      locking));
    const InflationState state = inflate_at_pole_stretch(membrane, stretch, options);
    if (!state.ok()) {
      out.status = state.status;
      out.message = fmt::format(
          "test {}: no inflated state at pole stretch {:.6g}: {}", i + 1, stretch, state.message);
      return out;
    }
    // At the pole the closed form is exact; elsewhere the state's largest I1 is above it.
    const bool at_pole =
        !(state.max_first_invariant > pole) || state.max_first_invariant_reference_radius_mm == 0.0;
    out.pole_first_invariants.push_back(pole);
    out.first_invariants.push_back(at_pole ? pole : state.max_first_invariant);
    out.largest_i1_radius_fractions.push_back(
        at_pole ? 0.0 : state.max_first_invariant_reference_radius_mm / membrane.clamp_radius_mm);
  }
  out.status = Status::Converged;
  summarise(out);
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
