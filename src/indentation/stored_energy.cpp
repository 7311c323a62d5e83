#include "indentation/stored_energy.hpp"

#include <boost/math/constants/constants.hpp>
#include <cstddef>

#include "indentation/part_quadrature.hpp"
#include "puncture/material.hpp"

namespace puncture::detail {

double stored_energy_nmm(const MembraneFields& m, const Problem& problem) {
  const double sum = integral_by_part(
      m,
      [&](std::size_t i) { return m.reference_radius_mm[i]; },
      [&](std::size_t i) {
        return strain_energy_density(problem.material.law, m.radial_stretch[i], m.hoop_stretch[i]) *
               m.reference_radius_mm[i];
      });
  return 2.0 * boost::math::constants::pi<double>() * problem.geometry.thickness_mm *
         problem.material.shear_modulus_mpa * sum;
}

}  // namespace puncture::detail
