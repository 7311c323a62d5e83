#pragma once
#include <cstddef>

#include "puncture/sweep.hpp"

namespace puncture::detail {

// sweep_point without its checks: the spec valid, index < point_count(spec) (the sweep checks
// once, then asks for every point).
SweepPoint point_of_valid_spec(const SweepSpec& spec, std::size_t index);

}  // namespace puncture::detail
