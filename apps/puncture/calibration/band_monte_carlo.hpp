#pragma once
// `calibrate band --method monte-carlo --samples N`: the puncture band by Monte Carlo on the
// sweep engine (include/puncture/sweep.hpp) instead of the intervals' corners.  A parameter
// given by its sd is normal(nominal, sd) truncated to nominal +- --sd-multiple sd (default 3
// here); one given by LO,HI is uniform on it.  The report: the nominal prediction, the
// percentiles, mean and sd of the puncture force and depth, failed samples, and the parameters
// ranked by standardised regression coefficient.
#include <cstdint>
#include <optional>
#include <string>

#include "output_options.hpp"
#include "puncture/puncture_band.hpp"

namespace puncture::cli {

struct MonteCarloBandRequest {
  Problem problem;              // the nominal values
  BandRanges ranges;            // where each parameter may go
  std::optional<double> sd[4];  // per BandParameter: normal with this sd, else uniform
  std::size_t samples = 1000;
  std::uint64_t seed = 1;
  int threads = 0;  // every core
};

// Throws InputError for a range the problem's validation refuses (naming the flag), SolveError
// when the nominal point has no puncture.
std::string monte_carlo_band_text(const MonteCarloBandRequest& request, Format format);

}  // namespace puncture::cli
