#pragma once
// The finite-element fields at any reference radius inside a part: the inverse of the part's map
// to find the element, then its shape functions.
#include <algorithm>
#include <cmath>
#include <optional>

#include "fe/element_energy.hpp"
#include "puncture/finite_element.hpp"

namespace puncture::fe {

struct PointFields {
  double radius = 0.0;      // current radius r (units of the part)
  double deflection = 0.0;  // z
  double l1 = 1.0, l2 = 1.0;
  double arclength = -1.0;  // s along the probe's profile, for a part lying on it (else -1)
};

// r, z and the stretches at reference radius R of `part` (R within its ends, same units).  On a
// probe's profile r and z interpolate their nodal values (within O(h^3) of the profile).
inline std::optional<PointFields> evaluate_part(const FePart& part, int order, double R) {
  const double rs = part.start_radius_mm, re = part.end_radius_mm;
  if (!(re > rs) || R < rs || R > re || part.elements <= 0) return std::nullopt;
  const double xi = part.logarithmic ? std::log(R / rs) / std::log(re / rs) : (R - rs) / (re - rs);
  const int e = std::clamp(int(xi * part.elements), 0, part.elements - 1);
  const double dxi = 1.0 / part.elements;
  const double eta = std::clamp(2.0 * (xi - e * dxi) / dxi - 1.0, -1.0, 1.0);
  std::array<double, kMaxOrder + 1> n{}, dn{};
  shape_functions(order, eta, n, dn);
  const double d_radius = part.logarithmic ? R * std::log(re / rs) : re - rs;
  const double d_radius_d_eta = 0.5 * dxi * d_radius;
  PointFields f;
  double dr = 0.0, dz = 0.0;
  for (int i = 0; i <= order; ++i) {
    f.radius += n[i] * part.radius_mm[e * order + i];
    f.deflection += n[i] * part.deflection_mm[e * order + i];
    dr += dn[i] * part.radius_mm[e * order + i];
    dz += dn[i] * part.deflection_mm[e * order + i];
  }
  double ds = 0.0;  // on a probe's profile lambda1 is ds/dR (the profile has unit speed in s)
  if (!part.arclength_mm.empty())
    for (int i = 0; i <= order; ++i) ds += dn[i] * part.arclength_mm[e * order + i];
  if (!part.arclength_mm.empty()) {
    f.arclength = 0.0;
    for (int i = 0; i <= order; ++i) f.arclength += n[i] * part.arclength_mm[e * order + i];
  }
  f.l1 = part.arclength_mm.empty() ? std::hypot(dr, dz) / d_radius_d_eta : ds / d_radius_d_eta;
  f.l2 = R > 0.0 ? f.radius / R : f.l1;  // at the axis the stretch is equibiaxial
  return f;
}

}  // namespace puncture::fe
