#pragma once
// The volume between a membrane state and its flat (clamp) plane, from the state's fields: what
// a sealed chamber's gas gains over its flat volume V0 (docs/model.md §17.1).
#include "puncture/membrane_fields.hpp"

namespace puncture::detail {

// V = pi int y d(r^2) along the meridian from the axis to the clamp [mm^3], y the height above
// the clamp plane (the clamp's deflection minus the point's): exact for any meridian, also one
// that overhangs or runs down the probe's side (r constant there, adding nothing).  Each part is
// integrated on its own samples (its stretches may jump where two parts meet) by the trapezoid
// rule on every sample and on every other one, extrapolated (Richardson).
double enclosed_volume_mm3(const MembraneFields& fields);

}  // namespace puncture::detail
