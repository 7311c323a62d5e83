#pragma once
// Errors that end the program, and the exit code each one gives.
#include <stdexcept>
#include <string>

#include "puncture/outcome.hpp"

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

// The solver gave no usable result, or its result cannot be written (exit code 2).  `status`
// is the library's (a non-finite result is NoConvergence); its failure kind is printed too.
struct SolveError : std::runtime_error {
  explicit SolveError(const std::string& what, Status status = Status::NoConvergence)
      : std::runtime_error(what), status(status) {}
  Status status;
};

}  // namespace puncture::cli
