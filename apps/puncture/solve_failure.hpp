#pragma once
// How a solve that gave no usable result is reported: one line on stderr with its failure kind
// (physical, numerical, outside the model), and with --format json also a JSON document on the
// output, so that scripts read the status and kind instead of parsing the message.
#include "cli_error.hpp"
#include "output_options.hpp"

namespace puncture::cli {

void report_solve_failure(const SolveError& error, const OutputFlags& output);

// Invalid input, reported the same way: the message on stderr and, with --format json, a
// document {"error": {"status": "invalid_input", "failure_kind": "input", "message": ...}}.
void report_input_error(const InputError& error, const OutputFlags& output);

}  // namespace puncture::cli
