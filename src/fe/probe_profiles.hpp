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

// The sharp flat punch as a profile: its face, a convex kink at the corner, its side.  Under a
// gas pressure the face touches a growing disc of the dome first, whose edge the smooth probes'
// search finds (where the membrane leaves the face horizontally); past it the edge stays at the
// kink (the corner), then moves up the side (Part II), as the sharp-corner layouts do.
std::unique_ptr<RigidProfile> sharp_punch_profile(const FlatPunch& punch, double clamp_radius_mm);

}  // namespace puncture::fe
