#pragma once
// One-line reports of the results, the same for every front end (the Python reprs use them):
// status, stage and configuration, and the numbers that matter, with their units.
#include <string>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture {

// e.g. "converged: slip stage, slip with Part II, force 0.3 N, depth 21.7 mm, Part III stretch
// 2.71, largest I1 14.6"; a failure: its status and message.
std::string brief_report(const Equilibrium& state);
// e.g. "force 0.699 N, depth 38 mm, Part III stretch 6.62, crack at Part II at the indenter's
// corner"; none found: "not found: " and why.
std::string brief_report(const PuncturePrediction& puncture);
// e.g. "converged: 200 points, depth 0 to 38 mm, puncture at 0.699 N"; a failure: its status and
// message.
std::string brief_report(const LoadingCurve& curve);

}  // namespace puncture
