#include "puncture/outcome.hpp"

#include <utility>

namespace puncture {

std::string to_string(Status s) {
  switch (s) {
    case Status::Converged:
      return "converged";
    case Status::NoConvergence:
      return "no convergence";
    case Status::BeyondLocking:
      return "beyond locking";
    case Status::StickWrapsSide:
      return "stick wraps side";
    case Status::NotReached:
      return "not reached";
    case Status::Incomplete:
      return "incomplete";
    case Status::ChecksFailed:
      return "checks failed";
    case Status::OutsideModel:
      return "outside the model";
  }
  return "?";
}

namespace {

std::string text_of(const std::vector<ValidationError>& errors, const std::string& heading) {
  std::string out = heading;
  for (const auto& e : errors) {
    if (!heading.empty())
      out += "\n  ";
    else if (&e != &errors.front())
      out += "\n";
    out += e.message;
  }
  return out;
}

}  // namespace

InvalidInput::InvalidInput(std::vector<ValidationError> errors, const std::string& heading)
    : std::invalid_argument(text_of(errors, heading)), errors_(std::move(errors)) {}

InvalidInput::InvalidInput(std::string parameter, std::string message)
    : InvalidInput({ValidationError{std::move(parameter), std::move(message)}}) {}

}  // namespace puncture
