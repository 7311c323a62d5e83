#pragma once
// Shared helpers of the physics tests: the paper's problem with a chosen law and friction, and
// index ranges of the membrane parts in MembraneFields.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "numerics/trapezoid.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "puncture/material.hpp"
#include "puncture/problem.hpp"

namespace puncture::test {

inline constexpr double kPi = boost::math::constants::pi<double>();
inline constexpr double kHalfPi = boost::math::constants::half_pi<double>();

// The paper's lubricated silicone membrane (A = 25 mm, a = 2 mm, H = 0.2 mm, G = 0.06 MPa,
// Gent J_lim = 125, mu' = 0.18) with another law and friction when asked.
inline Problem paper_problem(MaterialLaw law = Gent{125.0}, double friction = 0.18) {
  Problem p;
  p.material.law = law;
  p.friction = friction;
  return p;
}

// Solver tolerances well below what derivative checks need (the defaults are 1e-10): 1e-13 on
// the integration and the clamp residual, no fields recorded.
inline SolverOptions tight_options() {
  SolverOptions o;
  o.integration_rel_tol = 1e-13;
  o.integration_abs_tol = 1e-15;
  o.shooting_tol = 1e-13;
  o.record_fields = false;
  return o;
}

// F [N] at normalised force f = F / (2 pi G H A).
inline double force_at(const Problem& p, double f) { return f * force_scale_n(p); }

// Indices of the samples of one part (1, 2 or 3), in the order they are stored (centre outwards).
inline std::vector<std::size_t> part_indices(const MembraneFields& m, int part) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (static_cast<int>(m.part[i]) == part) out.push_back(i);
  return out;
}

// Equibiaxial nominal stress in MPa (Part III) of the problem's material.
inline double equibiaxial_stress_mpa(const Problem& p, double l) {
  return equibiaxial_stress(p.material.law, l) * p.material.shear_modulus_mpa;
}

// Strain energy per unit reference volume [MPa = mJ/mm^3] at stretches (l1, l2).
inline double energy_density_mpa(const Problem& p, double l1, double l2) {
  return strain_energy_density(p.material.law, l1, l2) * p.material.shear_modulus_mpa;
}

// Records a measured quantity (an error, a margin) in the test's XML report (--gtest_output=xml).
inline void record(const std::string& key, double value) {
  ::testing::Test::RecordProperty(key, fmt::format("{:.3e}", value));
}

using detail::trapezoid;  // numerics/trapezoid.hpp

inline bool all_finite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

// Every floating-point field of a MembraneFields is finite.
inline bool fields_finite(const MembraneFields& m) {
  return all_finite(m.reference_radius_mm) && all_finite(m.radius_mm) &&
         all_finite(m.deflection_mm) && all_finite(m.slope_rad) && all_finite(m.radial_stretch) &&
         all_finite(m.hoop_stretch) && all_finite(m.thickness_stretch) &&
         all_finite(m.radial_stress_mpa) && all_finite(m.hoop_stress_mpa) &&
         all_finite(m.first_invariant) && all_finite(m.contact_pressure_mpa) &&
         all_finite(m.friction_traction_mpa);
}

}  // namespace puncture::test
