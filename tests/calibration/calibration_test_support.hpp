#pragma once
// Pieces several calibration tests share.
#include "puncture/options.hpp"
#include "puncture/problem.hpp"

namespace puncture::test {

// Solver options without the fields along the membrane (the calibrations read numbers only).
inline SolverOptions quiet() {
  SolverOptions o;
  o.record_fields = false;
  return o;
}

// The paper's dry test with the small indenter: a 1 mm flat punch, friction 1.95.
inline Problem dry_small_indenter() {
  Problem p;
  p.indenter = FlatPunch{1.0};
  p.friction = 1.95;
  return p;
}

// A calibration run on a prediction of the model gives its parameter back to this (relative).
constexpr double kRecoveryTol = 1e-6;

}  // namespace puncture::test
