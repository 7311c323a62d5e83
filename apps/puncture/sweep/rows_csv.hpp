#pragma once
// The sweep's CSV: one row per point, failed points included.
//   point, <each swept flag>, status, failure_kind,
//   puncture_force_n, puncture_depth_mm, part_three_stretch, max_i1,
//   crack_reference_radius_mm, crack_radius_mm, crack_location     (when the puncture is asked)
//   force_n_at_<D>_mm ...                                          (per depth asked)
//   message
// The swept inputs are written as given to the problem (their flags' units); numbers of the
// outputs in their shortest exact decimal form (bit-identical runs give identical files); an
// output that failed is empty; the message says why the row failed.
#include <string>

#include "puncture/sweep.hpp"

namespace puncture::cli {

std::string sweep_csv_header(const SweepSpec& spec);  // ends in a newline
std::string sweep_csv_line(const SweepRow& row);      // ends in a newline

}  // namespace puncture::cli
