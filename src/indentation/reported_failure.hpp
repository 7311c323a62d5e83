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

inline void mark_failed(Equilibrium& r, std::string message) {
  r.status = Status::NoConvergence;
  r.message = std::move(message);
}
inline void mark_failed(StageBoundary& r, std::string message) {
  r.status = Status::NoConvergence;
  r.message = std::move(message);
}
inline void mark_failed(LoadingCurve& r, std::string message) {
  r.status = Status::NoConvergence;
  r.message = std::move(message);
}
inline void mark_failed(PuncturePrediction& r, std::string message) {
  r.found = false;
  r.message = std::move(message);
}

template <class Result, class Body>
Result reporting_failures(Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    Result r;
    mark_failed(r, std::string("numerical failure inside the solver: ") + e.what());
    return r;
  }
}

}  // namespace puncture::detail
