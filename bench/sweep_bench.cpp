// Speed of sweeps: points per second per thread against one puncture solve in the same run.
//   BM_PunctureOnce     one predict_puncture (fields off, as in a sweep) at the central point:
//                       the unit of a sweep's work
//   BM_SweepPuncture/T  a 64-point Latin hypercube of puncture points around the paper's
//                       membrane (friction, critical I1, thickness, shear modulus) on T threads;
//                       items_per_second: points per second in all
//   BM_SweepShare/P    the share of one of P processes (SweepOptions stride P, offset 0; as
//                       rank 0 of mpirun -n P) on 1 thread: it checks and solves its own
//                       points only, so its points per second per core equal the serial run's
// Per-point cost / one solve: sweep overhead (point list, validation pass, ordered delivery)
// and the points' own spread; T threads / 1 thread: the parallel efficiency.
#include <benchmark/benchmark.h>

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

}  // namespace

BENCHMARK_MAIN();
