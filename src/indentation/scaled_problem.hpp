#pragma once
// Conversion between the user's Problem (mm, N, MPa) and the solver's normalised variables.
#include "indentation/force_solver.hpp"
#include "puncture/equilibrium.hpp"

namespace puncture::detail {

ScaledSettings scaled_settings(const Problem& problem, const SolverOptions& options);

// Physical Equilibrium (with fields when options.record_fields) from a normalised solution.
Equilibrium to_physical(const Problem& problem, const ScaledSolution& sol, Stage stage,
                        const SolverOptions& options);

// Solve at normalised force f in the given stage, dispatching on the material law once.
ScaledSolution solve_scaled(const Problem& problem, double f, Stage stage,
                            const SolverOptions& options);

// Normalised force at normalised depth d in the given stage; the solution is returned.
ScaledSolution solve_scaled_at_depth(const Problem& problem, double d, Stage stage,
                                     const SolverOptions& options, double f_guess = 0.0);

// Largest I1 anywhere in the membrane, Part III included.
double max_first_invariant(const ScaledSolution& sol);

// See ForceSolver::part_two_onset.
std::optional<ScaledSolution> part_two_onset(const Problem& problem, const SolverOptions& options);

// See ForceSolver::puncture_at_corner.
std::optional<ScaledSolution> puncture_at_corner(const Problem& problem,
                                                 const SolverOptions& options);

}  // namespace puncture::detail
