#pragma once
// The units of the solver's normalised variables (ScaledSolution) for a problem: lengths in the
// stress-free clamp radius A / L0, forces in 2 pi G H A / L0 (A and force_scale_n without
// pre-stretch, bit for bit).
#include "puncture/problem.hpp"

namespace puncture::detail {

struct SolverScales {
  double length_mm;   // A / L0
  double force_n;     // 2 pi G H A / L0
  double prestretch;  // L0
  // The paper's normalised force F / (2 pi G H A) of a solver force f.
  double normalized_force(double f) const { return f / prestretch; }
};

// The gas pressure under the membrane in the solver's unit, P = p (A / L0) / (G H).
inline double dome_pressure(const Problem& p) {
  return p.preload.pressure_mpa * reference_clamp_radius_mm(p) /
         (p.material.shear_modulus_mpa * p.geometry.thickness_mm);
}

inline SolverScales solver_scales(const Problem& p) {
  const double l0 = p.preload.prestretch;
  return {reference_clamp_radius_mm(p), force_scale_n(p) / l0, l0};
}

}  // namespace puncture::detail
