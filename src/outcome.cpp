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
    case Status::LimitLoad:
      return "limit load";
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
    case Status::OnBound:
      return "on a bound";
    case Status::Wrinkles:
      return "wrinkles";
  }
  return "?";
}

FailureKind failure_kind(Status s) {
  switch (s) {
    case Status::Converged:
      return FailureKind::None;
    case Status::BeyondLocking:
    case Status::LimitLoad:
    case Status::StickWrapsSide:
    case Status::NotReached:
    case Status::OnBound:  // the data are not those of the law in its range
    case Status::Wrinkles:
      return FailureKind::Physical;
    case Status::OutsideModel:
      return FailureKind::OutsideModel;
    // Evaluations that failed, or two methods that disagree: the solver's trouble.
    case Status::NoConvergence:
    case Status::Incomplete:
    case Status::ChecksFailed:
      return FailureKind::Numerical;
  }
  return FailureKind::Numerical;
}

std::string to_token(FailureKind k) {
  switch (k) {
    case FailureKind::None:
      return "none";
    case FailureKind::Physical:
      return "physical";
    case FailureKind::Numerical:
      return "numerical";
    case FailureKind::OutsideModel:
      return "outside_model";
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
