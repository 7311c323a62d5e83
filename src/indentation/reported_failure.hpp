#pragma once
// The public solve functions report numerical trouble as a status, never by throwing (results
// carry a Status: README, "The library").  An exception from a library routine, e.g. one of
// Boost's root finders handed an interval that turns out not to bracket its root, becomes a
// NoConvergence result with the routine's message.
#include <exception>
#include <string>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::detail {

template <class Result, class Body>
Result reporting_failures(Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    Result r;
    r.status = Status::NoConvergence;
    r.message = std::string("numerical failure inside the solver: ") + e.what();
    return r;
  }
}

}  // namespace puncture::detail
