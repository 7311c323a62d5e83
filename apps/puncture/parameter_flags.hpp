#pragma once
// The command-line flag of each parameter the library's validation names (ValidationError's
// parameter: an attribute path of Problem or InflationProblem, or an argument's name).
#include <string>
#include <vector>

#include "puncture/outcome.hpp"

namespace puncture::cli {

// "--flag: message", or the message alone for a parameter without a flag of its own.
std::string with_flag(const ValidationError& error);

// Throws InputError: `heading`, then each error with its flag on its own indented line (after
// the CLI's own `errors`, already worded); nothing when both are empty.
void throw_if_invalid(const char* heading, std::vector<std::string> errors,
                      const std::vector<ValidationError>& validation);

// An input error of the library, as InputError with its flags.
[[noreturn]] void rethrow_with_flags(const InvalidInput& e);

}  // namespace puncture::cli
