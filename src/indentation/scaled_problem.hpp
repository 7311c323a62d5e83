#pragma once
// Single normalised solves of a Problem, each dispatched once to its shooting (dispatch.hpp): for
// checks that compare the solver's parts (the public entry points use the shooting directly).
#include <optional>

#include "indentation/scaled_solution.hpp"
#include "puncture/equilibrium.hpp"

namespace puncture::detail {

// Solve at normalised force f in the given stage.
ScaledSolution solve_scaled(const Problem& problem, double f, Stage stage,
                            const SolverOptions& options);

// The puncture solved directly by the contact model, when it knows one (the flat punch: the
// crack at the corner with Part II; FlatPunchContact::direct_puncture).
std::optional<ScaledSolution> direct_puncture(const Problem& problem, const SolverOptions& options);

}  // namespace puncture::detail
