// States at many depths with the partial-slip family built once (src/indentation/depth_solve.hpp,
// the loading curve's event sampling): the same states, bit for bit, as solve_at_depth's one at
// a time, in the family, beside it and in the held stage, and the time each takes.
#include "indentation/depth_solve.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <vector>

#include "puncture/loading_curve.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

// The sphere on a pre-stretched membrane with mu' = 0.5 under `coulomb`: held to its release at
// 0.913 mm, the family to its hand-over at 3.49 mm, sliding beyond (partial_slip_curve_test).
Problem depth_solve_coulomb_problem() {
  Problem p = paper_problem(Gent{125.0}, 0.5);
  p.indenter = SphereTipped{2.0};
  p.stick = {StickRule::Coulomb, 0.0};
  p.preload.prestretch = 1.2;
  return p;
}

double depth_solve_seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

TEST(DepthSolve, TheFamilyBuiltOnceGivesSolveAtDepthsStates) {
  const Problem p = depth_solve_coulomb_problem();
  SolverOptions quiet;
  quiet.record_fields = false;
  struct At {
    double depth_mm;
    Stage stage;
  };
  const std::vector<At> depths = {{0.5, Stage::Stick},
                                  {0.5, Stage::Slip},
                                  {0.9132, Stage::Slip},  // past the release, short of the family
                                  {1.5, Stage::Slip},
                                  {2.0, Stage::Slip},
                                  {3.0, Stage::Slip},
                                  {5.0, Stage::Slip}};
  auto start = std::chrono::steady_clock::now();
  std::vector<Equilibrium> alone;
  for (const At& a : depths) alone.push_back(solve_at_depth(p, a.depth_mm, a.stage, quiet));
  const double alone_s = depth_solve_seconds(start);
  start = std::chrono::steady_clock::now();
  std::vector<Equilibrium> once;
  detail::with_depth_solve(p, quiet, [&](const detail::DepthSolve& solve) {
    for (const At& a : depths) once.push_back(solve(a.depth_mm, a.stage));
  });
  const double once_s = depth_solve_seconds(start);
  ASSERT_EQ(once.size(), alone.size());
  int in_family = 0;
  for (std::size_t i = 0; i < depths.size(); ++i) {
    const Equilibrium &a = alone[i], &b = once[i];
    ASSERT_EQ(a.status, b.status) << depths[i].depth_mm << ": " << a.message << " / " << b.message;
    EXPECT_EQ(a.force_n, b.force_n) << depths[i].depth_mm;
    EXPECT_EQ(a.depth_mm, b.depth_mm) << depths[i].depth_mm;
    EXPECT_EQ(a.configuration, b.configuration) << depths[i].depth_mm;
    EXPECT_EQ(a.max_first_invariant, b.max_first_invariant) << depths[i].depth_mm;
    EXPECT_EQ(a.slip_front_reference_radius_mm, b.slip_front_reference_radius_mm);
    EXPECT_EQ(a.contact_edge_radius_mm, b.contact_edge_radius_mm) << depths[i].depth_mm;
    if (b.configuration == Configuration::PartialSlip) ++in_family;
  }
  EXPECT_EQ(in_family, 3);  // 1.5, 2 and 3 mm: the test reaches the cached family
  record("depth_solve_alone_s", alone_s);
  record("depth_solve_once_s", once_s);
}

}  // namespace
}  // namespace puncture::test
