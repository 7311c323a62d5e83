#pragma once
// A second solver, independent of the shooting one (it shares only the material laws): the
// membrane discretised by Lagrange finite elements along the meridian, the unknowns being the
// current radius r and deflection z at the nodes and the reference radii where the contact with
// the indenter begins and ends; equilibrium minimises the stored energy at a prescribed depth
// (docs/verification.md, "The finite-element solver").  It covers the sharp flat punch,
// frictionless (tip, corner and side) and held at its edge, and every other probe (sphere-tipped,
// flat punch with a rounded corner, cone, ball) frictionless (the membrane lying on its profile
// from the pole to a contact edge found by the method: docs/model.md, "Finite elements on a
// smooth probe") and held where it touched (the stick rule `always`: each node, once it reaches
// the profile, stays at that arclength and moves with the probe; docs/model.md §15.3, "Held where
// it touched"); a contact past the cone's shank or the ball's equator is Status::OutsideModel,
// and a held membrane reaching the sphere-tipped probe's or the fillet's cylinder side
// Status::StickWrapsSide, as in the shooting.  Coulomb friction is not modelled (it is
// dissipative: there is no energy to minimise).
#include <optional>
#include <string>
#include <vector>

#include "puncture/membrane_fields.hpp"
#include "puncture/outcome.hpp"
#include "puncture/problem.hpp"

namespace puncture {

enum class FeContact {
  Frictionless,  // the membrane slides freely over the tip, the corner and the side (mu' = 0)
  Held,          // the stick stage (fully stuck): held at the sharp punch's edge, or on a smooth
                 // probe where each material point touched (one loading history from the flat
                 // membrane, an event at each depth where a node reaches the profile)
};

struct FeOptions {
  int elements = 64;  // along the free part (Part I); Parts II, III (a smooth probe: each contact
                      // segment, cap and side) get a quarter each; held on a smooth probe, the
                      // reach that may be held half and a flat face an eighth
  int order = 2;      // polynomial order of the elements: 1 (linear) or 2 (quadratic)
  int max_newton_iterations = 60;  // per depth step
  int max_step_halvings = 16;      // continuation in depth: refinements of one step before failing
  double max_depth_step = 0.05;    // largest continuation step, as a fraction of the clamp radius
};

// One part of the meridian as the elements represent it: nodes equally spaced in a coordinate
// xi in [0, 1], mapped to the reference radius linearly or (Part I) logarithmically.
struct FePart {
  MembranePart part = MembranePart::Free;
  double start_radius_mm = 0.0;       // reference radius R of its inner end [mm]
  double end_radius_mm = 0.0;         // ... and of its outer end [mm]
  bool logarithmic = false;           // R = R_start (R_end / R_start)^xi, else linear in xi
  int elements = 0;                   // each of `order` + 1 nodes, neighbours sharing one
  std::vector<double> radius_mm;      // current radius r at the nodes [mm]
  std::vector<double> deflection_mm;  // deflection z below the clamp plane at the nodes [mm]
  // On a smooth probe's profile: the arclength s from the probe's pole at the nodes, the
  // elements' unknown there (r and z follow from the profile) [mm]; empty off the probe.
  std::vector<double> arclength_mm;
};

struct FeState : Outcome {
  FeContact contact = FeContact::Frictionless;
  int order = 2;
  double depth_mm = 0.0;           // prescribed indentation depth [mm]
  double force_n = 0.0;            // indenter force F = dU/d(depth), the reaction [N]
  double normalized_force = 0.0;   // F / (2 pi G H A)
  double stored_energy_nmm = 0.0;  // elastic energy U [N mm]
  // Under a gas pressure p: the volume V between the membrane and its clamp plane [mm^3] (> 0
  // above it), so that Pi = U - p V is the energy minimised and dPi/d(depth) = F.  0 without.
  double volume_mm3 = 0.0;
  // Under a gas pressure, the gauge pressure the state carries [MPa]: the held one, or over a
  // sealed chamber the one its gas law gives with volume_mm3 (docs/model.md §17.2).  0 without.
  double gas_pressure_mpa = 0.0;
  bool part_two = false;  // the membrane wraps the indenter's (cylinder) side
  // Flat punch: a / R at the corner (1 when held).  Smooth probe: the pole's equibiaxial stretch.
  double part_three_stretch = 1.0;
  // R at the corner (edge of Part III); on the sphere-tipped probe, where the contact leaves the
  // hemisphere (the contact edge, or the equator once the side is wrapped).
  double corner_reference_radius_mm = 0.0;
  double part_two_top_reference_radius_mm = 0.0;  // R where the membrane leaves the probe
  double contact_edge_radius_mm = 0.0;            // current radius r there [mm]
  // Smooth probe: the deepest a node of the free part lies inside the probe (0 when none), the
  // check of non-penetration [mm]; 0 for the flat punch.
  double largest_penetration_mm = 0.0;
  double max_first_invariant = 3.0;  // largest I1 at the quadrature points and nodes
  double max_first_invariant_reference_radius_mm = 0.0;
  int newton_iterations = 0;  // in the last depth step
  int unknowns = 0;
  std::vector<FePart> parts;  // from the centre outward
};

// States at the given depths [mm] (increasing, > 0), each reached by continuation in depth from
// the flat membrane, or under a gas pressure (frictionless, and held on a smooth probe) from the
// elements' own inflated dome, minimising U - p V, depths counted from its pole (docs/model.md
// §17.2, §15.3).  Over a sealed
// chamber (Preload::gas_volume_mm3, closed at a pressure > 0) each state is the one at the
// pressure its own volume gives by the gas law, depths from the sealed dome's pole.  Throws
// std::invalid_argument for an invalid problem, depths or options.
std::vector<FeState> fe_solve_at_depths(const Problem& problem,
                                        const std::vector<double>& depths_mm, FeContact contact,
                                        const FeOptions& options = {});
FeState fe_solve_at_depth(const Problem& problem, double depth_mm, FeContact contact,
                          const FeOptions& options = {});

// Under a gas pressure (Problem::preload.pressure_mpa > 0): the elements' inflated membrane before
// contact, the minimum of U - p V from which fe_solve_at_depths starts (depth 0, no force; the
// pole stretch as part_three_stretch, the pole's height above the clamp as -deflection_mm at
// the first node), on `options.elements` elements linear in R (also a dome overhanging its
// clamp); over a sealed chamber the dome it is closed at.  A pressure the membrane cannot hold
// (it bursts or snaps through), or a later inflated state that overhangs, is the state's status.
// Throws
// std::invalid_argument for an invalid problem or options, or without a pressure.
FeState fe_inflated_state(const Problem& problem, const FeOptions& options = {});

// I1 of the finite-element solution at reference radius R [mm] inside the given part (1, 2 or
// 3); empty when the state has no such part or R is outside it.
std::optional<double> fe_first_invariant(const FeState& state, MembranePart part,
                                         double reference_radius_mm);

std::string to_string(FeContact contact);

}  // namespace puncture
