#pragma once
// The puncture along the loading path at the problem's own (constant) pressure: predict_puncture
// (with the check of the face's sliding direction) and what a sealed chamber's puncture search
// evaluates at each trial pressure (without it: the direction is the gas path's, sealed_gas.hpp).
// Defined in loading_curve.cpp.
#include "puncture/loading_curve.hpp"

namespace puncture::detail {

PuncturePrediction puncture_on_path(const Problem& p, const SolverOptions& options,
                                    bool face_slip_checked);

}  // namespace puncture::detail
