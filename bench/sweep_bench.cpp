// Speed of sweeps: points per second per thread against one puncture solve in the same run.
//   BM_PunctureOnce     one predict_puncture (fields off, as in a sweep) at the central point:
//                       the unit of a sweep's work
//   BM_SweepPuncture/T  a 64-point Latin hypercube of puncture points around the paper's
//                       membrane (friction, critical I1, thickness, shear modulus) on T threads;
//                       items_per_second: points per second in all
//   BM_SweepShare/P    the share of one of P processes (SweepOptions stride P, offset 0; as
//                       rank 0 of mpirun -n P) on 1 thread: it checks and solves its own
//                       points only, so its points per second per core equal the serial run's
//   BM_GridLineWarm/L  a 32-point grid line (L: 0 friction 0.1 to 0.3, 1 critical I1 85 to
//                       105, 2 shear modulus, 3 thickness) of puncture points on 1 thread, cold
//                       and warm (two chains of 16) alternately in each iteration;
//                       warm_over_cold: the ratio of their CPU times (this thread's: the
//                       machine's load does not enter) in the same run
// Per-point cost / one solve: sweep overhead (point list, validation pass, ordered delivery)
// and the points' own spread; T threads / 1 thread: the parallel efficiency.
#include <benchmark/benchmark.h>
#include <time.h>

#include "puncture/loading_curve.hpp"
#include "puncture/sweep.hpp"

namespace {

using namespace puncture;

SweepSpec spec_around_paper() {
  SweepSpec spec;
  spec.design = SweepDesign::LatinHypercube;
  spec.samples = 64;
  spec.seed = 1;
  spec.parameters = {{"friction", {}, {DistributionKind::Uniform, 0.1, 0.3}},
                     {"critical-i1", {}, {DistributionKind::Uniform, 85.0, 105.0}},
                     {"thickness", {}, {DistributionKind::Uniform, 0.18, 0.22}},
                     {"shear-modulus", {}, {DistributionKind::Uniform, 0.054, 0.066}}};
  return spec;
}

Problem problem_at(const SweepPoint& p) {
  Problem problem;
  problem.friction = p.values[0];
  problem.critical_i1 = p.values[1];
  problem.geometry.thickness_mm = p.values[2];
  problem.material.shear_modulus_mpa = p.values[3];
  return problem;
}

void BM_PunctureOnce(benchmark::State& state) {
  Problem problem;
  problem.friction = 0.2;
  problem.critical_i1 = 95.0;
  SolverOptions options;
  options.record_fields = false;
  for (auto _ : state) benchmark::DoNotOptimize(predict_puncture(problem, options));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PunctureOnce)->Unit(benchmark::kMillisecond);

void BM_SweepPuncture(benchmark::State& state) {
  const SweepSpec spec = spec_around_paper();
  SweepOptions options;
  options.threads = static_cast<int>(state.range(0));
  std::size_t failed = 0;
  options.on_row = [&failed](const SweepRow& row) { failed += !row.ok(); };
  for (auto _ : state) benchmark::DoNotOptimize(sweep(spec, problem_at, options));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(spec.samples));
  state.counters["failed"] = static_cast<double>(failed);
}
BENCHMARK(BM_SweepPuncture)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SweepShare(benchmark::State& state) {
  const SweepSpec spec = spec_around_paper();
  SweepOptions options;
  options.threads = 1;
  options.stride = static_cast<std::size_t>(state.range(0));
  std::size_t rows = 0;
  options.on_row = [&rows](const SweepRow&) { ++rows; };
  for (auto _ : state) benchmark::DoNotOptimize(sweep(spec, problem_at, options));
  state.SetItemsProcessed(static_cast<std::int64_t>(rows));
}
BENCHMARK(BM_SweepShare)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// One parameter of the paper's membrane over 32 levels, the others at the paper's values.
struct GridLine {
  const char* name;
  double lower, upper;
  void (*set)(Problem&, double);
};
const GridLine kLines[] = {
    {"friction", 0.1, 0.3, [](Problem& p, double x) { p.friction = x; }},
    {"critical-i1", 85.0, 105.0, [](Problem& p, double x) { p.critical_i1 = x; }},
    {"shear-modulus", 0.054, 0.066, [](Problem& p, double x) { p.material.shear_modulus_mpa = x; }},
    {"thickness", 0.18, 0.22, [](Problem& p, double x) { p.geometry.thickness_mm = x; }},
};

void BM_GridLineWarm(benchmark::State& state) {
  const GridLine& line = kLines[state.range(0)];
  SweepSpec warm;
  warm.parameters = {{line.name, evenly_spaced_levels(line.lower, line.upper, 32), {}}};
  SweepSpec cold = warm;
  cold.warm_start = false;
  const ProblemOfPoint problem_of = [&line](const SweepPoint& point) {
    Problem problem;
    line.set(problem, point.values[0]);
    return problem;
  };
  SweepOptions options;
  options.threads = 1;
  std::size_t failed = 0;
  options.on_row = [&failed](const SweepRow& row) { failed += !row.ok(); };
  // On one thread the sweep runs on this one (OpenMP's master): its CPU time is the sweep's.
  const auto cpu_s = [] {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  };
  double cold_s = 0.0, warm_s = 0.0;
  for (auto _ : state) {
    const double t0 = cpu_s();
    benchmark::DoNotOptimize(sweep(cold, problem_of, options));
    const double t1 = cpu_s();
    benchmark::DoNotOptimize(sweep(warm, problem_of, options));
    cold_s += t1 - t0;
    warm_s += cpu_s() - t1;
  }
  const double points = 32.0 * static_cast<double>(state.iterations());
  state.counters["cold_ms_per_point"] = 1e3 * cold_s / points;
  state.counters["warm_ms_per_point"] = 1e3 * warm_s / points;
  state.counters["warm_over_cold"] = warm_s / cold_s;
  state.counters["failed"] = static_cast<double>(failed);
  state.SetLabel(line.name);
}
BENCHMARK(BM_GridLineWarm)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
