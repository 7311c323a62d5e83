#pragma once
// Statistics of one output over a sweep's points (Monte Carlo, Latin hypercube, Sobol): mean,
// sd, percentiles, a histogram, and which input moves it most.
//
// The ranking is by standardised regression coefficients: the least-squares fit
// y = b0 + sum_j b_j x_j over the points with an output, and SRC_j = b_j sd(x_j) / sd(y).  For
// independent inputs and an output close to linear (R^2 near 1), SRC_j^2 is input j's
// first-order Sobol index, its share of the output's variance; R^2 says how far to trust them.
//
//   SweepStatistics stats({"friction", "critical-i1"}, "puncture_force_n");
//   for (const SweepRow& row : rows) stats.add(row.point.values, force_or_nothing(row));
//   const OutputStatistics s = stats.result();
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "puncture/outcome.hpp"

namespace puncture {

struct Percentile {
  double probability = 0.5;  // in [0, 1]
  double value = 0.0;        // linear interpolation between order statistics (numpy's default)
};

struct Histogram {
  std::vector<double> edges;        // bins + 1 edges from the least to the largest value
  std::vector<std::size_t> counts;  // values in [edges[k], edges[k+1]) (the last bin closed)
};

struct InputSensitivity {
  std::string name;
  double coefficient = 0.0;  // b_j: output per unit of the input (the units of both)
  double src = 0.0;          // b_j sd(x_j) / sd(y)
};

// Converged when the output was found at two points or more; else Incomplete (message: why).
struct OutputStatistics : Outcome {
  std::string output;
  std::size_t points = 0;                             // rows added
  std::size_t found = 0;                              // rows with the output (the rest failed)
  double mean = 0.0, sd = 0.0, min = 0.0, max = 0.0;  // sd: sample (n - 1)
  std::vector<Percentile> percentiles;
  Histogram histogram;
  // By decreasing |src|; inputs that are not numbers or do not vary are left out.  Empty when
  // the points are too few for the fit (found <= inputs + 1).
  std::vector<InputSensitivity> sensitivities;
  double r_squared = 0.0;      // of the linear fit
  std::string report() const;  // the numbers as text, for people
};

class SweepStatistics {
 public:
  SweepStatistics(std::vector<std::string> input_names, std::string output_name);

  // One point: its inputs (a NaN input, e.g. a word, is not used in the fit) and its output,
  // or nothing when the point failed.  Throws std::invalid_argument for a wrong input count
  // or a non-finite output.
  void add(const std::vector<double>& inputs, std::optional<double> output);

  OutputStatistics result(const std::vector<double>& probabilities = {0.05, 0.25, 0.5, 0.75, 0.95},
                          int bins = 20) const;

 private:
  std::vector<std::string> names_;
  std::string output_;
  std::size_t points_ = 0;
  std::vector<double> values_;  // the outputs found (the percentiles need them all)
  // The fit's sums over the points with an output, of the inputs and the output less the first
  // such point's (shifted sums keep the cancellation small): sum dx, sum dx dx^T (row-major),
  // sum dx dy, sum dy, sum dy^2.  An input that is NaN anywhere is left out of the fit.
  std::vector<double> shift_;
  double shift_y_ = 0.0;
  std::vector<double> sum_x_, sum_xx_, sum_xy_;
  double sum_y_ = 0.0, sum_yy_ = 0.0;
  std::vector<bool> numeric_;
};

}  // namespace puncture
