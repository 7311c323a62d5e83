#pragma once
// The finite elements on a smooth rigid probe (rigid_profile.hpp), frictionless: the membrane
// lies on the profile from the pole to a contact edge that the method finds (docs/model.md,
// "Finite elements on a smooth probe").
#include <string>
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

// Where a continuation in depth stops: every depth not reached gets a state carrying the failure.
inline void fill_unreached_depths(std::vector<FeState>& states,
                                  const std::vector<double>& depths_mm, FeContact contact,
                                  Status status, const std::string& message) {
  FeState failed;
  failed.contact = contact;
  failed.status = status;
  failed.message = message;
  for (std::size_t k = states.size(); k < depths_mm.size(); ++k) {
    failed.depth_mm = depths_mm[k];
    states.push_back(failed);
  }
}

}  // namespace puncture::fe
