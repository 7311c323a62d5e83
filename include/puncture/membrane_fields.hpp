#pragma once
// The fields of an axisymmetric membrane state along its meridian, the same for every load
// (indentation, inflation): one row per point from the centre (R = 0) to the clamp (R = A), in
// physical units.
#include <cstddef>
#include <vector>

namespace puncture {

// The parts of the membrane (docs/model.md): the free membrane, the part wrapped on the
// indenter's side and the part under its tip.  The values are the part numbers written in CSV.
// An inflated membrane is free throughout.
enum class MembranePart { Free = 1, Side = 2, Tip = 3 };

struct MembraneFields {
  std::vector<MembranePart> part;
  std::vector<double> reference_radius_mm;  // R, position in the flat reference state
  std::vector<double> radius_mm;            // r, current distance from the axis
  // z, displacement from the clamp plane along the load: below it in the indenter's direction
  // when indented, above it (the height) when inflated.
  std::vector<double> deflection_mm;
  // phi, angle of the meridian to the clamp plane, positive where it returns toward the clamp
  // plane going outward (dz/dr = -tan phi); 0 at a pole, > pi/2 where an inflated membrane
  // overhangs.
  std::vector<double> slope_rad;
  std::vector<double> radial_stretch;         // lambda1 (meridional)
  std::vector<double> hoop_stretch;           // lambda2 = r / R
  std::vector<double> thickness_stretch;      // lambda3 = 1 / (lambda1 lambda2)
  std::vector<double> radial_stress_mpa;      // s1, nominal (force per reference area)
  std::vector<double> hoop_stress_mpa;        // s2, nominal
  std::vector<double> first_invariant;        // I1 = lambda1^2 + lambda2^2 + lambda3^2
  std::vector<double> contact_pressure_mpa;   // P_n on the indenter's side (true), else 0
  std::vector<double> friction_traction_mpa;  // mu P_n on the indenter's side, else 0
  std::size_t size() const { return reference_radius_mm.size(); }
};

}  // namespace puncture
