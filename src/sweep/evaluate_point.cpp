// One point's work: the outputs asked for, through the public solve API.
#include <fmt/format.h>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "puncture/sweep.hpp"

namespace puncture {

namespace {

SweepPuncture puncture_of(const Problem& problem, const SolverOptions& options) {
  PuncturePrediction p = predict_puncture(problem, options);
  if (!p.ok() && options.puncture_top_stretch_start) {
    // Never a failed row that a cold search would solve.
    SolverOptions cold = options;
    cold.puncture_top_stretch_start.reset();
    p = predict_puncture(problem, cold);
  }
  SweepPuncture s;
  s.status = p.status;
  s.message = p.message;
  if (!p.ok()) return s;
  s.force_n = p.force_n;
  s.depth_mm = p.depth_mm;
  s.part_three_stretch = p.part_three_stretch;
  s.max_first_invariant = p.state.max_first_invariant;
  s.crack_reference_radius_mm = p.crack_reference_radius_mm;
  s.crack_radius_mm = p.crack_radius_mm;
  s.crack_location = p.crack_location;
  s.part_two_top_stretch = p.part_two_top_stretch;
  return s;
}

// The stage at `depth_mm` as `puncture state --stage auto` picks it.
Stage stage_at(const StageBoundary& b, double depth_mm) {
  if (b.first_stage == Stage::Slip) return Stage::Slip;
  if (!b.switches) return Stage::Stick;
  return depth_mm <= b.depth_mm ? Stage::Stick : Stage::Slip;
}

std::vector<SweepForceAtDepth> forces_at(const Problem& problem, const std::vector<double>& depths,
                                         const SolverOptions& options) {
  std::vector<SweepForceAtDepth> forces;
  if (depths.empty()) return forces;
  const StageBoundary boundary = stick_slip_boundary(problem, options);
  for (const double depth : depths) {
    SweepForceAtDepth f;
    f.depth_mm = depth;
    if (!boundary.ok()) {
      f.status = boundary.status;
      f.message = "the stick -> slip switch: " + boundary.message;
    } else {
      const Equilibrium e = solve_at_depth(problem, depth, stage_at(boundary, depth), options);
      f.status = e.status;
      f.message = e.message;
      if (e.ok()) f.force_n = e.force_n;
    }
    forces.push_back(std::move(f));
  }
  return forces;
}

}  // namespace

SweepRow evaluate_point(const Problem& problem, const SweepOutputs& outputs,
                        const SolverOptions& options) {
  SolverOptions quiet = options;
  quiet.record_fields = false;  // the rows hold no fields
  SweepRow row;
  row.status = Status::Converged;
  const auto first_failure = [&row](const Outcome& o, const std::string& what) {
    if (row.ok() && !o.ok()) {
      row.status = o.status;
      row.message = what + ": " + o.message;
    }
  };
  if (outputs.puncture) {
    row.puncture = puncture_of(problem, quiet);
    first_failure(*row.puncture, "puncture");
  }
  // The warm start is the puncture search's only.
  quiet.puncture_top_stretch_start.reset();
  row.at_depth = forces_at(problem, outputs.force_at_depth_mm, quiet);
  for (const SweepForceAtDepth& f : row.at_depth)
    first_failure(f, fmt::format("force at depth {} mm", f.depth_mm));
  return row;
}

}  // namespace puncture
