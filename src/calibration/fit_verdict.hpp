#pragma once
// The verdict on a fit that explains too little of the measured force: shared by the fit of
// the curves (curve_fit.cpp) and the profile over the stick threshold
// (stick_threshold_profile.cpp).
#include <fmt/format.h>

#include <algorithm>

#include "puncture/curve_fit.hpp"

namespace puncture::detail {

// Marks the fit OutsideModel (a flat record, a curve of another model) when its R^2 is below
// `min_r_squared`; true when it did.
inline bool outside_model_by_r_squared(CurveFit& fit, double min_r_squared) {
  if (!(fit.r_squared < min_r_squared)) return false;
  fit.status = Status::OutsideModel;
  fit.message = fmt::format(
      "the fitted model explains {:.3g} % of the force variance (R^2 = {:.4g} < {:g}): {} of "
      "this model",
      100.0 * std::max(0.0, fit.r_squared),
      fit.r_squared,
      min_r_squared,
      fit.tests.size() == 1 ? "the record is not a force-depth curve"
                            : "the records are not force-depth curves");
  return true;
}

}  // namespace puncture::detail
