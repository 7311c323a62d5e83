#pragma once
// Each sweep point's Problem, built by the code that reads the command line's flags
// (add_problem_options and make_problem), so every flag of the problem, present and future,
// can be fixed or swept without a second list.
#include <string>
#include <utility>
#include <vector>

#include "puncture/sweep.hpp"

namespace puncture::cli {

// The problem of `point` (its parameters named by `spec`) with the `fixed` flags.  Throws
// InputError naming the point, its values and the flag when they are not a valid problem.
ProblemOfPoint problem_of_flags(const SweepSpec& spec,
                                std::vector<std::pair<std::string, std::string>> fixed);

}  // namespace puncture::cli
