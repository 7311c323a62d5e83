// Force-depth fit: records made by the loading curve with known parameters must give them back;
// with seeded noise the 95 % intervals must cover the truth at their rate; records the model
// cannot describe end with a clear status; bad input is refused naming what is wrong.
#include "puncture/curve_fit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "puncture/force_depth_record.hpp"
#include "puncture/loading_curve.hpp"
#include "seeded_noise.hpp"

namespace puncture {
namespace {

// The paper's lubricated membrane (Problem defaults: flat punch 2 mm, Gent J_lim 125,
// G 0.06 MPa, friction 0.18, critical I1 95.2).
Problem paper() { return Problem{}; }

// `n` depths evenly up to `fraction` of the puncture depth, the model's force plus noise of
// sd `noise_fraction` times the largest force; with `puncture`, the model's puncture point.
CurveTest synthetic(const Problem& truth, int n, double noise_fraction, unsigned seed,
                    double fraction = 0.95, bool puncture = false) {
  const auto p = predict_puncture(truth);
  EXPECT_TRUE(p.ok()) << p.message;
  CurveTest t;
  t.name = "synthetic";
  t.problem = truth;
  for (int i = 1; i <= n; ++i) t.depth_mm.push_back(fraction * p.depth_mm * i / n);
  CurveOptions c;
  c.depths_mm = t.depth_mm;
  const auto curve = loading_curve(truth, c);
  EXPECT_TRUE(curve.ok()) << curve.message;
  // One force per depth: at a stick -> slip switch the curve has two points at its depth (held,
  // then sliding); a machine at that depth reads the sliding one.
  std::vector<double> force;
  for (const double d : t.depth_mm) {
    double f = 0.0;
    for (const auto& pt : curve.points)
      if (pt.depth_mm == d) f = pt.force_n;
    force.push_back(f);
  }
  double f_max = 0.0;
  for (const double f : force) f_max = std::max(f_max, f);
  test::SeededNoise noise(seed, noise_fraction * f_max);
  for (const double f : force) t.force_n.push_back(f + noise());
  if (puncture) t.puncture = MeasuredPuncture{p.depth_mm, p.force_n};
  return t;
}

int repeats(int fallback) {
  const char* env = std::getenv("PUNCTURE_COVERAGE_REPEATS");
  return env ? std::atoi(env) : fallback;
}

bool covers(const FittedCurveParameter& p, double truth) {
  return p.ci_lower && p.ci_upper && *p.ci_lower <= truth && truth <= *p.ci_upper;
}

// The curve at given depths (CurveOptions::depths_mm, what the fit evaluates) is the even-grid
// curve at the same depths: the same Newton path from the same predictor, so the same numbers.
TEST(CurveFit, LoadingCurveAtGivenDepthsIsTheEvenGridCurve) {
  CurveOptions even;
  even.points = 41;
  even.max_depth_mm = 30.0;
  const auto grid = loading_curve(paper(), even);
  ASSERT_TRUE(grid.ok());
  CurveOptions given;
  for (std::size_t k = 1; k < grid.points.size(); ++k)
    given.depths_mm.push_back(grid.points[k].depth_mm);
  const auto at = loading_curve(paper(), given);
  ASSERT_TRUE(at.ok()) << at.message;
  ASSERT_EQ(at.points.size(), grid.points.size() - 1);
  for (std::size_t k = 0; k < at.points.size(); ++k)
    EXPECT_NEAR(
        at.points[k].force_n, grid.points[k + 1].force_n, 1e-12 * grid.points[k + 1].force_n);
  CurveOptions bad;
  bad.depths_mm = {1.0, 2.0, 2.0};
  EXPECT_THROW(loading_curve(paper(), bad), InvalidInput);
  bad.depths_mm = {0.0, 1.0};
  EXPECT_THROW(loading_curve(paper(), bad), InvalidInput);
}

// Data without noise: the optimum is the truth.  The model is accurate to ~1e-9 relative and
// Ceres stops on a relative step of 1e-9: the estimates agree to 1e-6.
TEST(CurveFit, RecoversShearModulusAndJLimFromAnExactCurve) {
  const Problem truth = paper();
  auto test = synthetic(truth, 60, 0.0, 1);
  test.problem.material.shear_modulus_mpa = 0.08;
  std::get<Gent>(test.problem.material.law).j_lim = 160.0;
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus, CurveParameter::JLim};
  const auto fit = fit_curves({{test}}, o);
  ASSERT_TRUE(fit.ok()) << fit.message;
  ASSERT_EQ(fit.parameters.size(), 2u);
  EXPECT_NEAR(fit.parameters[0].value, 0.06, 1e-6 * 0.06);
  EXPECT_NEAR(fit.parameters[1].value, 125.0, 1e-6 * 125.0);
  EXPECT_LT(fit.residual_sd_n, 1e-6 * test.force_n.back());
  EXPECT_GT(fit.r_squared, 1.0 - 1e-12);
  ASSERT_EQ(fit.tests.size(), 1u);
  EXPECT_EQ(fit.tests[0].model_force_n.size(), test.force_n.size());
}

// The force is proportional to G: a G-only fit is linear least squares, G = sum(f F) / sum(f^2)
// with f the curve per unit G, and its standard error s / sqrt(sum f^2) (closed forms).
TEST(CurveFit, ShearModulusAloneIsTheLinearLeastSquaresSolution) {
  const auto test = synthetic(paper(), 80, 0.01, 7);
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus};
  const auto fit = fit_curves({{test}}, o);
  ASSERT_TRUE(fit.ok()) << fit.message;
  CurveOptions c;
  c.depths_mm = test.depth_mm;
  Problem unit = paper();
  unit.material.shear_modulus_mpa = 1.0;
  const auto curve = loading_curve(unit, c);
  ASSERT_TRUE(curve.ok());
  double fd = 0.0, ff = 0.0;
  for (std::size_t i = 0; i < test.force_n.size(); ++i) {
    fd += curve.points[i].force_n * test.force_n[i];
    ff += curve.points[i].force_n * curve.points[i].force_n;
  }
  const double g = fd / ff;
  double ssr = 0.0;
  for (std::size_t i = 0; i < test.force_n.size(); ++i)
    ssr += std::pow(g * curve.points[i].force_n - test.force_n[i], 2);
  const double se = std::sqrt(ssr / (test.force_n.size() - 1.0)) / std::sqrt(ff);
  EXPECT_NEAR(fit.parameters[0].value, g, 1e-8 * g);
  ASSERT_TRUE(fit.parameters[0].standard_error);
  EXPECT_NEAR(*fit.parameters[0].standard_error, se, 1e-6 * se);
  // 95 % interval with t(0.975, 79) = 1.99045.
  EXPECT_NEAR(*fit.parameters[0].ci_upper - g, 1.99045 * se, 1e-4 * se);
}

// Coverage: over seeded repeats the 95 % interval holds the truth in about 95 % of them; at
// least 90 % (for 100 repeats the binomial sd is 2.2 %).
TEST(CurveFit, ShearModulusIntervalsCoverTheTruth) {
  const int n = repeats(100);
  int inside = 0;
  for (int seed = 1; seed <= n; ++seed) {
    const auto test = synthetic(paper(), 200, 0.005, static_cast<unsigned>(seed));
    CurveFitOptions o;
    o.free = {CurveParameter::ShearModulus};
    const auto fit = fit_curves({{test}}, o);
    ASSERT_TRUE(fit.ok()) << fit.message;
    inside += covers(fit.parameters[0], 0.06);
  }
  std::printf("%d of %d 95 %% intervals hold the truth\n", inside, n);
  EXPECT_GE(inside, (9 * n + 9) / 10) << inside << " of " << n;
}

TEST(CurveFit, JLimIntervalsCoverTheTruth) {
  const int n = repeats(20);
  int inside = 0;
  for (int seed = 1; seed <= n; ++seed) {
    auto test = synthetic(paper(), 100, 0.005, static_cast<unsigned>(1000 + seed));
    std::get<Gent>(test.problem.material.law).j_lim = 150.0;
    CurveFitOptions o;
    o.free = {CurveParameter::JLim};
    const auto fit = fit_curves({{test}}, o);
    ASSERT_TRUE(fit.ok()) << fit.message;
    inside += covers(fit.parameters[0], 125.0);
  }
  std::printf("%d of %d 95 %% intervals hold the truth\n", inside, n);
  EXPECT_GE(inside, (9 * n + 9) / 10) << inside << " of " << n;
}

// Joint fits: two tests (2 and 4 mm probes, 0.2 and 0.3 mm thick) in G, J_lim and friction,
// and four tests (probes 1 to 4 mm) in G and J_lim, over seeded repeats: every parameter's
// 95 % interval holds the truth in at least 90 % of 100 repeats (the slow label; measured for
// the three-parameter fit: 92, 92 and 94 of 100), and of the default run's 10 and 5 at least
// 80 % (at a true 95 %, 8 of 10 or fewer happens 8.6 % of the time: 90 % would be a coin that
// fails one run in ten; the first 40 repeats gave 36, 34, 37).
void expect_joint_coverage(const std::vector<Problem>& truths,
                           const std::vector<CurveParameter>& free, int n, unsigned seed0,
                           double min_share) {
  const auto start_of = [](CurveParameter f) {
    return f == CurveParameter::ShearModulus ? 0.07 : f == CurveParameter::JLim ? 110.0 : 0.25;
  };
  std::vector<int> inside(free.size(), 0);
  for (int k = 0; k < n; ++k) {
    CurveFitProblem problem;
    for (std::size_t t = 0; t < truths.size(); ++t) {
      auto test = synthetic(truths[t], 60, 0.005, seed0 + static_cast<unsigned>(100 * k + t));
      // The free parameters start off the truth; the fixed ones are the truth.
      for (const auto f : free) set_value(f, test.problem, start_of(f));
      problem.tests.push_back(test);
    }
    CurveFitOptions o;
    o.free = free;
    const auto fit = fit_curves(problem, o);
    ASSERT_TRUE(fit.ok()) << fit.message;
    for (std::size_t j = 0; j < free.size(); ++j) {
      const bool in = covers(fit.parameters[j], value_of(free[j], truths.front()));
      inside[j] += in;
      if (!in)
        std::printf("  repeat %d: %s = %.6g +- %.3g\n",
                    k,
                    to_token(free[j]).c_str(),
                    fit.parameters[j].value,
                    fit.parameters[j].standard_error.value_or(-1.0));
    }
  }
  for (std::size_t j = 0; j < free.size(); ++j) {
    std::printf(
        "%s: %d of %d 95 %% intervals hold the truth\n", to_token(free[j]).c_str(), inside[j], n);
    EXPECT_GE(inside[j], (n >= 100 ? 0.9 : min_share) * n)
        << to_token(free[j]) << ": " << inside[j] << " of " << n;
  }
}

TEST(CurveFit, JointTwoTestThreeParameterIntervalsCoverTheTruth) {
  Problem small = paper(), large = paper();
  large.indenter = FlatPunch{4.0};
  large.geometry.thickness_mm = 0.3;
  expect_joint_coverage(
      {small, large},
      {CurveParameter::ShearModulus, CurveParameter::JLim, CurveParameter::Friction},
      repeats(10),
      5000,
      0.8);
}

TEST(CurveFit, JointFourTestIntervalsCoverTheTruth) {
  std::vector<Problem> truths;
  for (const double a : {1.0, 2.0, 3.0, 4.0}) {
    Problem p = paper();
    p.indenter = FlatPunch{a};
    truths.push_back(p);
  }
  expect_joint_coverage(
      truths, {CurveParameter::ShearModulus, CurveParameter::JLim}, repeats(5), 9000, 0.8);
}

// Two tests of one material with different probes, fitted jointly in G, J_lim and friction.
TEST(CurveFit, JointFitOfTwoTestsRecoversThreeParameters) {
  Problem small = paper(), large = paper();
  large.indenter = FlatPunch{4.0};
  large.geometry.thickness_mm = 0.3;
  auto a = synthetic(small, 100, 0.003, 11), b = synthetic(large, 100, 0.003, 12);
  for (auto* t : {&a, &b}) {
    t->problem.material.shear_modulus_mpa = 0.07;
    std::get<Gent>(t->problem.material.law).j_lim = 110.0;
    t->problem.friction = 0.3;
  }
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus, CurveParameter::JLim, CurveParameter::Friction};
  const auto fit = fit_curves({{a, b}}, o);
  ASSERT_TRUE(fit.ok()) << fit.message;
  ASSERT_EQ(fit.correlation.size(), 3u);
  const double truth[] = {0.06, 125.0, 0.18};
  for (int j = 0; j < 3; ++j) {
    EXPECT_TRUE(covers(fit.parameters[static_cast<std::size_t>(j)], truth[j]))
        << fit.parameters[static_cast<std::size_t>(j)].name;
    EXPECT_NEAR(
        fit.correlation[static_cast<std::size_t>(j)][static_cast<std::size_t>(j)], 1.0, 1e-12);
  }
  EXPECT_EQ(fit.tests.size(), 2u);
  EXPECT_EQ(fit.points, 200);
}

// A membrane held until the force reaches 0.3 N, fitted in G alone through the switch (a
// measured depth there reads the sliding state).  The held force does not scale with G at a
// fixed threshold in N: the switch moves with G (the normalised curve is not reused across G).
TEST(CurveFit, ShearModulusThroughTheSwitch) {
  Problem truth = paper();
  truth.stick = {StickRule::Force, 0.3};
  auto test = synthetic(truth, 120, 0.002, 41);
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus};
  test.problem.material.shear_modulus_mpa = 0.07;
  const auto fit = fit_curves({{test}}, o);
  ASSERT_TRUE(fit.ok()) << fit.message;
  EXPECT_TRUE(covers(fit.parameters[0], 0.06)) << fit.parameters[0].value;
  EXPECT_EQ(unit_of(CurveParameter::StickThreshold, truth), "N");
}

// The stick threshold free: the residuals are a step function of it, so it is fitted by the
// profile over the place of the switch.  The thresholds that switch between the same two
// measured depths explain the record equally: the estimate is the middle of that range, the
// interval (cost rise <= 3.84 residual variances, widened by G's uncertainty of the held force)
// holds the truth.  The record's points are 0.3 mm apart near the switch at 16.8 mm, where the
// held force grows by ~5 % a point: the interval is a few % of the threshold wide.
TEST(CurveFit, StickThresholdFromTheProfileHoldsTheTruth) {
  Problem truth = paper();
  truth.stick = {StickRule::Force, 0.3};
  auto test = synthetic(truth, 120, 0.002, 41);
  test.problem.material.shear_modulus_mpa = 0.07;
  test.problem.stick.threshold = 0.2;
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus, CurveParameter::StickThreshold};
  const auto fit = fit_curves({{test}}, o);
  ASSERT_TRUE(fit.ok()) << fit.message;
  ASSERT_EQ(fit.parameters.size(), 2u);
  const auto& tau = fit.parameters[1];
  EXPECT_EQ(tau.name, "stick-threshold");
  EXPECT_EQ(tau.unit, "N");
  EXPECT_TRUE(tau.profile_interval);
  EXPECT_FALSE(tau.standard_error);
  ASSERT_TRUE(tau.ci_lower && tau.ci_upper);
  std::printf(
      "stick-threshold %.6g N, 95 %% interval [%.6g, %.6g] N; G %.6g +- %.3g MPa; %d "
      "curves\n",
      tau.value,
      *tau.ci_lower,
      *tau.ci_upper,
      fit.parameters[0].value,
      fit.parameters[0].standard_error.value_or(-1.0),
      fit.curve_evaluations);
  std::printf("%s\n", tau.note.c_str());
  EXPECT_TRUE(covers(tau, 0.3)) << tau.note;
  EXPECT_LT(*tau.ci_upper - *tau.ci_lower, 0.1 * 0.3);
  EXPECT_TRUE(covers(fit.parameters[0], 0.06)) << fit.parameters[0].value;
  EXPECT_NE(tau.note.find("the switch lies between the measured depths"), std::string::npos)
      << tau.note;
  ASSERT_EQ(fit.correlation.size(), 2u);
  EXPECT_EQ(fit.correlation[0][1], 0.0);
  EXPECT_EQ(fit.fitted_problems[0].stick.rule, StickRule::Force);
  EXPECT_EQ(fit.fitted_problems[0].stick.threshold, tau.value);
  // The estimate reproduces the record: the curve at it switches between the same two depths.
  CurveOptions c;
  c.depths_mm = test.depth_mm;
  const auto at = loading_curve(fit.fitted_problems[0], c);
  ASSERT_TRUE(at.ok()) << at.message;
  ASSERT_TRUE(at.stick_slip.occurs);
  EXPECT_NEAR(at.stick_slip.depth_mm, 16.778, 0.5);
}

// The same record read with an edge-tension rule: the same place of the switch, so the fitted
// edge tension switches the model between the same two measured depths, and the held force
// there is the force rule's estimate (both are the middle of the place at the same G).
TEST(CurveFit, EdgeTensionThresholdSwitchesAtTheSamePlace) {
  Problem truth = paper();
  truth.stick = {StickRule::Force, 0.3};
  auto test = synthetic(truth, 120, 0.002, 41);
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus, CurveParameter::StickThreshold};
  const auto by_force = fit_curves({{test}}, o);
  ASSERT_TRUE(by_force.ok()) << by_force.message;
  test.problem.stick = {StickRule::EdgeTension, 0.02};
  const auto by_tension = fit_curves({{test}}, o);
  ASSERT_TRUE(by_tension.ok()) << by_tension.message;
  EXPECT_EQ(by_tension.parameters[1].unit, "N/mm");
  EXPECT_EQ(by_tension.parameters[1].note, by_force.parameters[1].note);  // the same depths
  const auto at = [](const Problem& p, double threshold) {
    Problem q = p;
    q.stick.threshold = threshold;
    return stick_slip_boundary(q);
  };
  const auto& fitted = by_tension.fitted_problems[0];
  const auto mid = at(fitted, by_tension.parameters[1].value);
  ASSERT_TRUE(mid.ok() && mid.switches) << mid.message;
  EXPECT_GT(mid.depth_mm, 16.563);
  EXPECT_LE(mid.depth_mm, 16.8641);
  EXPECT_NEAR(mid.force_stuck_n, by_force.parameters[1].value, 1e-3 * 0.3);
  // The interval's ends switch at (or, widened by G's uncertainty, just beyond) those depths.
  EXPECT_LT(at(fitted, *by_tension.parameters[1].ci_lower).depth_mm, 16.563 + 1e-6);
  EXPECT_GT(at(fitted, *by_tension.parameters[1].ci_upper).depth_mm, 16.8641 - 1e-6);
}

// A depth threshold: the interval is exactly the measured depths around the switch (nothing
// else moves it), and J_lim is re-fitted at each place too.
TEST(CurveFit, DepthThresholdIsBracketedByTheMeasuredDepths) {
  Problem truth = paper();
  truth.stick = {StickRule::Depth, 10.0};
  auto test = synthetic(truth, 80, 0.003, 43);
  test.problem.stick.threshold = 20.0;
  std::get<Gent>(test.problem.material.law).j_lim = 150.0;
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus, CurveParameter::StickThreshold, CurveParameter::JLim};
  const auto fit = fit_curves({{test}}, o);
  ASSERT_TRUE(fit.ok()) << fit.message;
  const auto& tau = fit.parameters[1];
  ASSERT_TRUE(tau.ci_lower && tau.ci_upper);
  std::printf("depth threshold %.6g mm in [%.6g, %.6g] mm; %d curves\n",
              tau.value,
              *tau.ci_lower,
              *tau.ci_upper,
              fit.curve_evaluations);
  const auto next = std::upper_bound(test.depth_mm.begin(), test.depth_mm.end(), 10.0);
  ASSERT_NE(next, test.depth_mm.end());
  EXPECT_EQ(*tau.ci_upper, *next);
  EXPECT_EQ(*tau.ci_lower, *(next - 1));
  EXPECT_TRUE(covers(tau, 10.0));
  EXPECT_TRUE(covers(fit.parameters[0], 0.06)) << fit.parameters[0].value;
  EXPECT_TRUE(covers(fit.parameters[2], 125.0)) << fit.parameters[2].value;
}

// Over seeded repeats (noise 0.2 % of the largest force) the threshold's interval holds the
// truth at least at its rate.
TEST(CurveFit, StickThresholdIntervalsCoverTheTruth) {
  const int n = repeats(10);
  int inside = 0;
  for (int seed = 1; seed <= n; ++seed) {
    Problem truth = paper();
    truth.stick = {StickRule::Force, 0.3};
    auto test = synthetic(truth, 120, 0.002, static_cast<unsigned>(3000 + seed));
    CurveFitOptions o;
    o.free = {CurveParameter::ShearModulus, CurveParameter::StickThreshold};
    const auto fit = fit_curves({{test}}, o);
    ASSERT_TRUE(fit.ok()) << fit.message;
    const bool in = covers(fit.parameters[1], 0.3);
    inside += in;
    if (!in)
      std::printf("  seed %d: %.6g in [%.6g, %.6g]\n",
                  seed,
                  fit.parameters[1].value,
                  fit.parameters[1].ci_lower.value_or(-1.0),
                  fit.parameters[1].ci_upper.value_or(-1.0));
  }
  std::printf("%d of %d 95 %% intervals hold the truth\n", inside, n);
  EXPECT_GE(inside, (9 * n + 9) / 10) << inside << " of " << n;
}

// A record without a switch (held beyond its end) does not identify the threshold: OnBound,
// saying so.  Refused: the threshold with several tests, or with the contact offset.  Alone (G
// held at the truth) each place is the curve itself: the interval holds the truth.
TEST(CurveFit, StickThresholdWithoutASwitchAndRefusals) {
  Problem truth = paper();
  truth.stick = {StickRule::Force, 5.0};
  auto test = synthetic(truth, 40, 0.003, 45, 0.5);
  test.problem.stick.threshold = 0.1;
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus, CurveParameter::StickThreshold};
  const auto fit = fit_curves({{test}}, o);
  EXPECT_EQ(fit.status, Status::OnBound) << fit.message;
  EXPECT_NE(fit.message.find("past its last point"), std::string::npos) << fit.message;
  EXPECT_FALSE(fit.parameters[1].identifiable);
  EXPECT_THROW(fit_curves({{test, test}}, o), InvalidInput);
  Problem held = paper();
  held.stick = {StickRule::Force, 0.3};
  auto with_switch = synthetic(held, 120, 0.002, 41);
  with_switch.problem.stick.threshold = 0.2;
  o.free = {CurveParameter::StickThreshold};
  const auto alone = fit_curves({{with_switch}}, o);
  ASSERT_TRUE(alone.ok()) << alone.message;
  ASSERT_EQ(alone.parameters.size(), 1u);
  EXPECT_TRUE(covers(alone.parameters[0], 0.3)) << alone.parameters[0].note;
  EXPECT_TRUE(alone.correlation.empty());
  o.free = {
      CurveParameter::ShearModulus, CurveParameter::StickThreshold, CurveParameter::ContactOffset};
  EXPECT_THROW(fit_curves({{test}}, o), InvalidInput);
}

// One record in G, J_lim and friction (the bench's case): the Part II on the probe's side,
// from 15.5 mm on, carries the friction; over seeded repeats each interval holds the truth at
// its rate (100 under the slow label).
TEST(CurveFit, OneRecordThreeParameterIntervalsCoverTheTruth) {
  expect_joint_coverage(
      {paper()},
      {CurveParameter::ShearModulus, CurveParameter::JLim, CurveParameter::Friction},
      repeats(10),
      7000,
      0.8);
}

// A record as a machine writes it: the crosshead from 0, the contact at `contact_mm`, before it
// 30 points of force noise only, after it the model's curve plus the same noise.
std::string machine_record(const CurveTest& curve, double contact_mm, double noise_sd,
                           unsigned seed) {
  test::SeededNoise noise(seed, noise_sd);
  std::string text = "depth_mm,force_n\n";
  for (int i = 0; i < 30; ++i) {
    const double d = contact_mm * i / 30.0;
    text += std::to_string(d) + "," + std::to_string(noise()) + "\n";
  }
  char line[64];
  for (std::size_t i = 0; i < curve.depth_mm.size(); ++i) {
    std::snprintf(
        line, sizeof line, "%.9f,%.9f\n", contact_mm + curve.depth_mm[i], curve.force_n[i]);
    text += line;
  }
  return text;
}

// A contact point found from the data is late: the force grows as depth^3, so it rises above
// the baseline's noise only millimetres after the contact.  The measured depths are then short
// by that much and G comes out biased; fitting each test's contact offset (model depth =
// measured depth - offset) gives the offset back and removes the bias.
TEST(CurveFit, ContactOffsetRemovesTheBiasOfAContactFoundLate) {
  const Problem truth = paper();
  const auto curve = synthetic(truth, 100, 0.005, 61);
  const double f_max = *std::max_element(curve.force_n.begin(), curve.force_n.end());
  const auto record = parse_force_depth_record(
      machine_record(curve, 2.0, 0.005 * f_max, 62), "machine", RecordFormat{});
  ASSERT_TRUE(record.contact_found);
  const double late = record.contact_depth_mm - 2.0;  // the true offset is -late
  CurveTest test;
  test.name = "machine";
  test.problem = truth;
  test.depth_mm = record.depth_mm;
  test.force_n = record.force_n;
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus, CurveParameter::JLim};
  const auto found = fit_curves({{test}}, o);
  o.free.push_back(CurveParameter::ContactOffset);
  const auto fitted = fit_curves({{test}}, o);
  ASSERT_TRUE(fitted.ok()) << fitted.message;
  ASSERT_EQ(fitted.parameters.size(), 3u);
  const auto& offset = fitted.parameters[2];
  EXPECT_EQ(offset.test, "machine");
  EXPECT_EQ(offset.unit, "mm");
  std::printf(
      "contact found %.4g mm late; G %.6g +- %.3g MPa (contact as found, %s), "
      "%.6g +- %.3g MPa with the offset fitted: %.6g +- %.3g mm\n",
      late,
      found.parameters[0].value,
      found.parameters[0].standard_error.value_or(-1.0),
      to_string(found.status).c_str(),
      fitted.parameters[0].value,
      fitted.parameters[0].standard_error.value_or(-1.0),
      offset.value,
      offset.standard_error.value_or(-1.0));
  EXPECT_GT(late, 1.0);  // millimetres late, the point of the exercise
  EXPECT_TRUE(covers(offset, -late)) << offset.value;
  EXPECT_TRUE(covers(fitted.parameters[0], 0.06)) << fitted.parameters[0].value;
  EXPECT_TRUE(covers(fitted.parameters[1], 125.0)) << fitted.parameters[1].value;
  // As found, G is off by many of its standard errors.
  EXPECT_FALSE(covers(found.parameters[0], 0.06)) << found.parameters[0].value;
}

// Each test has its own offset: a joint fit of a 2 mm record whose contact was taken 1 mm late
// and a 4 mm record whose contact was taken 0.5 mm early (its first points lie before the model's
// contact: no force there) gives both back with the shared G and J_lim.
TEST(CurveFit, JointFitGivesEachTestItsOffset) {
  Problem small = paper(), large = paper();
  large.indenter = FlatPunch{4.0};
  auto a = synthetic(small, 80, 0.003, 71), b = synthetic(large, 80, 0.003, 72);
  for (auto& d : a.depth_mm) d -= 1.0;
  for (auto& d : b.depth_mm) d += 0.5;
  while (a.depth_mm.front() <= 0.0) {
    a.depth_mm.erase(a.depth_mm.begin());
    a.force_n.erase(a.force_n.begin());
  }
  b.depth_mm.insert(b.depth_mm.begin(), {0.1, 0.3});
  b.force_n.insert(b.force_n.begin(), {0.0, 0.0});
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus, CurveParameter::JLim, CurveParameter::ContactOffset};
  a.name = "a";
  b.name = "b";
  const auto fit = fit_curves({{a, b}}, o);
  ASSERT_TRUE(fit.ok()) << fit.message;
  ASSERT_EQ(fit.parameters.size(), 4u);
  EXPECT_EQ(fit.parameters[2].test, "a");
  EXPECT_EQ(fit.parameters[3].test, "b");
  EXPECT_TRUE(covers(fit.parameters[0], 0.06)) << fit.parameters[0].value;
  EXPECT_TRUE(covers(fit.parameters[1], 125.0)) << fit.parameters[1].value;
  EXPECT_TRUE(covers(fit.parameters[2], -1.0)) << fit.parameters[2].value;
  EXPECT_TRUE(covers(fit.parameters[3], 0.5)) << fit.parameters[3].value;
}

// The critical I1 moves only the puncture point: with it, it is fitted with G.
TEST(CurveFit, PuncturePointDeterminesTheCriticalI1) {
  auto test = synthetic(paper(), 80, 0.003, 21, 1.0, true);
  test.problem.critical_i1 = 80.0;
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus, CurveParameter::CriticalI1};
  const auto fit = fit_curves({{test}}, o);
  ASSERT_TRUE(fit.ok()) << fit.message;
  // The synthetic puncture point is exact: the fit puts it back within a fraction of its sd.
  EXPECT_NEAR(fit.parameters[1].value, 95.2, 0.5);
  EXPECT_TRUE(covers(fit.parameters[1], 95.2));
  ASSERT_TRUE(fit.tests[0].model_puncture);
}

// A record that stops at a third of the puncture depth hardly reaches the Gent stiffening: its
// J_lim is not identifiable, and the fit says so and which test would identify it: a warning
// at an interior optimum, or (this seed) J_lim run off to its upper bound, neo-Hookean.
TEST(CurveFit, ShallowRecordLeavesJLimNotIdentifiable) {
  auto test = synthetic(paper(), 60, 0.005, 31, 0.3);
  test.problem.critical_i1 = 10.0;  // J_lim's floor, critical I1 - 3, out of the way
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus, CurveParameter::JLim};
  const auto fit = fit_curves({{test}}, o);
  EXPECT_FALSE(fit.parameters[1].identifiable && fit.ok());
  const std::string text = fit.ok() ? fit.warnings.at(0) : fit.message;
  EXPECT_TRUE(fit.ok() || fit.status == Status::OnBound) << fit.message;
  EXPECT_NE(text.find("not identifiable"), std::string::npos) << text;
  EXPECT_NE(text.find("deeper"), std::string::npos) << text;
  // G stays determined: the force scale is in every point.
  EXPECT_NEAR(fit.parameters[0].value, 0.06, 0.06 * 0.05);
}

// Outliers (five points 10 % of the largest force too high, a slipping grip): least squares
// is pulled off the truth, a Huber loss with a scale of twice the noise is not.  (Ceres applies
// a loss to a residual block's whole squared norm: with one block per test the loss did
// nothing at all, hence one block per point under a robust loss.)
TEST(CurveFit, HuberLossResistsOutliers) {
  auto test = synthetic(paper(), 100, 0.003, 51);
  const double f_max = *std::max_element(test.force_n.begin(), test.force_n.end());
  for (const std::size_t i : {20u, 35u, 50u, 65u, 80u}) test.force_n[i] += 0.1 * f_max;
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus};
  const auto plain = fit_curves({{test}}, o);
  ASSERT_TRUE(plain.ok()) << plain.message;
  o.loss = RobustLoss::Huber;
  o.loss_scale_n = 2.0 * 0.003 * f_max;
  const auto huber = fit_curves({{test}}, o);
  ASSERT_TRUE(huber.ok()) << huber.message;
  // Least squares is 0.9 % high (its interval, widened by the outliers' share of the residual
  // sd, still holds the truth); Huber's error is a quarter of that or less.
  EXPECT_GT(std::abs(plain.parameters[0].value - 0.06), 0.005 * 0.06) << plain.parameters[0].value;
  EXPECT_LT(std::abs(huber.parameters[0].value - 0.06),
            0.25 * std::abs(plain.parameters[0].value - 0.06));
  EXPECT_TRUE(covers(huber.parameters[0], 0.06)) << huber.parameters[0].value;
}

// A flat record is no indentation curve: no clear "converged".
TEST(CurveFit, FlatRecordIsOutsideTheModel) {
  auto test = synthetic(paper(), 100, 0.0, 1);
  for (auto& f : test.force_n) f = 1.0;
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus, CurveParameter::JLim};
  const auto fit = fit_curves({{test}}, o);
  EXPECT_FALSE(fit.ok());
  EXPECT_TRUE(fit.status == Status::OutsideModel || fit.status == Status::OnBound)
      << to_string(fit.status) << ": " << fit.message;
  EXPECT_FALSE(fit.message.empty());
}

// A material stiffer than the largest allowed G ends on that bound, named.
TEST(CurveFit, TooStiffRecordEndsOnTheBound) {
  Problem stiff = paper();
  stiff.material.shear_modulus_mpa = 0.5;
  auto test = synthetic(stiff, 60, 0.002, 3);
  test.problem.material.shear_modulus_mpa = 0.06;
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus};
  o.bounds = {{CurveParameter::ShearModulus, 0.01, 0.2}};
  const auto fit = fit_curves({{test}}, o);
  EXPECT_EQ(fit.status, Status::OnBound) << fit.message;
  EXPECT_NE(fit.message.find("shear-modulus"), std::string::npos) << fit.message;
  EXPECT_TRUE(fit.parameters[0].on_bound);
}

TEST(CurveFit, RefusesBadInput) {
  const auto good = synthetic(paper(), 10, 0.01, 1);
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus};
  auto expect_refused = [&](CurveTest t, CurveFitOptions opt, const std::string& words) {
    try {
      fit_curves({{t}}, opt);
      ADD_FAILURE() << "accepted: " << words;
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  auto few = good;
  few.depth_mm.resize(1);
  few.force_n.resize(1);
  expect_refused(few, o, "at least 2 needed");
  auto backwards = good;
  std::swap(backwards.depth_mm[3], backwards.depth_mm[4]);
  expect_refused(backwards, o, "point 5: the depth");
  auto crit = o;
  crit.free = {CurveParameter::CriticalI1};
  expect_refused(good, crit, "no test has a puncture point");
  auto twice = o;
  twice.free = {CurveParameter::ShearModulus, CurveParameter::ShearModulus};
  expect_refused(good, twice, "named twice");
  auto neo = good;
  neo.problem.material.law = NeoHookean{};
  auto jlim = o;
  jlim.free = {CurveParameter::JLim};
  expect_refused(neo, jlim, "not gent");
  EXPECT_FALSE(curve_parameter_from_token("modulus"));
  EXPECT_EQ(curve_parameter_from_token("critical-i1"), CurveParameter::CriticalI1);
}

}  // namespace
}  // namespace puncture
