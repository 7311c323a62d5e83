#pragma once
// How a solve that gave no usable result is reported: one line on stderr with its failure kind
// (physical, numerical, outside the model), and with --format json also a JSON document on the
// output, so that scripts read the status and kind instead of parsing the message.
#include "cli_error.hpp"
#include "output_options.hpp"

namespace puncture::cli {

void report_solve_failure(const SolveError& error, const OutputFlags& output);

}  // namespace puncture::cli
