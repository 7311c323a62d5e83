#include "failure/cut_membrane.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "numerics/gauss_legendre.hpp"
#include "numerics/integrate.hpp"
#include "numerics/shooting.hpp"

namespace puncture::detail {

namespace {

// (lambda1, lambda2, integral of W R dR) along the reference radius R.
using AnnulusState = std::array<double, 3>;

// Plane axisymmetric equilibrium of a flat membrane, d(R s1)/dR = s2 with lambda2 = r / R and
// lambda1 = dr/dR: s1 + R (ds1/dl1 lambda1' + ds1/dl2 lambda2') = s2.  Unlike the free membrane's
// ODE it is written in the stretches, so it also follows radial compression (the held edge).
struct FlatAnnulusSystem {
  const MaterialLaw& law;
  double locking_i1;
  void operator()(const AnnulusState& x, AnnulusState& dx, double r) const {
    const double l1 = x[0], l2 = x[1];
    if (!(l1 > 0.0 && l2 > 0.0) || !(first_invariant(l1, l2) < locking_i1)) {
      outside_domain(dx);
      return;
    }
    const MembraneStress s = membrane_stress(law, l1, l2);
    if (!(s.ds1_dl1 > 0.0)) {
      outside_domain(dx);
      return;
    }
    const double dl2 = (l1 - l2) / r;
    dx[0] = (s.s2 - s.s1 - r * s.ds1_dl2 * dl2) / (r * s.ds1_dl1);
    dx[1] = dl2;
    dx[2] = strain_energy_density(law, l1, l2) * r;
  }
};

// The solver's integration tolerances (docs/model.md §7).
constexpr IntegrationSettings kIntegration{3e-11, 3e-13, 100000};

// The state at the clamp from (lambda1, lambda2) at the inner edge; empty past locking.
std::optional<AnnulusState> to_clamp(const MaterialLaw& law, double inner, double l1, double l2) {
  const FlatAnnulusSystem system{law, locking_first_invariant(law)};
  return advance(system, AnnulusState{l1, l2, 0.0}, inner, 1.0, kIntegration);
}

std::optional<FlatAnnulus> annulus_from(const MaterialLaw& law, double inner, double l1,
                                        double l2) {
  const auto end = to_clamp(law, inner, l1, l2);
  if (!end) return std::nullopt;
  return FlatAnnulus{(*end)[2], inner * l2, membrane_stress(law, l1, l2).s1};
}

// The clamp residual lambda2(1) - L0 is resolved to the integration's noise.
constexpr ShootingEnd kClampResidual{1e-12, std::nullopt};
constexpr int kMaxIterations = 200;

}  // namespace

std::optional<FlatAnnulus> free_edge_annulus(const MaterialLaw& law, double inner,
                                             double prestretch) {
  // Without pre-stretch the annulus is at rest: lambda1 = lambda2 = 1 solves the ODE exactly.
  if (prestretch == 1.0) return FlatAnnulus{0.0, inner, 0.0};
  // Free edge: s1 = 0, i.e. lambda1 = lambda3 = lambda2^-1/2 (s1 vanishes there for every law);
  // the shooting parameter is the edge's hoop stretch, from 1 (then the annulus stays at rest,
  // lambda2(1) = 1 < L0) upward: a wider hole pulls the clamp's ring wider.
  auto residual = [&](double p) -> std::optional<double> {
    const auto end = to_clamp(law, inner, 1.0 / std::sqrt(p), p);
    if (!end) return std::nullopt;
    return (*end)[1] - prestretch;
  };
  const auto p = shoot_increasing(residual,
                                  1.0,
                                  1.0 - prestretch,
                                  std::numeric_limits<double>::infinity(),
                                  kMaxIterations,
                                  prestretch - 1.0,
                                  kClampResidual);
  if (!p) return std::nullopt;
  return annulus_from(law, inner, 1.0 / std::sqrt(*p), *p);
}

std::optional<FlatAnnulus> held_edge_annulus(const MaterialLaw& law, double inner,
                                             double inner_radius, double prestretch) {
  const double l2 = inner_radius / inner;
  // The parameter is the edge's radial stretch; the clamp's hoop stretch grows with it.  Below
  // the root a too small stretch collapses the annulus (lambda2 -> 0): negative.
  auto residual = [&](double q) -> std::optional<double> {
    const auto end = to_clamp(law, inner, q, l2);
    if (!end) return std::nullopt;
    return (*end)[1] - prestretch;
  };
  double lo = 1.0;
  std::optional<double> g_lo = residual(lo);
  for (int k = 0; k < kMaxIterations && !(g_lo && *g_lo < 0.0); ++k) {
    lo *= 0.9;
    g_lo = residual(lo);
    if (!g_lo) g_lo = -1.0;  // collapsed
  }
  if (!(g_lo && *g_lo < 0.0)) return std::nullopt;
  const auto q = shoot_increasing(residual,
                                  lo,
                                  *g_lo,
                                  std::numeric_limits<double>::infinity(),
                                  kMaxIterations,
                                  0.1 * lo,
                                  kClampResidual);
  if (!q) return std::nullopt;
  return annulus_from(law, inner, *q, l2);
}

double slack_collar_energy(const MaterialLaw& law, double rod, double from, double to) {
  if (!(to > from)) return 0.0;
  // With x = lambda2 = rod / R, R dR = -rod^2 x^-3 dx; in t = ln x, rod^2 W x^-2 dt: smooth in
  // t, whatever the range of stretches (up to the Part III stretch).
  QuadratureNodes q;
  append_gauss_legendre(std::log(rod / to), std::log(rod / from), 16, q);
  double sum = 0.0;
  for (std::size_t i = 0; i < q.nodes.size(); ++i) {
    const double x = std::exp(q.nodes[i]);
    sum += q.weights[i] * strain_energy_density(law, 1.0 / std::sqrt(x), x) / (x * x);
  }
  return rod * rod * sum;
}

std::optional<CutMembrane> cut_membrane(const MaterialLaw& law, double rod, double cut,
                                        double prestretch) {
  const auto at_cut = free_edge_annulus(law, cut, prestretch);
  if (!at_cut) return std::nullopt;
  if (at_cut->inner_radius >= rod) return CutMembrane{at_cut->energy, cut, at_cut->inner_radius};
  // The flat annulus's free edge would lie inside the rod: the rings nearest the cut wrap the rod
  // until the flat annulus's free edge sits on it.  That edge's radius grows with its reference
  // radius, to L0 at the clamp, beyond the rod (a < A).
  std::optional<FlatAnnulus> flat;
  double collar_to = rod;  // without pre-stretch the flat annulus is at rest: r = R
  if (prestretch == 1.0) {
    flat = FlatAnnulus{0.0, rod, 0.0};
  } else {
    auto gap = [&](double r_j) -> std::optional<double> {
      const auto a = free_edge_annulus(law, r_j, prestretch);
      if (!a) return std::nullopt;
      return a->inner_radius - rod;
    };
    const auto r_j = shoot_increasing(
        gap, cut, at_cut->inner_radius - rod, 1.0, kMaxIterations, 0.0, ShootingEnd{1e-14, {}});
    if (!r_j) return std::nullopt;
    collar_to = *r_j;
    flat = free_edge_annulus(law, collar_to, prestretch);
    if (!flat) return std::nullopt;
  }
  return CutMembrane{
      flat->energy + slack_collar_energy(law, rod, cut, collar_to), collar_to, flat->inner_radius};
}

}  // namespace puncture::detail
