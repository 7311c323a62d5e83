#pragma once
// The stored energy of one finite element of the meridian, with its exact gradient and Hessian
// with respect to the element's local unknowns, by Eigen's forward automatic differentiation
// (nested for the second derivatives).  The material enters through W and its first and second
// derivatives with respect to the stretches (membrane_stress), so the laws need not be templates.
//
// Local unknowns, normalised by the clamp radius A: the current radius r and deflection z at the
// element's order + 1 nodes, then the reference radii of the two ends of the element's part (the
// part's mesh moves with them: that is how the contact boundaries are found).  An element lying
// on a smooth probe's profile (rigid_profile.hpp) holds the arclength s along the profile in
// place of r (its z values are unused): it lies on the profile at every point, not only at its
// nodes, with lambda1 = ds/dR and lambda2 = rho(s) / R.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/AutoDiff>
#include <variant>

#include "fe/rigid_profile.hpp"
#include "puncture/material.hpp"

namespace puncture::fe {

constexpr int kMaxOrder = 2;
constexpr int kMaxLocal = 2 * (kMaxOrder + 1) + 2;

using Vector = Eigen::Matrix<double, kMaxLocal, 1>;
using Matrix = Eigen::Matrix<double, kMaxLocal, kMaxLocal>;
using Inner = Eigen::AutoDiffScalar<Vector>;
using InnerVector = Eigen::Matrix<Inner, kMaxLocal, 1>;
using Dual = Eigen::AutoDiffScalar<InnerVector>;  // value, gradient and Hessian

inline int local_size(int order) { return 2 * (order + 1) + 2; }
inline int local_r(int node) { return node; }
inline int local_z(int order, int node) { return order + 1 + node; }
inline int local_start_radius(int order) { return 2 * (order + 1); }
inline int local_end_radius(int order) { return 2 * (order + 1) + 1; }

// Where an element lies in its part: xi in [xi0, xi0 + dxi], mapped to R by the part's map.
struct ElementPlace {
  int order = 2;
  bool logarithmic = false;
  double xi0 = 0.0;
  double dxi = 1.0;
  const RigidProfile* profile = nullptr;  // set when the element lies on a probe's profile
  // Gas pressure under the membrane, P = p (A / L0) / (G H): adds -P V / (2 pi A^3) to the
  // energy, V the volume between the membrane and the clamp plane.  Zero on a probe's profile,
  // whose volume depends on the contact edge and the depth only (smooth_probe.cpp adds it).
  double pressure = 0.0;
};

// Lagrange shape functions on equally spaced nodes of [-1, 1] and their derivatives.
inline void shape_functions(int order, double eta, std::array<double, kMaxOrder + 1>& n,
                            std::array<double, kMaxOrder + 1>& dn) {
  if (order == 1) {
    n = {0.5 * (1.0 - eta), 0.5 * (1.0 + eta), 0.0};
    dn = {-0.5, 0.5, 0.0};
  } else {
    n = {0.5 * eta * (eta - 1.0), 1.0 - eta * eta, 0.5 * eta * (eta + 1.0)};
    dn = {eta - 0.5, -2.0 * eta, eta + 0.5};
  }
}

// rho(s) of the profile with the derivatives of s carried through (chain rule, as Eigen's own
// sin of an AutoDiffScalar): plain, first-order and nested second-order scalars.
inline double profile_radius(const RigidProfile& profile, double s) { return profile.radius(s); }
inline Inner profile_radius(const RigidProfile& profile, const Inner& s) {
  return Inner(profile.radius(s.value()), profile.radius_slope(s.value()) * s.derivatives());
}
inline Dual profile_radius(const RigidProfile& profile, const Dual& s) {
  const double s0 = s.value().value();
  const Inner slope(profile.radius_slope(s0),
                    profile.radius_curvature(s0) * s.value().derivatives());
  InnerVector outer;
  for (int k = 0; k < kMaxLocal; ++k) outer[k] = slope * s.derivatives()[k];
  return Dual(profile_radius(profile, s.value()), outer);
}

// Reference radius at xi for a part from `start` to `end`, and dR/dxi.
template <class T>
void part_map(bool logarithmic, const T& start, const T& end, double xi, T& radius, T& d_radius) {
  if (logarithmic) {
    const T log_ratio = log(end / start);
    radius = start * exp(xi * log_ratio);
    d_radius = radius * log_ratio;
  } else {
    radius = start + xi * (end - start);
    d_radius = end - start;
  }
}

// Stretches at eta in the element from the local unknowns (any scalar type); false when the
// state is not admissible there (a reference interval of zero or negative length, r <= 0).
template <class T>
bool stretches_at(const ElementPlace& place, const std::array<T, kMaxLocal>& local, double eta,
                  T& l1, T& l2, T& radius, T& weight) {
  std::array<double, kMaxOrder + 1> n{}, dn{};
  shape_functions(place.order, eta, n, dn);
  T d_radius;
  const double xi = place.xi0 + 0.5 * place.dxi * (eta + 1.0);
  part_map(place.logarithmic,
           local[local_start_radius(place.order)],
           local[local_end_radius(place.order)],
           xi,
           radius,
           d_radius);
  const T d_radius_d_eta = d_radius * (0.5 * place.dxi);
  T r = local[0] * n[0], dr = local[0] * dn[0];
  T dz = local[local_z(place.order, 0)] * dn[0];
  for (int i = 1; i <= place.order; ++i) {
    r += local[local_r(i)] * n[i];
    dr += local[local_r(i)] * dn[i];
    dz += local[local_z(place.order, i)] * dn[i];
  }
  using std::sqrt;
  if (place.profile) {  // r holds the arclength along the profile
    if (!(d_radius_d_eta > 0.0) || !(radius > 0.0) || !(dr > 0.0)) return false;
    l1 = dr / d_radius_d_eta;
    l2 = profile_radius(*place.profile, r) / radius;
    weight = radius * d_radius_d_eta;
    return l2 > 0.0;
  }
  if (!(d_radius_d_eta > 0.0) || !(radius > 0.0) || !(r > 0.0)) return false;
  l1 = sqrt(dr * dr + dz * dz) / d_radius_d_eta;
  l2 = r / radius;
  weight = radius * d_radius_d_eta;  // R dR / d eta
  return l1 > 0.0;
}

// z r dr/deta at eta, the integrand of -V / (2 pi) (V = 2 pi int y r dr with the height y = -z
// above the clamp plane): a polynomial of degree 3 order - 1, exact under the Gauss rule below.
template <class T>
T volume_integrand(const ElementPlace& place, const std::array<T, kMaxLocal>& local, double eta) {
  std::array<double, kMaxOrder + 1> n{}, dn{};
  shape_functions(place.order, eta, n, dn);
  T r = local[0] * n[0], dr = local[0] * dn[0], z = local[local_z(place.order, 0)] * n[0];
  for (int i = 1; i <= place.order; ++i) {
    r += local[local_r(i)] * n[i];
    dr += local[local_r(i)] * dn[i];
    z += local[local_z(place.order, i)] * n[i];
  }
  return z * r * dr;
}

// W / G at the stretches, with the derivatives carried through the stretches.
inline Dual strain_energy(const MaterialLaw& law, const Dual& l1, const Dual& l2, bool& locked) {
  const double a = l1.value().value(), b = l2.value().value();
  const double i1 = first_invariant(a, b);
  const double w = strain_energy_density(law, a, b);
  locked = !std::isfinite(w) || i1 >= locking_first_invariant(law);
  const MembraneStress s = membrane_stress(law, a, b);
  const Vector& da = l1.value().derivatives();
  const Vector& db = l2.value().derivatives();
  // Inner level: first derivatives of W and of s1, s2 with respect to the local unknowns.
  const Inner w_inner(w, s.s1 * da + s.s2 * db);
  const Inner s1(s.s1, s.ds1_dl1 * da + s.ds1_dl2 * db);
  const Inner s2(s.s2, s.ds1_dl2 * da + s.ds2_dl2 * db);
  InnerVector outer;
  for (int k = 0; k < kMaxLocal; ++k)
    outer[k] = s1 * l1.derivatives()[k] + s2 * l2.derivatives()[k];
  return Dual(w_inner, outer);
}

struct ElementResult {
  bool admissible = true;
  double energy = 0.0;  // integral of W / G  R dR over the element
  Vector gradient = Vector::Zero();
  Matrix hessian = Matrix::Zero();
};

// Gauss-Legendre points on [-1, 1]: five, exact for polynomials of degree 9.
inline const std::array<std::pair<double, double>, 5>& gauss_points() {
  static const std::array<std::pair<double, double>, 5> points = [] {
    const double a = std::sqrt(245.0 - 14.0 * std::sqrt(70.0)) / 21.0;
    const double b = std::sqrt(245.0 + 14.0 * std::sqrt(70.0)) / 21.0;
    const double wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0;
    const double wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
    return std::array<std::pair<double, double>, 5>{
        {{-b, wb}, {-a, wa}, {0.0, 128.0 / 225.0}, {a, wa}, {b, wb}}};
  }();
  return points;
}

// The energy alone, in plain doubles (the line search's many evaluations).
inline double element_energy_value(const MaterialLaw& law, const ElementPlace& place,
                                   const std::array<double, kMaxLocal>& values) {
  double total = 0.0;
  for (const auto& [eta, w_gauss] : gauss_points()) {
    double l1, l2, radius, weight;
    if (!stretches_at(place, values, eta, l1, l2, radius, weight))
      return std::numeric_limits<double>::infinity();
    const double i1 = first_invariant(l1, l2);
    if (i1 >= locking_first_invariant(law)) return std::numeric_limits<double>::infinity();
    const double w = strain_energy_density(law, l1, l2);
    if (!std::isfinite(w)) return std::numeric_limits<double>::infinity();
    total += w * weight * w_gauss;
    if (place.pressure != 0.0)
      total += place.pressure * volume_integrand(place, values, eta) * w_gauss;
  }
  return total;
}

// Energy, gradient and Hessian of one element.
inline ElementResult element_energy(const MaterialLaw& law, const ElementPlace& place,
                                    const std::array<double, kMaxLocal>& values) {
  ElementResult result;
  const int size = local_size(place.order);
  std::array<Dual, kMaxLocal> local;
  for (int k = 0; k < kMaxLocal; ++k) {
    InnerVector seed;
    for (int j = 0; j < kMaxLocal; ++j)
      seed[j] = Inner(j == k && k < size ? 1.0 : 0.0, Vector::Zero());
    local[k] =
        Dual(Inner(values[k], k < size ? Vector(Vector::Unit(k)) : Vector(Vector::Zero())), seed);
  }
  Dual total(Inner(0.0, Vector::Zero()), InnerVector::Constant(Inner(0.0, Vector::Zero())));
  for (const auto& [eta, w_gauss] : gauss_points()) {
    Dual l1, l2, radius, weight;
    if (!stretches_at(place, local, eta, l1, l2, radius, weight)) {
      result.admissible = false;
      result.energy = std::numeric_limits<double>::infinity();
      return result;
    }
    bool locked = false;
    const Dual w = strain_energy(law, l1, l2, locked);
    if (locked) {
      result.admissible = false;
      result.energy = std::numeric_limits<double>::infinity();
      return result;
    }
    total += w * weight * w_gauss;
    if (place.pressure != 0.0)
      total += volume_integrand(place, local, eta) * (place.pressure * w_gauss);
  }
  result.energy = total.value().value();
  result.gradient = total.value().derivatives();
  for (int k = 0; k < kMaxLocal; ++k) result.hessian.col(k) = total.derivatives()[k].derivatives();
  return result;
}

}  // namespace puncture::fe
