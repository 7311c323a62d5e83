#include "indentation/stored_energy.hpp"

#include <boost/math/constants/constants.hpp>
#include <cstddef>
#include <vector>

#include "numerics/trapezoid.hpp"
#include "puncture/material.hpp"

namespace puncture::detail {

double stored_energy_nmm(const MembraneFields& m, const Problem& problem) {
  if (m.size() < 2) return 0.0;
  double sum = 0.0;
  for (std::size_t first = 0; first < m.size();) {
    std::size_t last = first;
    while (last + 1 < m.size() && m.part[last + 1] == m.part[first]) ++last;
    // Parts that meet without a shared sample: the interval between them goes with this part.
    const bool shared =
        first == 0 || m.reference_radius_mm[first] == m.reference_radius_mm[first - 1];
    std::vector<double> reference_radius, density_times_radius;
    for (std::size_t i = shared ? first : first - 1; i <= last; ++i) {
      reference_radius.push_back(m.reference_radius_mm[i]);
      density_times_radius.push_back(
          strain_energy_density(problem.material.law, m.radial_stretch[i], m.hoop_stretch[i]) *
          m.reference_radius_mm[i]);
    }
    const double fine = trapezoid(reference_radius, density_times_radius, 1);
    const double coarse = trapezoid(reference_radius, density_times_radius, 2);
    sum += fine + (fine - coarse) / 3.0;
    first = last + 1;
  }
  return 2.0 * boost::math::constants::pi<double>() * problem.geometry.thickness_mm *
         problem.material.shear_modulus_mpa * sum;
}

}  // namespace puncture::detail
