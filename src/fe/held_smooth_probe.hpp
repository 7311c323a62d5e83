#pragma once
// The finite elements on a smooth probe with the membrane held where it touched (the stick rule
// `always`, docs/model.md §15.4, §15.5): a fixed material mesh whose nodes, once they reach the
// profile, stay at the arclength where they touched and move with the probe (docs/model.md
// §15.3, "Held where it touched").
#include <vector>

#include "fe/rigid_profile.hpp"
#include "puncture/finite_element.hpp"
#include "puncture/problem.hpp"

namespace puncture::fe {

// States at the given depths [mm] (validated by the caller: increasing, > 0) along one loading
// history from the flat membrane.  `profile` is normalised by the stress-free clamp radius.
std::vector<FeState> solve_held_smooth_probe(const Problem& problem, const RigidProfile& profile,
                                             const std::vector<double>& depths_mm,
                                             const FeOptions& options);

}  // namespace puncture::fe
