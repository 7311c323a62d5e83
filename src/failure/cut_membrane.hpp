#pragma once
// The membrane cut through its thickness along a ring, at rest on a frictionless rod through the
// hole (docs/model.md §18, the energy-release criterion).  Normalised like the solver: lengths
// by the stress-free clamp radius A / L0, stresses by G, energies by 2 pi G H (A / L0)^2 (so an
// energy is the integral of W R dR).
#include <optional>

#include "puncture/material.hpp"

namespace puncture::detail {

// A flat annulus from reference radius `inner` to the clamp (R = 1, where lambda2 = L0), in
// plane axisymmetric equilibrium d(R s1)/dR = s2.
struct FlatAnnulus {
  double energy = 0.0;        // integral of W R dR over the annulus
  double inner_radius = 0.0;  // current radius r of the inner edge
  double inner_s1 = 0.0;      // radial nominal stress there (0 on a free edge)
};

// The annulus with a free inner edge (s1 = 0 there): empty if no equilibrium is found below the
// law's locking limit.
std::optional<FlatAnnulus> free_edge_annulus(const MaterialLaw& law, double inner,
                                             double prestretch);
// The annulus with its inner edge held at current radius `inner_radius` (a rod pushing it open
// puts the edge in radial compression: not a membrane state, the small-strain check's case).
std::optional<FlatAnnulus> held_edge_annulus(const MaterialLaw& law, double inner,
                                             double inner_radius, double prestretch);

// The rings from reference radius `from` to `to` wrapped on a rod of radius `rod`, free of
// meridional stress: each in uniaxial hoop tension at lambda2 = rod / R (lambda1 = lambda2^-1/2).
double slack_collar_energy(const MaterialLaw& law, double rod, double from, double to);

// The cut membrane: the disc inside `cut` free of stress; the annulus outside in the clamp plane
// with a free inner edge.  If that edge would lie inside the rod (radius `rod`), the rings from
// `cut` to `collar_to` wrap the rod slack and the flat annulus from `collar_to` has its free
// edge at the rod.
struct CutMembrane {
  double energy = 0.0;       // annulus and collar
  double collar_to = 0.0;    // R_j (`cut` when the hole clears the rod)
  double hole_radius = 0.0;  // current radius of the flat annulus's inner edge (>= rod)
};
std::optional<CutMembrane> cut_membrane(const MaterialLaw& law, double rod, double cut,
                                        double prestretch);

}  // namespace puncture::detail
