#pragma once
// States at many depths of one problem, as solve_at_depth gives them one at a time (the loading
// curve's event sampling): under the `coulomb` rule on a curved probe the partial-slip family
// after the release (partial_slip_path.hpp) is built once for all of them, not at every depth.
#include <functional>

#include "puncture/equilibrium.hpp"
#include "puncture/problem.hpp"

namespace puncture::detail {

// The state at a depth [mm] in a stage, as solve_at_depth(problem, depth_mm, stage, options).
using DepthSolve = std::function<Equilibrium(double depth_mm, Stage stage)>;

// use(solve) with such a solve for the valid `problem`, the same numbers as solve_at_depth's;
// `solve` is valid during the call only (the family lives in its shooting).
void with_depth_solve(const Problem& problem, const SolverOptions& options,
                      const std::function<void(const DepthSolve&)>& use);

}  // namespace puncture::detail
