#pragma once
// The fields of a solved state along the meridian, in physical units: Part I here (it is the
// same for every indenter); the parts in contact come from the contact model
// (append_contact_fields), which uses the same append_point.
#include <cmath>

#include "indentation/scaled_solution.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// The physical scales of a normalised solution.
struct FieldScales {
  double clamp_radius_mm;    // A: lengths
  double shear_modulus_mpa;  // G: stresses
  double thickness_mm;       // H: contact pressures from line tensions
};

inline void append_point(MembraneFields& m, MembranePart part, double r_ref, double radius,
                         double deflection, double slope, double l1, double l2,
                         const MembraneStress& st, double g_mpa, double pressure, double friction) {
  m.part.push_back(static_cast<int>(part));
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

// Part I, from the indenter to the clamp: its height is measured from its inner end, which lies
// `inner_height` (normalised) above the tip.
template <class Law>
void append_free_fields(const Law& law, const ScaledSolution& sol, double inner_height,
                        const FieldScales& u, MembraneFields& m) {
  const double big_a = u.clamp_radius_mm;
  const double depth = sol.depth * big_a;
  for (const auto& s : sol.part_one) {
    const double r_ref = s[0], t = s[1], l1 = s[2], l2 = s[3], h = s[4];
    const double z = depth - (inner_height + h) * big_a;
    append_point(m,
                 MembranePart::Free,
                 r_ref * big_a,
                 l2 * r_ref * big_a,
                 z,
                 std::atan2(sol.f, t),
                 l1,
                 l2,
                 membrane_stress(law, l1, l2),
                 u.shear_modulus_mpa,
                 0.0,
                 0.0);
  }
}

}  // namespace puncture::detail
