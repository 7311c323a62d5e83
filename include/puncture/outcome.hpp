#pragma once
// How every result and every input error is reported.
//  - Every result is an Outcome: a Status and a message (ok() when Converged).  A load the
//    membrane cannot carry, a target the model cannot reach or a solver that does not converge
//    is a value, never an exception.
//  - Invalid input is not an outcome: every function throws InvalidInput (a
//    std::invalid_argument) carrying a list of ValidationError {parameter, message}.
//    `parameter` is the path of the attribute in the problem ("geometry.clamp_radius_mm",
//    "material.law.j_lim") or the name of the argument ("pressure_mpa"), so that the CLI and
//    Python name their own flag or keyword without reading the message.  validation_errors()
//    of a problem lists them without throwing, to report all before anything runs.
#include <stdexcept>
#include <string>
#include <vector>

namespace puncture {

enum class Status {
  Converged,
  NoConvergence,   // the shooting did not reach the clamp condition; message says where
  BeyondLocking,   // the load needs stretches beyond the material's locking limit
  LimitLoad,       // the load is beyond the largest the membrane carries (a law without locking)
  StickWrapsSide,  // a held membrane would wrap the indenter's side: outside the stick model
  NotReached,      // the criterion or the target is not reached in the range the model covers
  Incomplete,      // some of the evaluations behind the result failed; the message lists them
  ChecksFailed,    // a verification check is outside its tolerance
  OutsideModel,    // the state needs what this indenter's model does not cover (message: what)
  OnBound,         // a fit's optimum is on a bound of the law's validity range (message: which)
  Wrinkles,        // the hoop stress turns compressive: the membrane wrinkles there, outside the
                   // tension-only membrane theory (message: where)
};

std::string to_string(Status status);

// Why a result failed, in two kinds that call for different actions:
//  - Physical: the model's answer is that there is no such state (locking, a limit load, the
//    end of a branch, a target beyond reach, a criterion never met).  Change the input.
//  - Numerical: the solver did not converge although a state may exist.  A bug to report.
//  - OutsideModel: the state needs what the chosen model does not cover (e.g. friction on a
//    curved side); neither the membrane's answer nor a solver failure.
enum class FailureKind { None, Physical, Numerical, OutsideModel };
FailureKind failure_kind(Status status);
// "none", "physical", "numerical", "outside_model": as written in JSON.
std::string to_token(FailureKind kind);

struct ValidationError {
  std::string parameter;  // attribute path or argument name, e.g. "geometry.clamp_radius_mm"
  std::string message;    // what is wrong, starting with the parameter's name in words
};

// What every result reports about itself.  Results derive from it:
//   if (const auto p = predict_puncture(problem); p.ok()) use(p.force_n);
//   else fmt::print("{}: {}\n", to_string(p.status), p.message);
struct Outcome {
  Status status = Status::NoConvergence;
  std::string message;  // why, when not ok(); a warning (or empty) when ok()
  bool ok() const { return status == Status::Converged; }
  FailureKind failure_kind() const { return puncture::failure_kind(status); }
};

class InvalidInput : public std::invalid_argument {
 public:
  // what(): `heading` with each message on its own indented line, or, without a heading, the
  // messages alone (one per line).
  explicit InvalidInput(std::vector<ValidationError> errors, const std::string& heading = {});
  // One error: its message alone.
  InvalidInput(std::string parameter, std::string message);
  const std::vector<ValidationError>& errors() const { return errors_; }

 private:
  std::vector<ValidationError> errors_;
};

}  // namespace puncture
