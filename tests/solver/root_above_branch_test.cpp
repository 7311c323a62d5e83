// The root above a square-root branch point (numerics/root_above_branch.hpp), on the model it is
// built for, g = c (sqrt(x - x_b) - sqrt(e)) above x_b and undefined below, whose root
// x* = x_b + e is known in closed form; and on a line, where it must not cost more than a
// secant.
#include "numerics/root_above_branch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <optional>

#include "solver_test_support.hpp"

namespace puncture::detail {
namespace {

using test::record;

// The sphere-tipped probe's clamp residual at the first point of the 200-point curve, fitted:
// c = 0.024, the root e = 2.1e-8 above the branch point at 2.79e-4 (its p - 1).
struct SquareRootBranch {
  double x_b = 2.79e-4, e = 2.1e-8, c = 0.024;
  double root() const { return x_b + e; }
  std::optional<double> operator()(double x) const {
    if (!(x > x_b)) return std::nullopt;
    return c * (std::sqrt(x - x_b) - std::sqrt(e));
  }
};

// From above (3 % of x* above, as the curve's start) and from below the branch point (the
// predictor's d^2 start, 65 % below): the root to the tolerance's worth of x (|g| <= tol, slope
// c / (2 sqrt(e)) = 83 at the root: 1e-13 / 83).  The model is exactly x quadratic in g, so the
// interpolation converges in a few steps: at most 12 evaluations against the 25 and more TOMS
// 748 takes on the bracket with a stand-in value below x_b.
TEST(RootAboveBranch, FindsTheRootNextToTheBranchPoint) {
  const SquareRootBranch g;
  const double tol = 1e-13;
  for (const double x0 : {1.03 * g.root(), 0.35 * g.root()}) {
    const auto root = root_above_branch(g, x0, {0.5 * g.root(), 1e-5 * g.root(), tol, 60});
    ASSERT_TRUE(root) << x0;
    EXPECT_LE(std::abs(root->g), tol) << x0;
    EXPECT_NEAR(root->x, g.root(), 2.0 * tol / 83.0) << x0;
    EXPECT_LE(root->evaluations, 12) << x0;
    record(
        x0 > g.root() ? "branch_root_from_above_evaluations" : "branch_root_from_below_evaluations",
        root->evaluations);
  }
  // TOMS 748 on the bracket [x* / 2 (a stand-in of -1), 1.03 x*], closed to the same |g|.
  std::uintmax_t iterations = 100;
  int toms = 0;
  double best = 1.0;
  const auto stand_in = [&](double x) {
    ++toms;
    const double value = g(x).value_or(-1.0);
    best = std::min(best, std::abs(value));
    return value;
  };
  boost::math::tools::toms748_solve(
      stand_in,
      0.5 * g.root(),
      1.03 * g.root(),
      [&](double, double) { return best <= tol; },
      iterations);
  record("branch_root_toms748_stand_in_evaluations", toms);
  EXPECT_GE(toms, 20);
}

// A line: the first step (Newton's on g|g| from above, half a Newton step) and the secant after
// it meet the root; with a known slope the probe is spared.
TEST(RootAboveBranch, ALineCostsAFewEvaluations) {
  const auto line = [](double x) -> std::optional<double> { return 2.0 * (x - 1.0); };
  const auto root = root_above_branch(line, 1.5, {0.1, 1e-5, 1e-14, 40});
  ASSERT_TRUE(root);
  EXPECT_NEAR(root->x, 1.0, 1e-14);
  EXPECT_LE(root->evaluations, 5);
  EXPECT_NEAR(root->slope, 2.0, 1e-9);
  const auto known = root_above_branch(line, 0.5, {0.1, 1e-5, 1e-14, 40, 2.0});
  ASSERT_TRUE(known);
  EXPECT_NEAR(known->x, 1.0, 1e-14);
  EXPECT_LE(known->evaluations, 2);
}

// Undefined everywhere it is asked within its budget, or a residual that does not rise: no root.
TEST(RootAboveBranch, ReportsNoRootWhereThereIsNone) {
  const auto nowhere = [](double) -> std::optional<double> { return std::nullopt; };
  EXPECT_FALSE(root_above_branch(nowhere, 0.0, {1.0, 1e-5, 1e-12, 30}));
  const auto falling = [](double x) -> std::optional<double> { return 1.0 - x; };
  EXPECT_FALSE(root_above_branch(falling, 0.0, {1.0, 1e-5, 1e-12, 30}));
}

}  // namespace
}  // namespace puncture::detail
