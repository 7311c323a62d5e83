#include "indentation/enclosed_volume.hpp"

#include <boost/math/constants/constants.hpp>
#include <cstddef>

#include "indentation/part_quadrature.hpp"

namespace puncture::detail {

double enclosed_volume_mm3(const MembraneFields& m) {
  if (m.size() < 2) return 0.0;
  const double clamp_z = m.deflection_mm.back();
  const double sum = integral_by_part(
      m,
      [&](std::size_t i) { return m.radius_mm[i] * m.radius_mm[i]; },
      [&](std::size_t i) { return clamp_z - m.deflection_mm[i]; });
  return boost::math::constants::pi<double>() * sum;
}

}  // namespace puncture::detail
