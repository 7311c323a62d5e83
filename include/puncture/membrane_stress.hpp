#pragma once
// Principal nominal stresses of an incompressible membrane in plane stress (paper Eqs. (1)-(6)),
// for any law W(I1, I2):  lambda3 = 1 / (lambda1 lambda2),
//   s1 = dW/dlambda1 = W1 dI1/dlambda1 + W2 dI2/dlambda1,   s2 likewise,
// with the Jacobian needed by the Part I and Part II ODEs and by the inverse lambda1(s1, lambda2).
// All stresses are divided by the shear modulus G.
#include <cmath>
#include <concepts>

namespace puncture {

struct MembraneStress {
  double s1;       // radial (meridional) nominal stress / G
  double s2;       // hoop nominal stress / G
  double ds1_dl1;  // d s1 / d lambda1
  double ds1_dl2;  // d s1 / d lambda2 (= d s2 / d lambda1: W is a potential)
  double ds2_dl2;  // d s2 / d lambda2
  double i1;       // first invariant of the right Cauchy-Green tensor
};

inline double first_invariant(double l1, double l2) {
  const double l3 = 1.0 / (l1 * l2);
  return l1 * l1 + l2 * l2 + l3 * l3;
}

inline double second_invariant(double l1, double l2) {
  return l1 * l1 * l2 * l2 + 1.0 / (l1 * l1) + 1.0 / (l2 * l2);
}

// A law whose energy depends on I1 only declares `static constexpr bool depends_on_i2 = false;`
// and the I2 terms are skipped (they cost a third of the evaluation, in the solver's inner loop).
template <class Law>
constexpr bool depends_on_i2() {
  if constexpr (requires { Law::depends_on_i2; })
    return Law::depends_on_i2;
  else
    return true;
}

// A law written in principal stretches (Ogden) gives its membrane stresses and its energy W / G
// directly; every other law is W(I1, I2) and gives derivatives(I1, I2) (invariant_derivatives.hpp).
template <class Law>
concept PrincipalStretchLaw = requires(const Law& law, double l) {
  { law.stresses(l, l) } -> std::same_as<MembraneStress>;
  { law.energy(l, l) } -> std::convertible_to<double>;
};

namespace detail {

// The stresses of a law W(I1, I2) through the derivatives of the invariants.
template <class Law>
MembraneStress invariant_membrane_stress(const Law& law, double l1, double l2) {
  // Two divisions only: this runs at every stage of every integration step.
  const double il1 = 1.0 / l1, il2 = 1.0 / l2;
  const double l1s = l1 * l1, l2s = l2 * l2, il1s = il1 * il1, il2s = il2 * il2;
  const double l3s = il1s * il2s;
  const double i1 = l1s + l2s + l3s;
  const double i2 = depends_on_i2<Law>() ? l1s * l2s + il1s + il2s : 3.0;
  const auto d = law.derivatives(i1, i2);
  // First and second derivatives of I1 with respect to the two in-plane stretches.
  const double a1 = 2.0 * (l1 - l3s * il1), a2 = 2.0 * (l2 - l3s * il2);
  const double a11 = 2.0 + 6.0 * l3s * il1s, a22 = 2.0 + 6.0 * l3s * il2s;
  const double a12 = 4.0 * l3s * il1 * il2;
  MembraneStress s;
  s.s1 = d.w1 * a1;
  s.s2 = d.w1 * a2;
  s.ds1_dl1 = d.w11 * a1 * a1 + d.w1 * a11;
  s.ds1_dl2 = d.w11 * a1 * a2 + d.w1 * a12;
  s.ds2_dl2 = d.w11 * a2 * a2 + d.w1 * a22;
  s.i1 = i1;
  if constexpr (depends_on_i2<Law>()) {
    // ... and of I2.
    const double b1 = 2.0 * (l1 * l2s - il1s * il1), b2 = 2.0 * (l1s * l2 - il2s * il2);
    const double b11 = 2.0 * l2s + 6.0 * il1s * il1s, b22 = 2.0 * l1s + 6.0 * il2s * il2s;
    const double b12 = 4.0 * l1 * l2;
    s.s1 += d.w2 * b1;
    s.s2 += d.w2 * b2;
    s.ds1_dl1 += 2.0 * d.w12 * a1 * b1 + d.w22 * b1 * b1 + d.w2 * b11;
    s.ds1_dl2 += d.w12 * (a1 * b2 + a2 * b1) + d.w22 * b1 * b2 + d.w2 * b12;
    s.ds2_dl2 += 2.0 * d.w12 * a2 * b2 + d.w22 * b2 * b2 + d.w2 * b22;
  }
  return s;
}

}  // namespace detail

template <class Law>
MembraneStress membrane_stress(const Law& law, double l1, double l2) {
  if constexpr (PrincipalStretchLaw<Law>)
    return law.stresses(l1, l2);
  else
    return detail::invariant_membrane_stress(law, l1, l2);
}

// W / G at the stretches; `i1` is their first invariant, which the callers already hold (an
// invariant law reads W from it and I2; a law in principal stretches does not need it).
template <class Law>
double strain_energy_density(const Law& law, double l1, double l2, double i1) {
  if constexpr (PrincipalStretchLaw<Law>)
    return law.energy(l1, l2);
  else
    return law.derivatives(i1, second_invariant(l1, l2)).w;
}

// Largest radial stretch lambda1 at hoop stretch l2 before the law locks (infinity if it never
// does): the larger root of lambda1^2 + l2^2 + 1/(lambda1^2 l2^2) = max_i1.
template <class Law>
double locking_radial_stretch(const Law& law, double l2) {
  const double i1_max = law.locking_i1();
  if (!std::isfinite(i1_max)) return i1_max;
  const double b = l2 * l2 - i1_max;  // x^2 + b x + 1/l2^2 = 0 with x = lambda1^2
  const double disc = b * b - 4.0 / (l2 * l2);
  if (disc <= 0.0) return 0.0;  // l2 alone already locks the material
  return std::sqrt(0.5 * (-b + std::sqrt(disc)));
}

}  // namespace puncture
