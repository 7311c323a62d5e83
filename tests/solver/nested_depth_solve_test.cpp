// The nested depth solve (indentation/nested_depth_solve.hpp) at the first point of the
// sphere-tipped probe's 200-point curve (#17), against the force search of solve_at_depth
// (independent: a bracketing in f of fixed-force shootings, each bracketed in p from the equator
// onset).
#include "indentation/nested_depth_solve.hpp"

#include <gtest/gtest.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>

#include "indentation/dispatch.hpp"
#include "indentation/shooting.hpp"
#include "indentation/solver_scales.hpp"
#include "solver_test_support.hpp"

namespace puncture::detail {
namespace {

using test::record;
using NestedSphereShooting = IndentationShooting<SphereTippedContact<Gent>>;

Problem nested_sphere_problem() {
  Problem p = test::paper_problem(Gent{125.0}, 0.0);
  p.indenter = SphereTipped{2.0};
  return p;
}

NestedSphereShooting nested_sphere_shooting(const Problem& p, const SolverOptions& o) {
  return NestedSphereShooting(std::get<Gent>(p.material.law),
                              shooting_settings(o),
                              contact_settings(p, std::get<SphereTipped>(p.indenter)),
                              false);
}

// The curve's first point, 0.15385 mm, from the starts the curve gives it: its predictor's force
// (6.6 % above the state's) with the parameter carried from the seed (f = 1e-4) as f^(1/2), 6 %
// above it in p - 1, and with the predictor's own d^2 (65 % below, where Part I turns back).
// Near zero load the depth carries noise of ~1e-8 relative (the pole strain ~3e-4 held in
// stretches near 1), d ln F / d ln depth ~ 3: the force within 1e-7 of the search's, the depth
// within the noise guard's 1e-7.
TEST(NestedDepthSolve, SolvesTheSphereCurvesFirstPointFromItsSeed) {
  const Problem p = nested_sphere_problem();
  const SolverOptions o;
  const auto shooting = nested_sphere_shooting(p, o);
  const double d = 0.153850119 / solver_scales(p).length_mm;
  const auto searched = shooting.solve_at_depth(Stage::Slip, d);
  ASSERT_TRUE(searched.ok()) << searched.message;
  const double f0 = 1.4894599169482196e-07;
  for (const double p0 : {1.0002863652812886, 1.0000967739571542}) {
    NestedDepthSolve<NestedSphereShooting> nested(shooting, o.curve_tol, 100.0 * o.curve_tol);
    const auto s = nested.solve(Configuration::SlipWithoutPartTwo, d, f0, p0);
    ASSERT_TRUE(s) << p0;
    EXPECT_TRUE(s->ok()) << s->message;
    EXPECT_NEAR(s->f, searched.f, 1e-7 * searched.f) << p0;
    EXPECT_NEAR(s->depth, d, 1e-7 * d) << p0;
    EXPECT_LE(std::abs(s->residual), 1e-7 * (s->parameter - 1.0)) << p0;
    EXPECT_GT(s->max_i1, 3.0) << p0;  // its largest I1 was searched
    EXPECT_LE(s->evaluations, 40) << p0;
    record(p0 > 1.0002 ? "nested_first_point_force_vs_search"
                       : "nested_first_point_from_below_force_vs_search",
           std::abs(s->f - searched.f) / searched.f);
    record(p0 > 1.0002 ? "nested_first_point_evaluations"
                       : "nested_first_point_from_below_evaluations",
           s->evaluations);
  }
}

// The curve's seed, the state at f = 1e-4: its plan's bracket starts at a turned-back stand-in
// (branch_below), and the search down from the cap through defined residuals finds the root
// bisection finds on the sign of the residual (stand-in included, to 4 ulps), to the residual's
// noise over its slope (~1e-13 / 27 in p).
TEST(NestedDepthSolve, SeedBelowAStandInMatchesBisection) {
  const Problem p = nested_sphere_problem();
  const SolverOptions o;
  const auto shooting = nested_sphere_shooting(p, o);
  const double f = 1e-4;
  auto residual = [&](Configuration c, double q) { return shooting.residual(c, f, q); };
  const auto plan = shooting.contact().plan(Stage::Slip, f, residual);
  ASSERT_TRUE(plan.ok()) << plan.message;
  EXPECT_TRUE(plan.branch_below);
  const auto seed = shooting.solve(Stage::Slip, f);
  ASSERT_TRUE(seed.ok()) << seed.message;
  const auto sign = [&](double q) {
    return shooting.residual(plan.configuration, f, q).value_or(-1.0);
  };
  const auto bracket = boost::math::tools::bisect(
      sign, plan.lo, plan.cap, boost::math::tools::eps_tolerance<double>(50));
  const double bisected = 0.5 * (bracket.first + bracket.second);
  EXPECT_NEAR(seed.parameter, bisected, 1e-13);
  EXPECT_LE(seed.evaluations, 20);
  record("seed_branch_search_vs_bisection", std::abs(seed.parameter - bisected));
  record("seed_branch_search_evaluations", seed.evaluations);
}

}  // namespace
}  // namespace puncture::detail
