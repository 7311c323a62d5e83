// Preload::inflated_state (docs/model.md §17): which of the inflated states at a pressure is
// indented.  The chosen state is the inflation solver's on that branch, an index beyond the
// states found is invalid input naming the parameter, and the paper's Gent membrane, whose
// states at one pressure all overhang their clamp (its limit point lies past the hemisphere),
// says for a later branch chosen that it is not indented.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "puncture/equilibrium.hpp"
#include "puncture/inflation.hpp"
#include "puncture/reports.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

// The paper's Gent membrane (J_lim = 125), frictionless, on a 2 mm sphere-tipped probe.
Problem inflated_at(double pressure_mpa, int state) {
  Problem p = paper_problem(Gent{125.0}, 0.0);
  p.indenter = SphereTipped{2.0};
  p.preload.pressure_mpa = pressure_mpa;
  p.preload.inflated_state = state;
  return p;
}

bool names_inflated_state(const std::vector<ValidationError>& errors) {
  return std::any_of(errors.begin(), errors.end(), [](const ValidationError& e) {
    return e.parameter == "preload.inflated_state";
  });
}

// Where one state holds the pressure, 'last' is it: found by the inflation solver's search over
// every state (another path than the first crossing's), the state at zero depth is the same to
// the root's tolerance, and the indentation from it the same.
TEST(InflatedState, LastOfOneStateIsTheFirst) {
  const Problem first = inflated_at(3e-4, 1), last = inflated_at(3e-4, kLastInflatedState);
  EXPECT_TRUE(validation_errors(last).empty());
  const auto at = inflate_at_pressure(inflation_problem(last), 3e-4);
  ASSERT_TRUE(at.ok()) << at.message;
  ASSERT_EQ(at.states.size(), 1u);
  const Equilibrium dome = solve_at_depth(last, 0.0, Stage::Slip);
  ASSERT_TRUE(dome.ok()) << dome.message;
  EXPECT_NEAR(dome.part_three_stretch, at.states.back().pole_stretch, 1e-12);
  const Equilibrium a = solve_at_depth(first, 5.0, Stage::Slip);
  const Equilibrium b = solve_at_depth(last, 5.0, Stage::Slip);
  ASSERT_TRUE(a.ok() && b.ok()) << a.message << b.message;
  EXPECT_NEAR(b.force_n, a.force_n, 1e-9 * a.force_n);
}

// At 0.9 kPa the membrane has three states (pole stretches 1.82, 3.47, 6.18), each overhanging its
// clamp (heights 25, 44, 85 mm on A = 25 mm).  The first is indented (overhanging_dome_test); a
// later one chosen is indented from its own dome in depth control (overhanging_paths_test): its
// state at zero depth is the inflation solver's on that branch (pole stretch to 1e-12), and a
// state at a force is outside the model (the force searches near zero force find the first
// state's branch).
TEST(InflatedState, TheChosenBranchIsTheInflationSolversState) {
  constexpr double kPressureMpa = 9e-4;
  const auto at =
      inflate_at_pressure(inflation_problem(inflated_at(kPressureMpa, 1)), kPressureMpa);
  ASSERT_TRUE(at.ok()) << at.message;
  ASSERT_EQ(at.states.size(), 3u);
  for (const int k : {2, 3, kLastInflatedState}) {
    SCOPED_TRACE(k);
    const Problem p = inflated_at(kPressureMpa, k);
    EXPECT_TRUE(validation_errors(p).empty());
    const InflationState& branch = at.states[k == kLastInflatedState ? 2 : k - 1];
    const Equilibrium e = solve_at_depth(p, 0.0, Stage::Slip);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_NEAR(e.part_three_stretch, branch.pole_stretch, 1e-12 * branch.pole_stretch);
    const Equilibrium by_force = solve_at_force(p, 0.01, Stage::Slip);
    EXPECT_EQ(by_force.status, Status::OutsideModel);
    // The summary says which state is used.
    EXPECT_NE(full_report(p).find(fmt::format("state {} of 3", k == kLastInflatedState ? 3 : k)),
              std::string::npos);
  }
}

// An index beyond the states found, below 1 (other than 'last'), or without a held pressure is
// invalid input naming preload.inflated_state.
TEST(InflatedState, InvalidChoicesAreRefused) {
  EXPECT_TRUE(names_inflated_state(validation_errors(inflated_at(9e-4, 4))));
  EXPECT_TRUE(names_inflated_state(validation_errors(inflated_at(3e-4, 2))));
  EXPECT_TRUE(names_inflated_state(validation_errors(inflated_at(3e-4, 0))));
  EXPECT_TRUE(names_inflated_state(validation_errors(inflated_at(3e-4, -2))));
  EXPECT_TRUE(names_inflated_state(validation_errors(inflated_at(0.0, 2))));
  Problem sealed = inflated_at(3e-4, kLastInflatedState);
  sealed.preload.gas_volume_mm3 = 1e6;
  EXPECT_TRUE(names_inflated_state(validation_errors(sealed)));
  EXPECT_THROW((void)solve_at_depth(inflated_at(9e-4, 4), 1.0, Stage::Slip), InvalidInput);
}

}  // namespace
}  // namespace puncture::test
