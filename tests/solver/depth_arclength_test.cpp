// The loading path followed through a fold of the depth by pseudo-arclength continuation
// (src/indentation/depth_arclength.hpp, src/numerics/pseudo_arclength.hpp): on synthetic branches
// whose fold is known in closed form the continuation passes the turn and its states lie on the
// branch beyond it; on the unstable middle inflated state at 0.9 kPa (docs/model.md §8.1) its
// states are equilibria solved again independently at their depths, the force is the
// potential's derivative along the continued branch, and the fold agrees with depth_fold_after.
#include "indentation/depth_arclength.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "indentation/depth_newton.hpp"
#include "indentation/depth_path_puncture.hpp"
#include "indentation/dispatch.hpp"
#include "indentation/physical_state.hpp"
#include "indentation/shooting.hpp"
#include "indentation/solver_scales.hpp"
#include "membrane_potential.hpp"
#include "pressurised_support.hpp"
#include "puncture/inflation.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

// A branch p^2 = 1 + f (clamp residual p^2 - 1 - f) whose depth is d(f) = f - k f^2 / 2: it
// turns back at f = 1 / k, depth 1 / (2 k).
struct ArcSyntheticBranch {
  double k = 1.0;
  detail::ShootingSettings settings_;
  const detail::ShootingSettings& settings() const { return settings_; }
  double parameter_floor(Configuration) const { return 0.0; }
  detail::ScaledSolution assemble(Configuration c, double f, double p, bool, bool = true) const {
    detail::ScaledSolution s;
    s.configuration = c;
    s.status = Status::Converged;
    s.f = f;
    s.parameter = p;
    s.integrated = true;
    s.residual = p * p - 1.0 - f;
    s.depth = f - 0.5 * k * f * f;
    return s;
  }
};

detail::ScaledSolution arc_synthetic_state(const ArcSyntheticBranch& b, double f) {
  return b.assemble(Configuration::SlipWithoutPartTwo, f, std::sqrt(1.0 + f), false);
}

TEST(DepthArclength, ASyntheticFoldIsPassedAndTheBranchBeyondIsTheAnalyticOne) {
  for (const double k : {1.0, 4.0, 0.3}) {
    SCOPED_TRACE(fmt::format("k = {}", k));
    ArcSyntheticBranch b;
    b.k = k;
    b.settings_.shooting_tol = 1e-12;
    const auto branch = detail::follow_through_fold(
        b, arc_synthetic_state(b, 0.5 / k), arc_synthetic_state(b, 0.6 / k));
    ASSERT_TRUE(branch.has_value());
    const double exact_depth = 0.5 / k, exact_force = 1.0 / k;
    EXPECT_NEAR(branch->fold.state.depth, exact_depth, branch->fold.depth_uncertainty);
    EXPECT_LE(branch->fold.depth_uncertainty, 1e-8 * exact_depth);
    // The tangent's zero: the force to the corrector's accuracy, not the square root of it.
    EXPECT_NEAR(branch->fold.state.f, exact_force, 1e-8 * exact_force);
    // Past the turn the force keeps rising, the depth falls to half the fold's, and every state
    // lies on the analytic branch.
    ASSERT_GT(branch->states.size(), branch->fold_index + 3);
    const auto& last = branch->states.back();
    EXPECT_GT(last.f, 1.5 * exact_force);
    EXPECT_LT(last.depth, 0.5 * exact_depth);
    double worst = 0.0;
    for (std::size_t i = branch->fold_index + 1; i < branch->states.size(); ++i) {
      const auto& s = branch->states[i];
      EXPECT_GT(s.f, exact_force);
      worst = std::max({worst,
                        std::abs(s.depth - (s.f - 0.5 * k * s.f * s.f)) / exact_depth,
                        std::abs(s.parameter - std::sqrt(1.0 + s.f))});
    }
    EXPECT_LE(worst, 1e-8);
    record(fmt::format("synthetic_arclength_branch_error_k{}", k), worst);
    record(fmt::format("synthetic_arclength_fold_force_error_k{}", k),
           std::abs(branch->fold.state.f - exact_force) / exact_force);
  }
}

// The middle inflated state at 0.9 kPa under the 2 mm sphere: the path in depth from its dome,
// then the continuation through the fold.
template <class Shooting>
std::optional<detail::FoldBranch> middle_state_branch(const Shooting& shooting,
                                                      std::optional<detail::DepthFold>* located) {
  using namespace detail;
  ScaledSolution start = dome_branch_start(shooting, Stage::Slip);
  EXPECT_TRUE(start.ok()) << start.message;
  if (!start.ok()) return std::nullopt;
  ScaledSolution from = start;
  EXPECT_FALSE(shooting.continue_in_depth(from, start.depth + kDepthPathStep).has_value());
  if (located) *located = depth_fold_after(shooting, start, from);
  return follow_through_fold(shooting, start, from);
}

TEST(DepthArclength, TheMiddleInflatedStateIsFollowedThroughItsFold) {
  for (const double friction : {0.18, 0.0}) {
    SCOPED_TRACE(fmt::format("mu' = {}", friction));
    Problem p = pressurised(9e-4, friction, SphereTipped{2.0});
    p.preload.inflated_state = 2;
    std::vector<detail::ScaledSolution> continued;
    std::size_t fold_index = 0;
    SolverOptions o;
    o.record_fields = false;
    const double length_mm = detail::solver_scales(p).length_mm;
    const double force_n = detail::solver_scales(p).force_n;
    detail::with_shooting(p, o, [&](const auto& shooting) {
      using namespace detail;
      std::optional<DepthFold> located;
      const auto branch = middle_state_branch(shooting, &located);
      ASSERT_TRUE(branch.has_value());
      ASSERT_TRUE(located.has_value());
      const DepthFold& fold = branch->fold;
      // The two locators agree within their stated uncertainties.
      EXPECT_NEAR(fold.state.depth,
                  located->state.depth,
                  fold.depth_uncertainty + located->depth_uncertainty);
      record(fmt::format("middle_state_arclength_fold_depth_mm_mu{}", friction),
             fold.state.depth * length_mm);
      record(fmt::format("middle_state_arclength_fold_force_n_mu{}", friction),
             fold.state.f * force_n);
      record(fmt::format("middle_state_fold_depth_difference_mm_mu{}", friction),
             std::abs(fold.state.depth - located->state.depth) * length_mm);
      // Beyond the fold the depth falls as the force rises: every continued state, solved again
      // by Newton in depth control at its depth from a guess 0.1 % off in force, is the same
      // state.
      ASSERT_GT(branch->states.size(), branch->fold_index + 3);
      EXPECT_LT(branch->states.back().depth, 0.5 * fold.state.depth + 1e-12);
      double worst = 0.0;
      for (std::size_t i = branch->fold_index + 1; i < branch->states.size(); ++i) {
        const ScaledSolution& s = branch->states[i];
        EXPECT_GT(s.f, fold.state.f);
        EXPECT_LT(s.depth, fold.state.depth);
        DepthNewton<std::decay_t<decltype(shooting)>> newton(shooting,
                                                             shooting.settings().shooting_tol);
        const auto again = newton.solve(s.configuration, s.depth, s.f * 1.001, s.parameter);
        ASSERT_TRUE(again && again->ok()) << "no state again at depth " << s.depth * length_mm;
        EXPECT_NEAR(again->f, s.f, 1e-9 * s.f);
        worst = std::max(worst, std::abs(again->f / s.f - 1.0));
      }
      record(fmt::format("middle_state_arclength_resolve_force_error_mu{}", friction), worst);
      continued = branch->states;
      fold_index = branch->fold_index;
    });
    // The branch beyond the fold is the third inflated state's path seen from its far end: the
    // probe at the same height above the clamp, its depth from the third state's pole (41.47 mm
    // higher), solved from that dome in depth control (an independent path: another dome,
    // another branch start, no continuation), carries the same force; to 1e-7, the poles'
    // heights' difference known to ~1e-10 mm and dF/d(depth) ~ 0.4 N/mm here.
    // (With mu' = 0.18; without friction the third state's path in depth from its dome does
    // not reach these depths: solve_at_depth fails there.)
    if (friction == 0.0) continue;
    Problem third = p;
    third.preload.inflated_state = 3;
    const auto states = inflate_at_pressure(inflation_problem(p), 9e-4).states;
    ASSERT_GE(states.size(), 3u);
    const double offset_mm = states[2].pole_height_mm - states[1].pole_height_mm;
    // (Three states, away from the fold, where that path ends: each solve follows it from the
    // third state's dome, 41 mm.)
    double worst_third = 0.0;
    const double fold_depth = continued[fold_index].depth;
    int compared = 0;
    for (std::size_t i = fold_index + 1; i < continued.size(); ++i) {
      const auto& s = continued[i];
      if (s.depth > 0.85 * fold_depth || compared >= 3) continue;
      if (compared > 0 && s.depth > continued[i - 1].depth - 0.1 * fold_depth) continue;
      ++compared;
      const Equilibrium e = solve_at_depth(third, offset_mm + s.depth * length_mm, Stage::Slip);
      ASSERT_TRUE(e.ok()) << e.message;
      EXPECT_NEAR(e.force_n, s.f * force_n, 1e-7 * s.f * force_n);
      worst_third = std::max(worst_third, std::abs(e.force_n / (s.f * force_n) - 1.0));
    }
    EXPECT_GE(compared, 2);
    record(fmt::format("middle_state_branch_vs_third_state_force_error_mu{}", friction),
           worst_third);
  }
}

// The curve of the middle state to puncture: the grid to the fold, the snap-through there onto
// the first inflated state, clear of the probe (its pole 18.89 mm below), and that state's own
// curve to its puncture, shifted by the poles' heights' difference; and to a depth past the fold.
TEST(DepthArclength, TheMiddleStatesCurveSnapsThroughToTheFirstState) {
  Problem p = pressurised(9e-4, 0.18, SphereTipped{2.0});
  p.preload.inflated_state = 2;
  CurveOptions c;
  c.points = 21;
  const LoadingCurve curve = loading_curve(p, c);
  ASSERT_TRUE(curve.ok()) << curve.message;
  const auto snap = std::find_if(curve.events.begin(), curve.events.end(), [](const CurveEvent& e) {
    return e.kind == CurveEventKind::SnapThrough;
  });
  ASSERT_NE(snap, curve.events.end());
  EXPECT_NEAR(snap->depth_mm, 0.025355, 1e-6);
  EXPECT_NEAR(snap->force_n, 5.0263e-3, 1e-7);
  ASSERT_TRUE(snap->force_after_n.has_value());
  EXPECT_EQ(*snap->force_after_n, 0.0);
  const auto states = inflate_at_pressure(inflation_problem(p), 9e-4).states;
  ASSERT_GE(states.size(), 2u);
  const double offset_mm = states[1].pole_height_mm - states[0].pole_height_mm;
  ASSERT_TRUE(snap->end_depth_mm.has_value());
  EXPECT_NEAR(*snap->end_depth_mm, offset_mm, 1e-9 * offset_mm);
  // The grid to the fold: 20 points, the fold the last; then the landing at the fold's depth.
  ASSERT_GT(curve.points.size(), 22u);
  EXPECT_EQ(curve.points[20].depth_mm, snap->depth_mm);
  EXPECT_EQ(curve.points[20].force_n, snap->force_n);
  EXPECT_EQ(curve.points[21].depth_mm, snap->depth_mm);
  EXPECT_EQ(curve.points[21].force_n, 0.0);
  for (std::size_t i = 1; i < 21; ++i)
    EXPECT_GT(curve.points[i].force_n, curve.points[i - 1].force_n);
  EXPECT_FALSE(curve.beyond_fold.empty());
  for (std::size_t i = 1; i < curve.beyond_fold.size(); ++i) {
    EXPECT_LT(curve.beyond_fold[i].depth_mm, curve.beyond_fold[i - 1].depth_mm);
    EXPECT_GT(curve.beyond_fold[i].force_n, curve.beyond_fold[i - 1].force_n);
  }
  // The first state's puncture, its depth shifted.
  Problem first = p;
  first.preload.inflated_state = 1;
  const PuncturePrediction alone = predict_puncture(first);
  ASSERT_TRUE(alone.ok()) << alone.message;
  ASSERT_TRUE(curve.puncture.ok()) << curve.puncture.message;
  EXPECT_NEAR(curve.puncture.force_n, alone.force_n, 1e-9 * alone.force_n);
  EXPECT_NEAR(curve.puncture.depth_mm, alone.depth_mm + offset_mm, 1e-9 * curve.puncture.depth_mm);
  EXPECT_NEAR(
      curve.points.back().depth_mm, curve.puncture.depth_mm, 1e-9 * curve.puncture.depth_mm);
  record("middle_state_curve_puncture_depth_mm", curve.puncture.depth_mm);

  // To a depth past the fold (--max-depth): the grid's depths short of the fold, the fold, the
  // landing, then the grid's deeper depths: force 0 while the probe is above the first state's
  // pole, that state's own force beyond (solved alone at the shifted depth).
  CurveOptions to_depth;
  to_depth.points = 12;
  to_depth.max_depth_mm = 30.0;
  const LoadingCurve partial = loading_curve(p, to_depth);
  ASSERT_TRUE(partial.ok()) << partial.message;
  ASSERT_EQ(partial.points.size(), 14u);
  EXPECT_EQ(partial.points[0].depth_mm, 0.0);
  EXPECT_EQ(partial.points[1].depth_mm, snap->depth_mm);
  EXPECT_EQ(partial.points[2].force_n, 0.0);
  for (int k = 1; k < 12; ++k) {
    const CurvePoint& q = partial.points[static_cast<std::size_t>(k) + 2];
    EXPECT_NEAR(q.depth_mm, 30.0 * k / 11, 1e-12);
    if (q.depth_mm <= offset_mm) {
      EXPECT_EQ(q.force_n, 0.0);
      continue;
    }
    const Equilibrium alone_at = solve_at_depth(first, q.depth_mm - offset_mm, Stage::Slip);
    ASSERT_TRUE(alone_at.ok()) << alone_at.message;
    // (The curve's points converge to curve_tol, 1e-9, the solve to its own: 1.6e-9 apart at
    // 21.8 mm.)
    EXPECT_NEAR(q.force_n, alone_at.force_n, 1e-8 * alone_at.force_n);
  }
}

// Constant pressure, frictionless: dPi/d(depth) = F on the branch beyond the fold (Pi = U - p V,
// membrane_potential.hpp), by central differences at h and h/2 about a continued state,
// extrapolated.  Pi (~10^2 mJ) is ~10^7 times the work F h over a step here, so the states are
// solved again to the tight tolerances (tight_options: clamp residual 1e-13) with 4000-sample
// fields, each by Newton in depth control from the continued state.
TEST(DepthArclength, OnTheContinuedBranchTheForceIsThePotentialsDerivative) {
  Problem p = pressurised(9e-4, 0.0, SphereTipped{2.0});
  p.preload.inflated_state = 2;
  const double length_mm = detail::solver_scales(p).length_mm;
  std::optional<detail::ScaledSolution> continued;
  std::optional<double> fold_depth;
  detail::with_shooting(p, SolverOptions{}, [&](const auto& shooting) {
    const auto branch = middle_state_branch(shooting, nullptr);
    ASSERT_TRUE(branch.has_value());
    fold_depth = branch->fold.state.depth;
    // The continued state nearest to 3/4 of the fold's depth, beyond it.
    const double target = 0.75 * branch->fold.state.depth;
    for (std::size_t i = branch->fold_index + 1; i < branch->states.size(); ++i)
      if (!continued ||
          std::abs(branch->states[i].depth - target) < std::abs(continued->depth - target))
        continued = branch->states[i];
  });
  ASSERT_TRUE(continued.has_value());
  SolverOptions tight = tight_options();
  tight.record_fields = true;
  tight.field_points = 16000;
  detail::with_shooting(p, tight, [&](const auto& shooting) {
    using namespace detail;
    const ScaledSolution& s = *continued;
    auto physical_at = [&](double d) -> std::optional<Equilibrium> {
      // Near first (the loose tolerance's Newton reaches it from farther), then to the tight one.
      using Newton = DepthNewton<std::decay_t<decltype(shooting)>>;
      Newton loose(shooting, SolverOptions{}.shooting_tol), newton(shooting, 1e-12, true);
      const auto near = loose.solve(s.configuration, d, s.f, s.parameter);
      EXPECT_TRUE(near.has_value()) << "no state near depth " << d * length_mm;
      if (!near) return std::nullopt;
      const auto at = newton.solve(s.configuration, d, near->f, near->parameter);
      EXPECT_TRUE(at && at->ok()) << "no state at depth " << d * length_mm;
      if (!at || !at->ok()) return std::nullopt;
      return to_physical(p, shooting.contact(), *at, Stage::Slip, tight);
    };
    const auto e = physical_at(s.depth);
    ASSERT_TRUE(e.has_value());
    EXPECT_LT(e->depth_mm, *fold_depth * length_mm);
    const double depth_mm = e->depth_mm, h = 0.05 * depth_mm;
    auto pi_at = [&](double d_mm) {
      const auto q = physical_at(d_mm / length_mm);
      return q ? potential(p, *q).value : 0.0;
    };
    const double d1 = (pi_at(depth_mm + h) - pi_at(depth_mm - h)) / (2.0 * h);
    const double d2 = (pi_at(depth_mm + h / 2) - pi_at(depth_mm - h / 2)) / h;
    const double slope = (4.0 * d2 - d1) / 3.0;
    EXPECT_NEAR(slope, e->force_n, 1e-6 * e->force_n)
        << "dPi/ddelta " << slope << " N at " << depth_mm << " mm; Pi " << potential(p, *e).value
        << " +- " << potential(p, *e).error << " mJ; F h " << e->force_n * h << " mJ";
    record("middle_state_continued_potential_slope_relative_difference",
           std::abs(slope / e->force_n - 1.0));
  });
}

}  // namespace
}  // namespace puncture::test
