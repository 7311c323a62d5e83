// How uncertain is the puncture force?  A Monte Carlo sweep of critical I1 and friction
// (Latin hypercube, every core) and the percentiles of the force.
#include <fmt/format.h>

#include "puncture/sweep.hpp"
#include "puncture/sweep_statistics.hpp"

int main() {
  using namespace puncture;
  SweepSpec spec;
  spec.design = SweepDesign::LatinHypercube;
  spec.samples = 400;
  spec.seed = 1;
  spec.parameters = {{"critical-i1", {}, {DistributionKind::Normal, 0, 0, 95.2, 4.8}},
                     {"friction", {}, {DistributionKind::TruncatedNormal, 0.1, 0.3, 0.18, 0.03}}};
  SweepStatistics stats({"critical-i1", "friction"}, "puncture_force_n");
  SweepOptions options;
  options.on_row = [&stats](const SweepRow& row) {  // in point order, failures included
    stats.add(row.point.values,
              row.ok() ? std::optional<double>(row.puncture->force_n) : std::nullopt);
  };
  const auto problem_of = [](const SweepPoint& p) {  // the point's values -> a Problem
    Problem problem;
    problem.critical_i1 = p.values[0];
    problem.friction = p.values[1];
    return problem;
  };
  const SweepSummary summary = sweep(spec, problem_of, options);
  fmt::print("{}\n{}", summary.brief_report(), stats.result().report());
  return summary.ok() ? 0 : 1;
}
