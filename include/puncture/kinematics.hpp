#pragma once
// Kinematics of the equibiaxial state (Part III under a flat tip, the pole of an inflated
// membrane): I1 from the stretch and back.
namespace puncture {

double equibiaxial_first_invariant(double stretch);  // 2 l^2 + l^-4
// The stretch >= 1 whose equibiaxial I1 is `i1` (>= 3); Boost's bracketed Newton.  Throws
// InvalidInput ("i1") for an I1 below 3 or not finite.
double equibiaxial_stretch_for_first_invariant(double i1);

}  // namespace puncture
