// Speed of the solver on the paper's default membrane (2 mm indenter, lubricated).
//   BM_PartOneIntegration  the baseline: one integration of Part I at a converged state, the
//                          unit of work every shooting repeats
//   BM_EquilibriumAtForce  one equilibrium at a prescribed force (bracketing shooting)
//   BM_EquilibriumAtDepth  one equilibrium at a prescribed depth (nested bracketing)
//   BM_PunctureDefault     the puncture point alone
//   BM_LoadingCurveDefault the loading curve, 200 depth points from zero to puncture
//   BM_LoadingCurveFlatFrictionless, BM_LoadingCurveSphereTipped  the same without friction, for
//                          the flat punch and the sphere-tipped probe of radius 2 mm
//   BM_LoadingCurveStick.. the same with a stick stage: held until 0.3 N (the switch is one
//                          solve at that force), or until the edge tension reaches 0.02 N/mm
//                          (the switch is a root search over the force)
//   BM_LoadingCurveNearLimitLoad  12 points of a membrane sliding just below its limit load
//   BM_FiniteElements...   the second method (finite_element.hpp), 128 quadratic elements:
//                          held at 20 mm (a plain minimisation, continuation from flat) and
//                          frictionless at 20 mm (side wrapped: the departure is searched)
// Compare them as ratios to the baseline: the machines are noisy, the ratios much less so.
#include <benchmark/benchmark.h>

#include "indentation/dispatch.hpp"
#include "indentation/scaled_problem.hpp"
#include "puncture/finite_element.hpp"
#include "puncture/loading_curve.hpp"

namespace {

using namespace puncture;

void BM_PartOneIntegration(benchmark::State& state) {
  const Problem problem;
  SolverOptions options;
  options.record_fields = false;
  const Gent& law = std::get<Gent>(problem.material.law);
  const detail::IndentationShooting<detail::FlatPunchContact<Gent>> shooting(
      law,
      detail::shooting_settings(options),
      detail::contact_settings(problem, std::get<FlatPunch>(problem.indenter)));
  const auto sol = shooting.solve(Stage::Slip, 0.2);
  for (auto _ : state)
    benchmark::DoNotOptimize(shooting.assemble(sol.configuration, sol.f, sol.parameter, false));
}
BENCHMARK(BM_PartOneIntegration)->Unit(benchmark::kMicrosecond);

void BM_EquilibriumAtForce(benchmark::State& state) {
  const Problem problem;
  for (auto _ : state) benchmark::DoNotOptimize(solve_at_force(problem, 0.4, Stage::Slip));
}
BENCHMARK(BM_EquilibriumAtForce)->Unit(benchmark::kMicrosecond);

void BM_EquilibriumAtDepth(benchmark::State& state) {
  const Problem problem;
  for (auto _ : state) benchmark::DoNotOptimize(solve_at_depth(problem, 20.0, Stage::Slip));
}
BENCHMARK(BM_EquilibriumAtDepth)->Unit(benchmark::kMillisecond);

void BM_PunctureDefault(benchmark::State& state) {
  const Problem problem;
  for (auto _ : state) benchmark::DoNotOptimize(predict_puncture(problem));
}
BENCHMARK(BM_PunctureDefault)->Unit(benchmark::kMillisecond);

// The loading curve of `problem`, 200 depth points to puncture.
void loading_curve_benchmark(benchmark::State& state, const Problem& problem) {
  CurveOptions curve;
  curve.points = 200;
  std::size_t points = 0;
  for (auto _ : state) {
    const auto result = loading_curve(problem, curve);
    if (!result.ok()) state.SkipWithError(result.message.c_str());
    points = result.points.size();
  }
  state.counters["points"] = static_cast<double>(points);
}

// The default problem with a stick rule (none: the default).
Problem with_stick(StickCriterion stick) {
  Problem problem;
  problem.stick = stick;
  return problem;
}

// The default membrane without friction, pushed by `indenter`.
Problem frictionless(Indenter indenter) {
  Problem problem;
  problem.friction = 0.0;
  problem.indenter = indenter;
  return problem;
}

void BM_LoadingCurveDefault(benchmark::State& state) { loading_curve_benchmark(state, {}); }
BENCHMARK(BM_LoadingCurveDefault)->Unit(benchmark::kMillisecond);

// Frictionless, the flat punch and the sphere-tipped probe of the same radius (2 mm): the smooth
// probe's curve should cost at most twice the flat punch's.
void BM_LoadingCurveFlatFrictionless(benchmark::State& state) {
  loading_curve_benchmark(state, frictionless(FlatPunch{2.0}));
}
BENCHMARK(BM_LoadingCurveFlatFrictionless)->Unit(benchmark::kMillisecond);
void BM_LoadingCurveSphereTipped(benchmark::State& state) {
  loading_curve_benchmark(state, frictionless(SphereTipped{2.0}));
}
BENCHMARK(BM_LoadingCurveSphereTipped)->Unit(benchmark::kMillisecond);

// A curve with a stick stage: the switch located by the stick rule, then both sides of it.
void BM_LoadingCurveStickForce(benchmark::State& state) {
  loading_curve_benchmark(state, with_stick({StickRule::Force, 0.3}));
}
BENCHMARK(BM_LoadingCurveStickForce)->Unit(benchmark::kMillisecond);
void BM_LoadingCurveStickEdgeTension(benchmark::State& state) {
  loading_curve_benchmark(state, with_stick({StickRule::EdgeTension, 0.02}));
}
BENCHMARK(BM_LoadingCurveStickEdgeTension)->Unit(benchmark::kMillisecond);

// The robustness issue's slow case: a thin neo-Hookean membrane held to 2.9946 N that slides
// frictionless into Part II 1.4e-4 below its limit load, 12 points (depth control by the Part III
// stretch there).
void BM_LoadingCurveNearLimitLoad(benchmark::State& state) {
  Problem problem;
  problem.indenter = FlatPunch{4.86};
  problem.geometry.thickness_mm = 0.02936;
  problem.material.law = NeoHookean{};
  problem.material.shear_modulus_mpa = 0.6708;
  problem.friction = 0.0;
  problem.critical_i1 = 118.0;
  problem.stick = {StickRule::Force, 2.9946};
  CurveOptions curve;
  curve.points = 12;
  for (auto _ : state) {
    const auto result = loading_curve(problem, curve);
    if (!result.ok()) state.SkipWithError(result.message.c_str());
  }
}
BENCHMARK(BM_LoadingCurveNearLimitLoad)->Unit(benchmark::kMillisecond);

void BM_FiniteElementsHeld(benchmark::State& state) {
  Problem problem;
  problem.stick.rule = StickRule::Always;
  for (auto _ : state) benchmark::DoNotOptimize(fe_solve_at_depth(problem, 20.0, FeContact::Held));
}
BENCHMARK(BM_FiniteElementsHeld)->Unit(benchmark::kMillisecond);

void BM_FiniteElementsFrictionless(benchmark::State& state) {
  Problem problem;
  problem.friction = 0.0;
  for (auto _ : state)
    benchmark::DoNotOptimize(fe_solve_at_depth(problem, 20.0, FeContact::Frictionless));
}
BENCHMARK(BM_FiniteElementsFrictionless)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
