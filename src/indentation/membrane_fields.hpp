#pragma once
// The fields of a solved state along the meridian, in physical units: Part I here (it is the
// same for every indenter); the parts in contact come from the contact model
// (append_contact_fields), which uses the same append_point.
#include <cmath>

#include "indentation/scaled_solution.hpp"
#include "mechanics/field_point.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// The physical scales of a normalised solution.
struct FieldScales {
  double clamp_radius_mm;    // A: lengths
  double shear_modulus_mpa;  // G: stresses
  double thickness_mm;       // H: contact pressures from line tensions
};

// Part I, from the indenter to the clamp: its height is measured from its inner end, which lies
// `inner_height` (normalised) above the tip.  Under a gas pressure P (normalised) the meridian's
// slope follows the vertical load f - P r^2 / 2.
template <class Law>
void append_free_fields(const Law& law, const ScaledSolution& sol, double inner_height,
                        const FieldScales& u, MembraneFields& m, double pressure = 0.0) {
  const double big_a = u.clamp_radius_mm;
  const double depth = sol.depth * big_a;
  for (const auto& s : sol.part_one) {
    const double r_ref = s[0], t = s[1], l1 = s[2], l2 = s[3], h = s[4];
    const double z = depth - (inner_height + h) * big_a;
    append_point(
        m,
        MembranePart::Free,
        r_ref * big_a,
        l2 * r_ref * big_a,
        z,
        std::atan2(pressure == 0.0 ? sol.f : sol.f - 0.5 * pressure * l2 * l2 * r_ref * r_ref, t),
        l1,
        l2,
        membrane_stress(law, l1, l2),
        u.shear_modulus_mpa,
        0.0,
        0.0);
  }
}

}  // namespace puncture::detail
