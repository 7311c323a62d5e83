// The fold of a loading path in depth (src/indentation/depth_fold.hpp): on a synthetic branch
// whose fold is known in closed form the locator finds it to its stated uncertainty; on a branch
// without one it finds none; and on the unstable middle inflated state at 0.9 kPa (docs/model.md
// §8.1) the located fold is the deepest of the states of a fine scan of the branch in force.
#include "indentation/depth_fold.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "indentation/depth_path_puncture.hpp"
#include "indentation/dispatch.hpp"
#include "indentation/shooting.hpp"
#include "indentation/solver_scales.hpp"
#include "pressurised_support.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

// A branch p = 1 + f (clamp residual p - 1 - f) whose depth is d(f) = f - k f^2 / 2 (turning
// back at f = 1 / k, depth 1 / (2 k)), or d(f) = f without a fold (k = 0).
struct SyntheticBranch {
  double k = 1.0;
  detail::ShootingSettings settings_;
  const detail::ShootingSettings& settings() const { return settings_; }
  std::optional<double> residual(Configuration, double f, double p) const { return p - 1.0 - f; }
  detail::ScaledSolution assemble(Configuration c, double f, double p, bool) const {
    detail::ScaledSolution s;
    s.configuration = c;
    s.f = f;
    s.parameter = p;
    s.integrated = true;
    s.residual = p - 1.0 - f;
    s.depth = f - 0.5 * k * f * f;
    return s;
  }
};

detail::ScaledSolution synthetic_state(const SyntheticBranch& b, double f) {
  return b.assemble(Configuration::SlipWithoutPartTwo, f, 1.0 + f, false);
}

TEST(DepthFold, ASyntheticFoldIsLocatedWhereItIsInClosedForm) {
  for (const double k : {1.0, 4.0, 0.3}) {
    SCOPED_TRACE(fmt::format("k = {}", k));
    SyntheticBranch b;
    b.k = k;
    b.settings_.shooting_tol = 1e-12;
    // The path's last two states, at 0.5 and 0.6 of the fold's force.
    const auto fold =
        detail::depth_fold_after(b, synthetic_state(b, 0.5 / k), synthetic_state(b, 0.6 / k));
    ASSERT_TRUE(fold.has_value());
    const double exact_depth = 0.5 / k, exact_force = 1.0 / k;
    EXPECT_NEAR(fold->state.depth, exact_depth, fold->depth_uncertainty);
    EXPECT_LE(fold->depth_uncertainty, 1e-8 * exact_depth);
    // Brent's bracket in the force: the depth's maximum is quadratic, so the force is found to
    // about the square root of the depth's resolution.
    EXPECT_NEAR(fold->state.f, exact_force, 1e-6 * exact_force);
    record(fmt::format("synthetic_fold_depth_error_k{}", k),
           std::abs(fold->state.depth - exact_depth) / exact_depth);
    record(fmt::format("synthetic_fold_force_error_k{}", k),
           std::abs(fold->state.f - exact_force) / exact_force);
  }
}

TEST(DepthFold, ABranchWithoutAFoldHasNone) {
  SyntheticBranch b;
  b.k = 0.0;
  b.settings_.shooting_tol = 1e-12;
  EXPECT_FALSE(
      detail::depth_fold_after(b, synthetic_state(b, 0.5), synthetic_state(b, 0.6)).has_value());
}

// The middle inflated state at 0.9 kPa under the 2 mm sphere: its path in depth ends at a fold
// (0.02536 mm, 5.03 mN with friction 0.18), where predict_puncture reports the snap-through; the
// fold is the deepest state of the branch followed in force on a grid 0.2 % apart around it (within
// the grid's resolution, the depth's curvature times the spacing squared), and deeper than the
// state at every grid force.
TEST(DepthFold, TheMiddleInflatedStateFoldsUnderTheSphere) {
  Problem p = pressurised(9e-4, 0.18, SphereTipped{2.0});
  p.preload.inflated_state = 2;
  SolverOptions o;
  o.record_fields = false;
  const double length_mm = detail::solver_scales(p).length_mm;
  double fold_depth_mm = 0.0, fold_uncertainty_mm = 0.0;
  detail::with_shooting(p, o, [&](const auto& shooting) {
    using namespace detail;
    ScaledSolution start = dome_branch_start(shooting, Stage::Slip);
    ASSERT_TRUE(start.ok()) << start.message;
    ScaledSolution from = start;
    EXPECT_FALSE(shooting.continue_in_depth(from, start.depth + kDepthPathStep).has_value());
    ASSERT_GT(from.depth, start.depth);
    const auto fold = depth_fold_after(shooting, start, from);
    ASSERT_TRUE(fold.has_value());
    EXPECT_NEAR(fold->state.depth * length_mm, 0.02536, 1e-4);
    const ScaledSolution& turn = fold->state;
    double deepest = 0.0;
    for (int i = -20; i <= 20; ++i) {
      const double f = turn.f * (1.0 + 0.002 * i);
      const auto s = branch_state_at_force(
          shooting, turn.configuration, f, start.f, start.parameter, turn.f, turn.parameter);
      ASSERT_TRUE(s.has_value()) << f;
      EXPECT_LE(s->depth, turn.depth + fold->depth_uncertainty);
      deepest = std::max(deepest, s->depth);
    }
    EXPECT_NEAR(deepest, turn.depth, 1e-4 * turn.depth);
    record("middle_state_fold_depth_mm", turn.depth * length_mm);
    fold_depth_mm = turn.depth * length_mm;
    fold_uncertainty_mm = fold->depth_uncertainty * length_mm;
  });
  // predict_puncture goes on under depth control (snap_puncture_test.cpp): the snap-through it
  // states is at this fold, within both locators' uncertainties.
  const auto puncture = predict_puncture(p);
  ASSERT_TRUE(puncture.ok()) << puncture.message;
  ASSERT_TRUE(puncture.snap_through.has_value());
  EXPECT_NEAR(puncture.snap_through->depth_mm,
              fold_depth_mm,
              fold_uncertainty_mm + puncture.snap_through->depth_uncertainty_mm);
}

}  // namespace
}  // namespace puncture::test
