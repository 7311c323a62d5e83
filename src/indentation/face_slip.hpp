#pragma once
// Which way the membrane on a flat punch's face slides under a gas pressure with friction.
//
// The gas presses Part III onto the face, and the model's friction mu' p there assumes the
// face's material slides outward (docs/model.md §17).  Early in the loading it slides inward
// instead (lubricated to ~1-2 mm, dry to ~10-20 mm on the paper's membrane), where the model's
// friction points the wrong way: those states are not the membrane's.  This compares the face's
// material in two nearby states to tell.
#include <optional>
#include <string>

#include "puncture/problem.hpp"

namespace puncture::detail {

// Whether the direction of the face's friction is a question at all: a flat punch under a gas
// pressure with friction.
bool face_friction_direction_matters(const Problem& p);

// The face's slip between the states at depth_mm and a little deeper: the least and the most
// radial displacement [mm] of Part III's material points (both > 0: the whole face slides
// outward, as modelled).  Nothing when a state does not solve or the face has no material.
struct FaceSlip {
  double least_mm = 0.0;
  double most_mm = 0.0;
};
std::optional<FaceSlip> face_slip(const Problem& p, double depth_mm);

// Why a state at depth_mm is not the membrane's (the face slides inward there), or nothing.
std::optional<std::string> inward_face_slip(const Problem& p, double depth_mm);

}  // namespace puncture::detail
