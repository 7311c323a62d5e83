#pragma once
// How every result and every input error is reported.
//  - A result carries a Status and a message (ok() when Converged): a load the membrane cannot
//    carry, or a solver that does not converge, is a value, never an exception.
//  - Invalid input is a list of ValidationError {parameter, message}.  `parameter` is the path of
//    the attribute in the problem ("geometry.clamp_radius_mm", "material.law.j_lim") or the name
//    of the argument ("pressure_mpa"), so that the CLI and Python name their own flag or keyword
//    without reading the message.  Functions that do not return a Status throw InvalidInput (a
//    std::invalid_argument) carrying the list.
#include <stdexcept>
#include <string>
#include <vector>

namespace puncture {

enum class Status {
  Converged,
  NoConvergence,   // the shooting did not reach the clamp condition; message says where
  BeyondLocking,   // the load needs stretches beyond the material's locking limit
  StickWrapsSide,  // a held membrane would wrap the indenter's side: outside the stick model
  InvalidInput,    // the problem or the requested load is invalid; message names it
};

std::string to_string(Status status);

struct ValidationError {
  std::string parameter;  // attribute path or argument name, e.g. "geometry.clamp_radius_mm"
  std::string message;    // what is wrong, starting with the parameter's name in words
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
