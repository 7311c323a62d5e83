#pragma once
// The finite elements on a smooth rigid probe (rigid_profile.hpp), frictionless: the membrane
// lies on the profile from the pole to a contact edge that the method finds (docs/model.md,
// "Finite elements on a smooth probe").
#include <vector>

#include "fe/rigid_profile.hpp"
#include "puncture/finite_element.hpp"
#include "puncture/problem.hpp"

namespace puncture::fe {

// States at the given depths [mm] (validated by the caller: increasing, > 0), reached by
// continuation in depth from the flat membrane.  `profile` is normalised by the stress-free
// clamp radius.
std::vector<FeState> solve_smooth_probe(const Problem& problem, const RigidProfile& profile,
                                        const std::vector<double>& depths_mm,
                                        const FeOptions& options);

}  // namespace puncture::fe
