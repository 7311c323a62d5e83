#include "solve_failure.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

namespace puncture::cli {

namespace {

// What the kind means for the user.
const char* advice(FailureKind kind) {
  switch (kind) {
    case FailureKind::Physical:
      return "physical: the model has no such state for this membrane; change the load or the "
             "input";
    case FailureKind::OutsideModel:
      return "outside the model: the state needs what this model does not cover";
    case FailureKind::Numerical:
    case FailureKind::None:
      break;
  }
  return "numerical: the solver did not converge although a state may exist; please report "
         "this case";
}

}  // namespace

void report_solve_failure(const SolveError& error, const OutputFlags& output) {
  const FailureKind kind = failure_kind(error.status);
  fmt::print(
      stderr, "puncture: solver failure: {}\n  failure kind: {}\n", error.what(), advice(kind));
  if (format_of(output) != Format::Json) return;
  const nlohmann::json doc{{"error",
                            {{"status", to_string(error.status)},
                             {"failure_kind", to_token(kind)},
                             {"message", error.what()}}}};
  try {
    write_output(output, doc.dump(2) + "\n");
  } catch (const std::exception&) {
    // The failure is on stderr already; an unwritable output adds nothing.
  }
}

void report_input_error(const InputError& error, const OutputFlags& output) {
  fmt::print(stderr, "puncture: error: {}\n", error.what());
  // The JSON asked for is only written when the output flags themselves are sound.
  try {
    if (format_of(output) != Format::Json) return;
    const nlohmann::json doc{
        {"error",
         {{"status", "invalid_input"}, {"failure_kind", "input"}, {"message", error.what()}}}};
    write_output(output, doc.dump(2) + "\n");
  } catch (const std::exception&) {
    // The error is on stderr already.
  }
}

}  // namespace puncture::cli
