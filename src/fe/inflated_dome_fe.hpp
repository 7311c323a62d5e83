#pragma once
// The inflated membrane before contact as the finite elements find it (docs/model.md §17): the
// minimum of U - p V over the free membrane, the start of an indentation at constant pressure.
#include "puncture/finite_element.hpp"
#include "puncture/problem.hpp"

namespace puncture::fe {

struct FeDome {
  FeState state;        // depth 0, force 0: one free part, linear in R from the pole
  double height = 0.0;  // the pole's height above the clamp plane, / (A / L0)
};

// The dome at the problem's pressure (> 0), started from the shooting's first inflated state
// (inflated_dome.hpp) and minimised on `options.elements` elements linear in R.  Throws
// InvalidInput where the shooting has no dome (it bursts, snaps through or overhangs).
FeDome solve_dome(const Problem& problem, const FeOptions& options);

}  // namespace puncture::fe
