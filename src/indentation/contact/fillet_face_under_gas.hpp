#pragma once
// The filleted flat punch under a gas pressure (docs/model.md §17, §19): while the gas alone
// carries the force on a disc of the flat face, f <= P b^2 / 2 (b the face's radius), the
// membrane touches the face only.  The face is flat, so its contact pressure is exactly P (no
// curvature carries any of it) and, without friction, Part III is uniform at the pole stretch l;
// where Part I leaves the face the meridian is horizontal, so the disc's vertical balance is
// f = P c^2 / 2: F = p pi c^2, as on the sharp punch's face (contact/flat_punch.hpp).  Past
// P b^2 / 2 the arc starts at the face's edge (sphere_tipped.hpp's march, whose edge event
// counts the gas's share P r^2 / 2).  With Coulomb slip the face carries the traction mu P and
// is no longer uniform: the sharp punch's Part III system (flat_punch_face.hpp) marched from the
// pole, with the stored energy, to the contact disc's edge or to the face's (the arc's start).
#include <cmath>
#include <optional>
#include <vector>

#include "indentation/contact/contact_model.hpp"
#include "indentation/contact/flat_punch_face.hpp"
#include "indentation/free_part.hpp"
#include "indentation/scaled_solution.hpp"
#include "numerics/integrate.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// ---- With Coulomb slip: Part III not uniform.  Its samples carry the profile coordinate psi =
// (r - b) / rho < 0 (the arc's theta is 0 at the face's edge), so that the fields know each
// point's current radius.

// The face's edge (or the contact disc's): reference radius, stretches and stored energy
// int W R dR from the pole (/ (2 pi G H A^2)), as the arc's march state (theta = 0, lambda1, e).
struct RoughFaceEdge {
  double r_ref = 0.0, l1 = 0.0, l2 = 0.0, energy = 0.0;
};

// Part III with the stored energy, along the current radius r: (R, lambda1, e), de/dr = W R /
// lambda1 (dR/dr = 1 / lambda1).
template <class Law>
struct RoughFaceEnergySystem {
  PartThreeSystem<Law> face;
  void operator()(const std::array<double, 3>& x, std::array<double, 3>& dx, double r) const {
    const PartThreeState y{x[0], x[1]};
    PartThreeState dy{};
    face(y, dy, r);
    dx[0] = dy[0];
    dx[1] = dy[1];
    const double l2 = r / x[0];
    dx[2] = dy[0] > 0.0
                ? strain_energy_density(face.law, x[1], l2, first_invariant(x[1], l2)) * x[0] / x[1]
                : dy[0];  // outside the domain: the system's NaN
  }
};

// From the pole stretch `pole` to the current radius `edge` (<= b); with `samples`, (R, lambda1,
// psi) from the pole, psi = (r - face) / arc.  Empty when the material locks or the edge's
// material lies beyond the clamp.
template <class Law>
std::optional<RoughFaceEdge> rough_fillet_face(const Law& law, double locking_i1,
                                               double mu_pressure, double pole, double edge,
                                               IntegrationSettings integration, double face,
                                               double arc,
                                               std::vector<PartTwoSample>* samples = nullptr,
                                               int points = 0) {
  const RoughFaceEnergySystem<Law> system{{law, mu_pressure, locking_i1}};
  const double r_start = 1e-3 * edge;  // the series' error, O((mu P r)^2), is ~1e-12 there
  const auto start = system.face.pole_start(pole, r_start);
  if (!start || !(edge > 0.0)) return std::nullopt;
  const auto st = membrane_stress(law, pole, pole);
  std::array<double, 3> x{
      (*start)[0],
      (*start)[1],
      0.5 * strain_energy_density(law, pole, pole, st.i1) * (*start)[0] * (*start)[0]};
  if (samples) {
    samples->clear();
    samples->push_back({0.0, pole, -face / arc});
    if (points > 0) integration.max_step = edge / points;
  }
  const bool ok =
      integrate_part(system, x, r_start, edge, integration, [&](double r, const auto& y) {
        if (samples && r < edge) samples->push_back({y[0], y[1], (r - face) / arc});
        return y[0] < 1.0;  // the edge's material must lie inside the clamp
      });
  if (!ok || !(x[0] < 1.0) || !(x[0] > 0.0) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    return std::nullopt;
  return RoughFaceEdge{x[0], x[1], edge / x[0], x[2]};
}

// The face stage and the rough face, for the contact model (sphere_tipped.hpp).
template <class Law>
struct FilletFaceUnderGas {
  const Law& law;
  double locking_i1;
  double pressure;  // P; the face stage exists only with P > 0
  double mu;
  double face;  // b / (A / L0); 0 for the sphere-tipped probe, the ball and the cone
  double arc;   // rho / (A / L0)
  IntegrationSettings integration;

  // The gas's share on the whole face, P b^2 / 2: up to it the membrane touches the face only.
  bool on_face(double f) const {
    return face > 0.0 && pressure > 0.0 && f <= 0.5 * pressure * face * face;
  }
  // The face carries the slip traction mu P (not uniform).
  bool rough() const { return face > 0.0 && pressure > 0.0 && mu != 0.0; }

  // Part III from the pole stretch l to the current radius `edge` (rough only).
  std::optional<RoughFaceEdge> march(double l, double edge,
                                     std::vector<PartTwoSample>* samples = nullptr,
                                     int points = 0) const {
    return rough_fillet_face(
        law, locking_i1, mu * pressure, l, edge, integration, face, arc, samples, points);
  }

  // Part I leaving the contact disc c = sqrt(2 f / P) of the face tangentially: slope 0, t = R s1
  // (R = c / l and s_eq(l) on the uniform face).  Empty past locking or with the disc's material
  // beyond the clamp.
  std::optional<FreeStart> start(double f, double l) const {
    const double c = std::sqrt(2.0 * f / pressure);
    if (rough()) {
      const auto e = march(l, c);
      if (!e) return std::nullopt;
      const double s1 = membrane_stress(law, e->l1, e->l2).s1;
      if (!(s1 > 0.0) || !std::isfinite(s1)) return std::nullopt;
      return FreeStart{{e->r_ref * s1, e->l1, e->l2, 0.0}, e->r_ref, 0.0, 1.0};
    }
    const auto st = membrane_stress(law, l, l);
    if (!(st.i1 < locking_i1) || !(st.s1 > 0.0) || !std::isfinite(st.s1)) return std::nullopt;
    const double r0 = c / l;
    if (!(r0 > 0.0) || !(r0 < 1.0)) return std::nullopt;
    return FreeStart{{r0 * st.s1, l, l, 0.0}, r0, 0.0, 1.0};
  }

  // The parts in contact on the face alone, after Part I: the disc up to Part I's start, sampled
  // with `points` > 0 (uniform: points + 1 samples (R, l, 0); rough: the march's, psi < 0), its
  // edge at the tip's depth; the rough disc's largest I1 (at its edge: both stretches grow
  // outward) into the solution's.
  bool attach(const FreeStart& st, double l, int points, ScaledSolution& sol) const {
    sol.part_two.clear();
    sol.r_corner = st.r0;
    sol.part_three_stretch = l;
    sol.part_two_length = 0.0;
    sol.tension_ratio = 1.0;
    if (!rough()) {
      for (int k = 0; k <= points && points > 0; ++k)
        sol.part_two.push_back({st.r0 * k / points, l, 0.0});
      return true;
    }
    const auto e =
        march(l, std::sqrt(2.0 * sol.f / pressure), points > 0 ? &sol.part_two : nullptr, points);
    if (!e) {
      sol.status = Status::NoConvergence;
      sol.message = "the flat face with friction could not be integrated again";
      return false;
    }
    if (points > 0) sol.part_two.push_back({e->r_ref, e->l1, (e->l2 * e->r_ref - face) / arc});
    if (const double i1 = first_invariant(e->l1, e->l2); i1 > sol.max_i1) {
      sol.max_i1 = i1;
      sol.max_i1_r = e->r_ref;
      sol.max_i1_radius = e->l2 * e->r_ref;
    }
    return true;
  }
};

}  // namespace puncture::detail
