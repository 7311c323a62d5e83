#include "indentation/enclosed_volume.hpp"

#include <boost/math/constants/constants.hpp>
#include <cstddef>
#include <vector>

#include "numerics/trapezoid.hpp"

namespace puncture::detail {

double enclosed_volume_mm3(const MembraneFields& m) {
  if (m.size() < 2) return 0.0;
  const double clamp_z = m.deflection_mm.back();
  double sum = 0.0;
  for (std::size_t first = 0; first < m.size();) {
    std::size_t last = first;
    while (last + 1 < m.size() && m.part[last + 1] == m.part[first]) ++last;
    // Parts that meet without a shared sample: the interval between them goes with this part.
    const bool shared =
        first == 0 || m.reference_radius_mm[first] == m.reference_radius_mm[first - 1];
    std::vector<double> r_squared, height;
    for (std::size_t i = shared ? first : first - 1; i <= last; ++i) {
      r_squared.push_back(m.radius_mm[i] * m.radius_mm[i]);
      height.push_back(clamp_z - m.deflection_mm[i]);
    }
    const double fine = trapezoid(r_squared, height, 1), coarse = trapezoid(r_squared, height, 2);
    sum += fine + (fine - coarse) / 3.0;
    first = last + 1;
  }
  return boost::math::constants::pi<double>() * sum;
}

}  // namespace puncture::detail
