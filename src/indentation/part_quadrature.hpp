#pragma once
// Integrals along a state's fields, part by part: the stretches (and so the integrands) may jump
// where two parts meet, so each part is integrated on its own samples.
#include <cstddef>
#include <vector>

#include "numerics/trapezoid.hpp"
#include "puncture/membrane_fields.hpp"

namespace puncture::detail {

// The sum over the parts of the integral of y(i) dx(i) over the samples i of each part: the
// trapezoid rule extrapolated once (Richardson: fine + (fine - coarse) / 3).
template <class X, class Y>
double integral_by_part(const MembraneFields& m, X&& x_at, Y&& y_at) {
  if (m.size() < 2) return 0.0;
  double sum = 0.0;
  for (std::size_t first = 0; first < m.size();) {
    std::size_t last = first;
    while (last + 1 < m.size() && m.part[last + 1] == m.part[first]) ++last;
    // Parts that meet without a shared sample: the interval between them goes with this part.
    const bool shared =
        first == 0 || m.reference_radius_mm[first] == m.reference_radius_mm[first - 1];
    std::vector<double> x, y;
    for (std::size_t i = shared ? first : first - 1; i <= last; ++i) {
      x.push_back(x_at(i));
      y.push_back(y_at(i));
    }
    const double fine = trapezoid(x, y, 1), coarse = trapezoid(x, y, 2);
    sum += fine + (fine - coarse) / 3.0;
    first = last + 1;
  }
  return sum;
}

}  // namespace puncture::detail
