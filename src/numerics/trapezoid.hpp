#pragma once
// The trapezoid rule on sampled fields, for the quadratures along the membrane (the enclosed
// volume, energies in the tests) and their Richardson steps.
#include <cstddef>
#include <vector>

namespace puncture::detail {

// Trapezoid rule of y over x on the samples 0, stride, 2 stride, ..., and the last: stride 2
// gives the coarse value of a Richardson step.
inline double trapezoid(const std::vector<double>& x, const std::vector<double>& y,
                        std::size_t stride) {
  double sum = 0.0;
  std::size_t i = 0;
  for (; i + stride < x.size(); i += stride)
    sum += 0.5 * (y[i] + y[i + stride]) * (x[i + stride] - x[i]);
  if (i + 1 < x.size()) sum += 0.5 * (y[i] + y.back()) * (x.back() - x[i]);
  return sum;
}

}  // namespace puncture::detail
