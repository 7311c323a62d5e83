// Speed of the force-depth fit (curve_fit.hpp) against the loading curve it repeats:
//   BM_LoadingCurveAtRecordDepths  one loading curve at a record's 200 depths (the unit of work)
//   BM_FitCurveThreeParameters     G, J_lim and friction fitted to one 200-point record from a
//                                  start 15-30 % off (the target: <= 2 s on one core)
//   BM_FitCurveFourTests           the same three jointly to four records (target <= 5 s)
//   BM_FitCurveStickThreshold      G and a force threshold (0.3 N) from one 200-point record with
//                                  a switch: the profile over the place of the switch
//   BM_FitCurveContactOffset       G, J_lim and the contact offset from one 200-point record
//                                  whose depths are 1.5 mm short
// The records are the model's with known parameters plus seeded noise (0.5 % of the largest
// force), as in tests/calibration/curve_fit_test.cpp.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "puncture/curve_fit.hpp"
#include "puncture/loading_curve.hpp"

namespace {

using namespace puncture;

CurveTest record(const Problem& truth, unsigned seed) {
  const auto p = predict_puncture(truth);
  CurveTest t;
  t.name = "record";
  t.problem = truth;
  for (int i = 1; i <= 200; ++i) t.depth_mm.push_back(0.95 * p.depth_mm * i / 200);
  CurveOptions c;
  c.depths_mm = t.depth_mm;
  const auto curve = loading_curve(truth, c);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.005 * curve.points.back().force_n);
  // One force per depth: at a stick -> slip switch the curve also has the held and the sliding
  // state at the switch's own depth; a measured depth reads the last point at it.
  for (const double d : t.depth_mm) {
    double f = 0.0;
    for (const auto& pt : curve.points)
      if (pt.depth_mm == d) f = pt.force_n;
    t.force_n.push_back(f + noise(rng));
  }
  // The fit's start, off the truth.
  t.problem.material.shear_modulus_mpa *= 1.2;
  std::get<Gent>(t.problem.material.law).j_lim *= 1.3;
  t.problem.friction *= 1.15;
  return t;
}

CurveFitOptions three_free() {
  CurveFitOptions o;
  o.free = {CurveParameter::ShearModulus, CurveParameter::JLim, CurveParameter::Friction};
  return o;
}

void BM_LoadingCurveAtRecordDepths(benchmark::State& state) {
  const auto t = record(Problem{}, 1);
  CurveOptions c;
  c.depths_mm = t.depth_mm;
  for (auto _ : state) benchmark::DoNotOptimize(loading_curve(Problem{}, c));
}
BENCHMARK(BM_LoadingCurveAtRecordDepths)->Unit(benchmark::kMillisecond);

// The benchmark loop of a fit, with the curves it solved as a counter.
void fit_repeatedly(benchmark::State& state, const CurveFitProblem& problem,
                    const CurveFitOptions& options) {
  int curves = 0;
  for (auto _ : state) {
    const auto fit = fit_curves(problem, options);
    curves = fit.curve_evaluations;
    benchmark::DoNotOptimize(fit);
  }
  state.counters["curves"] = curves;
}

// Argument: -log10 of the function tolerance (8, the default; 10, tighter).
void BM_FitCurveThreeParameters(benchmark::State& state) {
  const CurveFitProblem problem{{record(Problem{}, 1)}};
  auto options = three_free();
  options.function_tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  fit_repeatedly(state, problem, options);
}
BENCHMARK(BM_FitCurveThreeParameters)->Arg(8)->Arg(10)->Unit(benchmark::kMillisecond);

void BM_FitCurveFourTests(benchmark::State& state) {
  CurveFitProblem problem;
  for (int k = 0; k < 4; ++k) {
    Problem truth;
    truth.indenter = FlatPunch{1.0 + 0.5 * k};
    truth.geometry.thickness_mm = 0.2 + 0.05 * k;
    problem.tests.push_back(record(truth, static_cast<unsigned>(10 + k)));
  }
  fit_repeatedly(state, problem, three_free());
}
BENCHMARK(BM_FitCurveFourTests)->Unit(benchmark::kMillisecond);

void BM_FitCurveStickThreshold(benchmark::State& state) {
  Problem truth;
  truth.stick = {StickRule::Force, 0.3};
  auto t = record(truth, 3);
  t.problem.stick.threshold = 0.2;
  CurveFitOptions options;
  options.free = {CurveParameter::ShearModulus, CurveParameter::StickThreshold};
  const CurveFitProblem problem{{t}};
  fit_repeatedly(state, problem, options);
}
BENCHMARK(BM_FitCurveStickThreshold)->Unit(benchmark::kMillisecond);

void BM_FitCurveContactOffset(benchmark::State& state) {
  auto t = record(Problem{}, 4);
  t.problem.friction = Problem{}.friction;
  for (auto& d : t.depth_mm) d -= 1.5;
  while (t.depth_mm.front() <= 0.0) {
    t.depth_mm.erase(t.depth_mm.begin());
    t.force_n.erase(t.force_n.begin());
  }
  CurveFitOptions options;
  options.free = {
      CurveParameter::ShearModulus, CurveParameter::JLim, CurveParameter::ContactOffset};
  const CurveFitProblem problem{{t}};
  fit_repeatedly(state, problem, options);
}
BENCHMARK(BM_FitCurveContactOffset)->Unit(benchmark::kMillisecond);

}  // namespace
