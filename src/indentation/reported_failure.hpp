#pragma once
// The public solve functions report numerical trouble as a status, never by throwing (results
// carry a Status: README, "The library").  An exception from a library routine, e.g. one of
// Boost's root finders handed an interval that turns out not to bracket its root, becomes a
// NoConvergence result with the routine's message.
#include <exception>
#include <stdexcept>
#include <string>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::detail {

// A physical answer found before any solve could start (e.g. a pressure that no inflated state
// holds): reported with its own status, not as a numerical failure.
class PhysicalFailure : public std::runtime_error {
 public:
  PhysicalFailure(Status status, const std::string& message)
      : std::runtime_error(message), status_(status) {}
  Status status() const { return status_; }

 private:
  Status status_;
};

// A trial gas pressure over a sealed chamber past the inflation's limit point (inflated_dome.hpp):
// a PhysicalFailure (OutsideModel) that knows the limit point's pressure [MPa].
class PastLimitPoint : public PhysicalFailure {
 public:
  PastLimitPoint(const std::string& message, double limit_mpa)
      : PhysicalFailure(Status::OutsideModel, message), limit_mpa_(limit_mpa) {}
  double limit_mpa() const { return limit_mpa_; }

 private:
  double limit_mpa_;
};

template <class Result, class Body>
Result reporting_failures(Body&& body) {
  try {
    return body();
  } catch (const PhysicalFailure& e) {
    Result r;
    r.status = e.status();
    r.message = e.what();
    return r;
  } catch (const std::exception& e) {
    Result r;
    r.status = Status::NoConvergence;
    r.message = std::string("numerical failure inside the solver: ") + e.what();
    return r;
  }
}

}  // namespace puncture::detail
