#pragma once
// `sweep --statistics`: the statistics of each output column of a finished sweep's CSV (read
// back, so a resumed sweep's earlier rows count): percentiles, histogram, sensitivity ranking.
#include <string>

#include "puncture/sweep.hpp"

namespace puncture::cli {

// The report of every output of `spec` over the rows of `csv_path` (written by
// sweep_csv_line).  Throws SolveError when the file cannot be read back.
std::string sweep_statistics_report(const std::string& csv_path, const SweepSpec& spec);

}  // namespace puncture::cli
