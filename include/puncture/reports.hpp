#pragma once
// Reports of the results in words, the same for every front end (Ceres' BriefReport and
// FullReport): brief_report() is one line with the numbers that matter; full_report() is a block
// of "  label    value unit" lines.  The Python reprs are the brief reports; the CLI's summary is
// the full reports plus its tables.  A number that is not finite is written "n/a", never NaN.
#include <string>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "puncture/problem.hpp"
#include "puncture/verification.hpp"

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

// "Inputs" and the problem's geometry, material, friction, criterion, stick rule, Part II
// equation and force scale, one per line with units.
std::string full_report(const Problem& problem);
// The state's configuration, force, depth, Part III stretch, corner, Part II, corner slope and
// tension ratio, largest I1 against the problem's critical I1 and the clamp residual (not the
// fields); a failure: its status and message.
std::string full_report(const Equilibrium& state, const Problem& problem);
// "Puncture" and its force, depth, stage, configuration, Part III stretch, largest I1 and where
// the crack starts; none found: why.
std::string full_report(const PuncturePrediction& puncture);
// The stick -> slip switch, where Part II appears, and the puncture (full_report of it); a
// failure: its status and message.
std::string full_report(const LoadingCurve& curve, const Problem& problem);
// Every check grouped, with both values, the relative difference, the tolerance and the verdict,
// then "Result: n passed, n failed, n skipped".
std::string full_report(const VerificationReport& report);

}  // namespace puncture
