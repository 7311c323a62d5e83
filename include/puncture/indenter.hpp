#pragma once
// The rigid probe pushed into the membrane's centre.  A shape is a struct here and an
// alternative of Indenter, with its contact model in src/indentation/contact/
// (docs/architecture.md).
#include <string>
#include <variant>
#include <vector>

namespace puncture {

// The paper's flat-ended cylinder: Part III under the flat tip, Part II on the side.  Its corner
// is sharp, or rounded by a toroidal fillet of radius rho < a: then the flat face ends at a - rho
// and the membrane lies on the fillet, sliding (docs/model.md §19).
struct FlatPunch {
  double radius_mm = 2.0;         // cylinder radius a [mm]
  double fillet_radius_mm = 0.0;  // corner fillet radius rho [mm] (0: the sharp corner)
};

// A cylinder of radius a ending in a hemisphere of the same radius (the ASTM F1306 probe has
// a = 1.6 mm): the membrane lies on the hemisphere from the pole to the contact edge and leaves it
// tangentially.  Sliding (frictionless, or Coulomb slip on the hemisphere and the cylinder side),
// or first held where it touched with a stick rule (docs/model.md, §15, §15.4).
struct SphereTipped {
  double radius_mm = 2.0;  // hemisphere and cylinder radius a [mm]
};

// A sphere of radius RB on a rod of radius a < RB: up to the ball's equator the sphere-tipped
// probe of radius RB.  Past the equator the membrane would wrap the upper hemisphere and neck
// above it, which is not solved: a status (docs/model.md, §15.1).
struct Ball {
  double radius_mm = 1.0;       // rod radius a [mm]
  double ball_radius_mm = 2.0;  // ball radius RB [mm] (> a)
};

// A cone of half-angle alpha (from the axis) with a spherical tip of radius RT tangent to it,
// ending on a cylindrical shank of radius a (RT cos(alpha) <= a).  A sharp cone (RT = 0) would
// make the stretch at the apex unbounded at a finite force.  Sliding (Coulomb slip on the tip,
// the cone and the kink); a contact that reaches the shank is a status (docs/model.md, §15.2).
struct Cone {
  double radius_mm = 2.0;        // shank radius a [mm]
  double half_angle_deg = 30.0;  // cone half-angle alpha from the axis [degrees], in (0, 90)
  double tip_radius_mm = 0.5;    // radius RT of the spherical tip [mm] (> 0)
};

using Indenter = std::variant<FlatPunch, SphereTipped, Ball, Cone>;

// The probe's radius a [mm]: the cylinder's, for the flat punch; the hemisphere's and the
// cylinder's, for the sphere-tipped probe; the rod's, for the ball (the ball's own radius is
// Ball::ball_radius_mm); the shank's, for the cone.
double radius_mm(const Indenter& indenter);
// Name and dimensions, e.g. "flat punch, radius 2 mm", "sphere-tipped probe, radius 1.6 mm",
// "flat punch, radius 2 mm, corner fillet radius 0.5 mm",
// "ball, radius 3 mm, on a rod of radius 1 mm", "cone, half-angle 30 deg, tip radius 0.5 mm,
// shank radius 2 mm".
std::string describe(const Indenter& indenter);
// Whether it is the flat punch with a sharp corner (fillet radius 0): the finite elements held
// at the edge, verify()'s held and Foppl rows, friction calibration, energy-release criterion.
bool sharp_flat_punch(const Indenter& indenter);

// A point of a probe's meridian: its distance from the axis and its height above the tip [mm].
struct OutlinePoint {
  double r_mm;
  double height_mm;
};
// The probe's meridian from its tip (r = 0, height 0) to where its vertical shank (side, rod)
// begins at r = radius_mm(indenter), curved parts in 24 chords each: for drawing it to scale.
std::vector<OutlinePoint> outline(const Indenter& indenter);

}  // namespace puncture
