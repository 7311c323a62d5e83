// The puncture search's warm start (SolverOptions::puncture_top_stretch_start): the flat punch's
// corner solve polishes its root from a neighbouring problem's hoop stretch at the top of Part II
// instead of bracketing it.  Checks: along lines of friction and critical I1 each warm puncture
// agrees with the cold one to the shooting's tolerance; a start at the root keeps it and the
// cold numbers bit for bit; a start off the root is used (another double within the tolerance);
// an unusable start falls back to the cold search bit for bit; an invalid one is refused.
#include <cmath>
#include <optional>
#include <stdexcept>

#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

PuncturePrediction predict(const Problem& p, std::optional<double> start = std::nullopt) {
  SolverOptions o;
  o.record_fields = false;
  o.puncture_top_stretch_start = start;
  return predict_puncture(p, o);
}

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

void expect_bit_identical(const PuncturePrediction& a, const PuncturePrediction& b) {
  ASSERT_EQ(a.status, b.status) << a.message;
  EXPECT_EQ(a.force_n, b.force_n);
  EXPECT_EQ(a.depth_mm, b.depth_mm);
  EXPECT_EQ(a.part_three_stretch, b.part_three_stretch);
  EXPECT_EQ(a.state.max_first_invariant, b.state.max_first_invariant);
  EXPECT_EQ(a.part_two_top_stretch, b.part_two_top_stretch);
}

// Each point of a line warm from its neighbour's cold root, against its own cold solve.  Both
// roots meet the clamp to 1e-2 of the shooting's tolerance (|lambda2(A) - 1| <= 1e-12), so they
// lie within ~1e-12 / (p g'(p)) of each other and the force and the depth (smooth in p) within
// the same relative order: 1e-12 is the shooting's own resolution.  The corner's stretch and
// I1 (fixed by the capstan condition and I1 = I1c) are reported as the state marched down Part
// II from p finds them, which amplifies the difference (~2e-11 at high friction): 1e-10, still
// a hundredth of the solver's 1e-9 accuracy.
struct Line {
  const char* name;
  Problem (*problem_at)(double);
  double lower, upper;
};

void PrintTo(const Line& line, std::ostream* os) { *os << line.name; }

Problem with_friction(double mu) { return paper_problem(Gent{125.0}, mu); }
Problem with_critical_i1(double i1c) {
  Problem p = paper_problem();
  p.critical_i1 = i1c;
  return p;
}
Problem neo_hookean_with_friction(double mu) { return paper_problem(NeoHookean{}, mu); }

class WarmStartLine : public ::testing::TestWithParam<Line> {};

INSTANTIATE_TEST_SUITE_P(
    PunctureSearch, WarmStartLine,
    ::testing::Values(Line{"Friction", with_friction, 0.05, 0.4},
                      Line{"CriticalI1", with_critical_i1, 70.0, 120.0},
                      Line{"NeoHookeanFriction", neo_hookean_with_friction, 0.1, 0.6}),
    [](const auto& info) { return std::string(info.param.name); });

TEST_P(WarmStartLine, AgreesWithColdToTheShootingTolerance) {
  const Line& line = GetParam();
  constexpr int kPoints = 8;
  std::optional<double> start;
  double worst_force = 0.0, worst_depth = 0.0, worst_stretch = 0.0;
  for (int i = 0; i < kPoints; ++i) {
    const double x = line.lower + (line.upper - line.lower) * i / (kPoints - 1);
    const Problem p = line.problem_at(x);
    const PuncturePrediction cold = predict(p);
    ASSERT_TRUE(cold.ok()) << x << ": " << cold.message;
    ASSERT_TRUE(cold.part_two_top_stretch) << "the crack is expected at the corner";
    if (start) {
      const PuncturePrediction warm = predict(p, start);
      ASSERT_TRUE(warm.ok()) << x << ": " << warm.message;
      ASSERT_TRUE(warm.part_two_top_stretch);
      EXPECT_NEAR(*warm.part_two_top_stretch,
                  *cold.part_two_top_stretch,
                  1e-12 * *cold.part_two_top_stretch);
      EXPECT_LE(relative(warm.force_n, cold.force_n), 1e-12) << x;
      EXPECT_LE(relative(warm.depth_mm, cold.depth_mm), 1e-12) << x;
      EXPECT_LE(relative(warm.state.max_first_invariant, cold.state.max_first_invariant), 1e-10);
      EXPECT_NEAR(
          warm.part_three_stretch, cold.part_three_stretch, 1e-10 * cold.part_three_stretch);
      EXPECT_EQ(warm.crack_location, cold.crack_location);
      EXPECT_EQ(warm.stage, cold.stage);
      worst_force = std::max(worst_force, relative(warm.force_n, cold.force_n));
      worst_depth = std::max(worst_depth, relative(warm.depth_mm, cold.depth_mm));
      worst_stretch =
          std::max(worst_stretch, relative(warm.part_three_stretch, cold.part_three_stretch));
    }
    start = cold.part_two_top_stretch;
  }
  record("largest_relative_force_difference", worst_force);
  record("largest_relative_depth_difference", worst_depth);
  record("largest_relative_corner_stretch_difference", worst_stretch);
}

TEST(WarmStart, AStartAtTheRootKeepsItAndTheColdNumbers) {
  const Problem p = paper_problem();
  const PuncturePrediction cold = predict(p);
  ASSERT_TRUE(cold.ok() && cold.part_two_top_stretch) << cold.message;
  expect_bit_identical(predict(p, cold.part_two_top_stretch), cold);
  // Along the shear modulus the stretches do not change: the neighbour's root is the root.
  Problem softer = p;
  softer.material.shear_modulus_mpa *= 0.75;
  const PuncturePrediction warm = predict(softer, cold.part_two_top_stretch);
  ASSERT_TRUE(warm.ok()) << warm.message;
  EXPECT_EQ(warm.part_two_top_stretch, cold.part_two_top_stretch);
  EXPECT_NEAR(warm.force_n / cold.force_n, 0.75, 1e-12);
  EXPECT_EQ(warm.depth_mm, cold.depth_mm);
}

// A start 1e-6 off the root is polished by secant steps to another root within the tolerance:
// the start was used (the cold search lands on another double).
TEST(WarmStart, AStartOffTheRootIsPolishedWithinTheTolerance) {
  const Problem p = paper_problem();
  const PuncturePrediction cold = predict(p);
  ASSERT_TRUE(cold.ok() && cold.part_two_top_stretch) << cold.message;
  const PuncturePrediction warm = predict(p, *cold.part_two_top_stretch * (1.0 + 1e-6));
  ASSERT_TRUE(warm.ok() && warm.part_two_top_stretch) << warm.message;
  EXPECT_NE(*warm.part_two_top_stretch, *cold.part_two_top_stretch);
  EXPECT_NEAR(
      *warm.part_two_top_stretch, *cold.part_two_top_stretch, 1e-12 * *cold.part_two_top_stretch);
  EXPECT_LE(relative(warm.force_n, cold.force_n), 1e-12);
  EXPECT_LE(relative(warm.depth_mm, cold.depth_mm), 1e-12);
}

// Below the floor a / A (0.08), beyond the corner's stretch, or at the clamp (a residual of
// about a / A - 1, far beyond a secant's reach): the cold search runs, bit for bit.
TEST(WarmStart, AnUnusableStartFallsBackToTheColdSearch) {
  const Problem p = paper_problem();
  const PuncturePrediction cold = predict(p);
  ASSERT_TRUE(cold.ok()) << cold.message;
  for (const double start : {0.05, 0.08 * (1.0 + 1e-6), 1e3})
    expect_bit_identical(predict(p, start), cold);
}

// The sphere-tipped probe has no corner solve, and the frictionless flat punch's is a shooting at
// a known force (R s1 is constant up the side): the start changes nothing.
TEST(WarmStart, ProblemsWithoutACornerRootIgnoreTheStart) {
  Problem sphere = paper_problem(Gent{125.0}, 0.0);
  sphere.indenter = SphereTipped{2.0};
  const PuncturePrediction cold = predict(sphere);
  ASSERT_TRUE(cold.ok()) << cold.message;
  EXPECT_FALSE(cold.part_two_top_stretch);
  expect_bit_identical(predict(sphere, 1.5), cold);
  const Problem frictionless = paper_problem(Gent{125.0}, 0.0);
  expect_bit_identical(predict(frictionless, 1.5), predict(frictionless));
}

TEST(WarmStart, AnInvalidStartIsRefused) {
  const Problem p = paper_problem();
  for (const double start : {std::nan(""), -1.0, 0.0, HUGE_VAL}) {
    SolverOptions o;
    o.puncture_top_stretch_start = start;
    EXPECT_THROW(predict_puncture(p, o), std::invalid_argument) << start;
  }
}

}  // namespace
}  // namespace puncture::test
