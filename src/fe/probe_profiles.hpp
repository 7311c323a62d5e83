#pragma once
// The profile the finite elements lie on for each smooth probe of include/puncture/indenter.hpp,
// normalised by the stress-free clamp radius (docs/model.md §15.3): the sphere-tipped probe,
// the flat punch with a rounded corner, the cone and the ball.  None for the sharp flat punch,
// whose corner the elements treat as a layout of their own (finite_element.cpp).
#include <memory>

#include "fe/rigid_profile.hpp"
#include "puncture/indenter.hpp"

namespace puncture::fe {

// The profile of `indenter` with lengths divided by `clamp_radius_mm` (A / L0 in mm); empty for
// the sharp flat punch.
std::unique_ptr<RigidProfile> smooth_profile(const Indenter& indenter, double clamp_radius_mm);

}  // namespace puncture::fe
