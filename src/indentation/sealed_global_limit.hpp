#pragma once
// Over a sealed chamber the probe compresses the gas, and the gas lifts the dome: a large probe
// can drive the pressure to the inflation's limit point before any puncture (docs/model.md §8.1,
// §17.1).  The membrane then heads for its global limit, which the model does not follow.
#include <optional>
#include <string>

#include "puncture/options.hpp"
#include "puncture/problem.hpp"

namespace puncture::detail {

// Why the puncture search over the chamber stopped, in words, when it can be said from the
// facts: no puncture at gas pressures up to `passed_mpa` (the gas law's root lies above it),
// and the inflation limit point's pressure lies between it and `failed_mpa` (just above, whose
// dome is past it).  Empty when any of these fails: the caller's message stands.
std::optional<std::string> heading_for_global_limit(const Problem& p, const SolverOptions& options,
                                                    double passed_mpa, double failed_mpa);

}  // namespace puncture::detail
