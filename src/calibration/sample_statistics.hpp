#pragma once
// The mean of per-test values, and with two tests or more their sample standard deviation (n - 1)
// and the standard error of the mean: the calibrations from repeated tests share it.
#include <cmath>
#include <vector>

namespace puncture::detail {

// Fills an estimate's mean, standard_deviation and standard_error from values (at least one).
template <class Estimate>
void summarise_sample(const std::vector<double>& values, Estimate& out) {
  const auto n = static_cast<double>(values.size());
  double sum = 0.0;
  for (const double v : values) sum += v;
  out.mean = sum / n;
  if (values.size() >= 2) {
    double ss = 0.0;
    for (const double v : values) ss += (v - out.mean) * (v - out.mean);
    out.standard_deviation = std::sqrt(ss / (n - 1.0));
    out.standard_error = *out.standard_deviation / std::sqrt(n);
  }
}

}  // namespace puncture::detail
