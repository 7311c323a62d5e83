#pragma once
// A smooth rigid probe as the finite elements see it: its axisymmetric profile, parameterised by
// the arclength s from the pole (the probe's lowest point) along the meridian.  The membrane in
// contact lies on the profile, each material point at an unknown s (frictionless: the membrane
// slides freely over it); the energy needs only the current radius rho(s) and its first two
// derivatives (exact Hessians through the chain rule), the contact edge the tangent and the
// non-penetration check the signed gap of a point.  All lengths are normalised by the stress-free
// clamp radius, like the rest of the finite elements.  A new smooth probe is one more subclass.
#include <limits>
#include <string>
#include <vector>

#include "puncture/membrane_fields.hpp"

namespace puncture::fe {

class RigidProfile {
 public:
  virtual ~RigidProfile() = default;
  // The current radius rho(s) of the profile point at arclength s from the pole, and its first
  // and second derivatives in s (|d(rho, height)/ds| = 1).
  virtual double radius(double s) const = 0;
  virtual double radius_slope(double s) const = 0;
  virtual double radius_curvature(double s) const = 0;
  // Height of that point above the pole (the deflection there is depth - height).
  virtual double height(double s) const = 0;
  virtual double height_slope(double s) const = 0;
  // Arclengths where the profile's curvature jumps (e.g. a sphere meeting its cylinder), in
  // increasing order: no element of the contact straddles one (each starts a part whose material
  // there is an unknown, so the solution is smooth in every element).
  virtual std::vector<double> curvature_breaks() const = 0;
  // The membrane part a contact segment is reported as (segment 0 from the pole, segment k after
  // the k-th break).
  virtual MembranePart segment_part(int segment) const = 0;
  // Signed distance of the point at current radius r and height y above the pole from the
  // profile: > 0 outside the probe, < 0 inside.
  virtual double gap(double r, double y) const = 0;
  // Arclength of the profile point closest to (r, y): where a point of the free membrane would
  // land if the contact took it (the starting guesses of a growing contact).
  virtual double closest_arclength(double r, double y) const = 0;
  // The arclength the contact edge may reach at most (the cone's kink onto its shank, the ball's
  // equator), and what lies past it: a contact beyond is outside the model, a status.
  virtual double contact_end() const { return std::numeric_limits<double>::infinity(); }
  virtual std::string beyond_contact_end() const { return {}; }
  // The arclength where the height starts to rise from the pole's (the end of a flat face).
  virtual double rise_start() const { return 0.0; }
};

// The outward normal of the profile at s (away from the probe's body), in (r, height).
inline void outward_normal(const RigidProfile& profile, double s, double& nr, double& ny) {
  nr = profile.height_slope(s);
  ny = -profile.radius_slope(s);
}

}  // namespace puncture::fe
