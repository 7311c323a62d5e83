#pragma once
// The transverse load on a free membrane, in the normalised variables of docs/model.md (lengths
// / A, stresses / G): a point force at the axis, f = F / (2 pi G H A), and a uniform pressure
// normal to the deformed membrane (a follower load), P = p A / (G H).  Both are positive in the
// same direction, the one the membrane's height h is measured against (docs/model.md, §3 and §14):
// an indenter pushing a flat membrane (f > 0, P = 0), the air inflating it (f = 0, P > 0).
namespace puncture::detail {

struct TransverseLoad {
  double force = 0.0;     // f, carried across the inner end of the integrated part
  double pressure = 0.0;  // P, on the membrane

  // The vertical force per radian across the cut at current radius r, / (G H A): the vertical
  // balance R s1 sin(phi) = f + P r^2 / 2.  The pressure's resultant on any surface spanning the
  // circle of radius r is p pi r^2, whatever its shape.  With P = 0 this is f exactly, with f = 0
  // exactly P r^2 / 2 (adding a zero rounds nothing).
  double vertical(double r) const { return force + 0.5 * pressure * r * r; }
};

}  // namespace puncture::detail
