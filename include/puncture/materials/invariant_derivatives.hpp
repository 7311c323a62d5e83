#pragma once

namespace puncture {

// A strain-energy function W(I1, I2) of an incompressible isotropic solid, divided by the shear
// modulus G, with its first and second partial derivatives.  Every material law returns this;
// the membrane kinematics (membrane_stress.hpp) turns it into principal nominal stresses.
struct InvariantDerivatives {
  double w;    // W / G
  double w1;   // dW/dI1 / G
  double w2;   // dW/dI2 / G
  double w11;  // d2W/dI1^2 / G
  double w12;  // d2W/dI1 dI2 / G
  double w22;  // d2W/dI2^2 / G
};

}  // namespace puncture
