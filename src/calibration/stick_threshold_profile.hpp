#pragma once
// The force-depth fit with the stick threshold free (docs/model.md "Fitting force-depth
// curves"): the residuals are a step function of the threshold (the sliding state at a depth
// does not depend on where the switch was), so it is fitted by a profile over where the switch
// falls among the measured depths, the other free parameters re-fitted at each place.
#include "puncture/curve_fit.hpp"

namespace puncture::detail {

// One test, the threshold free, no contact offset free (fit_curves checks); with no other free
// parameter a place is the model's curve at the test's parameters.  Each place of the switch is
// fitted as the stick rule `depth` with its threshold between the two measured depths (the same
// held and sliding points as any threshold of the test's rule that switches there, and smooth in
// the other parameters); the places are searched on a grid, then by Brent's method between the best
// grid place's neighbours; the interval is the places around the best whose cost rises by at most
// chi2(0.95, 1) residual variances.  The places map back to thresholds of the test's rule at the
// fitted parameters.
CurveFit fit_with_stick_threshold_profile(const CurveFitProblem& problem,
                                          const CurveFitOptions& options);

}  // namespace puncture::detail
