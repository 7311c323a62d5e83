#pragma once
// Errors that end the program, and the exit code each one gives.
#include <stdexcept>

namespace puncture::cli {

enum ExitCode : int {
  kExitOk = 0,
  kExitBadInput = 1,       // invalid flags, values or files
  kExitSolverFailure = 2,  // the solver gave no usable result
};

// Invalid input; the message names the parameter and its allowed range (exit code 1).
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The solver did not converge, or its result cannot be written (exit code 2).
struct SolveError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace puncture::cli
