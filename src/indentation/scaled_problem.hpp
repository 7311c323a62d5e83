#pragma once
// Conversion between the user's Problem (mm, N, MPa) and the solver's normalised variables, and
// single solves of a Problem (each dispatched once to its shooting: dispatch.hpp).
#include <optional>

#include "indentation/scaled_solution.hpp"
#include "puncture/equilibrium.hpp"

namespace puncture::detail {

// Solve at normalised force f in the given stage.
ScaledSolution solve_scaled(const Problem& problem, double f, Stage stage,
                            const SolverOptions& options);

// Normalised force at normalised depth d in the given stage; the solution is returned.
ScaledSolution solve_scaled_at_depth(const Problem& problem, double d, Stage stage,
                                     const SolverOptions& options, double f_guess = 0.0);

// The puncture solved directly by the contact model, when it knows one (the flat punch: the
// crack at the corner with Part II; FlatPunchContact::direct_puncture).
std::optional<ScaledSolution> direct_puncture(const Problem& problem, const SolverOptions& options);

}  // namespace puncture::detail
