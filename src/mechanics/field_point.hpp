#pragma once
// One row of MembraneFields from a point's stretches: the stresses and I1 from the law, the
// thickness stretch from incompressibility.  Indentation and inflation write their fields with it.
#include "puncture/membrane_fields.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// Lengths in mm, the slope in rad, `g_mpa` the shear modulus (the stresses' scale), the contact
// pressure and friction traction in MPa (0 off the contact).
inline void append_point(MembraneFields& m, MembranePart part, double r_ref, double radius,
                         double deflection, double slope, double l1, double l2,
                         const MembraneStress& st, double g_mpa, double pressure, double friction) {
  m.part.push_back(part);
  m.reference_radius_mm.push_back(r_ref);
  m.radius_mm.push_back(radius);
  m.deflection_mm.push_back(deflection);
  m.slope_rad.push_back(slope);
  m.radial_stretch.push_back(l1);
  m.hoop_stretch.push_back(l2);
  m.thickness_stretch.push_back(1.0 / (l1 * l2));
  m.radial_stress_mpa.push_back(st.s1 * g_mpa);
  m.hoop_stress_mpa.push_back(st.s2 * g_mpa);
  m.first_invariant.push_back(st.i1);
  m.contact_pressure_mpa.push_back(pressure);
  m.friction_traction_mpa.push_back(friction);
}

}  // namespace puncture::detail
