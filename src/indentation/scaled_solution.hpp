#pragma once
// A solution of the indentation problem in normalised variables, whatever the indenter, and the
// settings of the shooting that finds it.  Lengths are normalised by the stress-free clamp
// radius A / L0 (A without pre-stretch; SolverScales), stresses by G, the force f by
// 2 pi G H A / L0.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "numerics/integrate.hpp"
#include "puncture/equilibrium.hpp"

namespace puncture::detail {

// How the shooting integrates and when it stops (from SolverOptions).
struct ShootingSettings {
  IntegrationSettings integration;
  double shooting_tol;
  int max_iterations;
  int field_points;  // intervals between the samples of a recorded part (even_samples)
  // The clamp condition lambda2 = L0 at R = 1, and the stretch of material the indenter holds
  // where it touched: the pre-stretch (1 for a membrane mounted stress-free).
  double prestretch = 1.0;
  // The gas pressure under the membrane, P = p (A / L0) / (G H), pushing it against the
  // indenter (0: none), and the inflated pole's height above the clamp, / (A / L0): depths are
  // measured from it.
  double pressure = 0.0;
  double dome_height = 0.0;
  // The inflated pole's equibiaxial stretch, the stretch of the first material an indenter
  // touches under a gas pressure (0: no dome).
  double dome_pole_stretch = 0.0;
  // Whether that dome overhangs its clamp (beyond a hemisphere): the puncture is then searched
  // along the path in depth alone (puncture_search.hpp).
  bool dome_overhangs = false;
  // Whether that dome is a later inflated state than the first (Preload::inflated_state), which
  // overhangs: the shooting at a force then refuses (OutsideModel), its searches near zero force
  // finding the first state's branch, and the states are followed in depth control from the dome
  // (depth_path_puncture.hpp: dome_branch_start).
  bool dome_later_state = false;
};

// Part I sample: R, t, lambda1, lambda2, h.  Part II sample: R, lambda1, y.
using PartOneSample = std::array<double, 5>;
using PartTwoSample = std::array<double, 3>;

struct ScaledSolution {
  Status status = Status::NoConvergence;
  std::string message;
  Configuration configuration = Configuration::Unloaded;
  double f = 0.0;          // F / (2 pi G H A / L0)
  double parameter = 0.0;  // the configuration's shooting parameter (see the contact model)
  double part_three_stretch = 1.0;
  double r_corner = 0.0;         // reference radius of the material at the corner
  double r_top = 0.0;            // reference radius where Part I starts
  double edge_radius = 0.0;      // ... and its current radius (the contact's edge)
  double part_two_length = 0.0;  // current length of Part II
  double depth = 0.0;
  double corner_slope = 0.0;
  double tension_ratio = 1.0;  // s1 outside the corner / s1 in Part III
  double edge_s1 = 0.0;        // s1 at the inner end of Part I
  // Held on a curved probe: the largest |tangential traction| / contact pressure of the held
  // contact, what Coulomb friction must reach to hold it (StickRule::Coulomb).
  double held_traction_ratio = 0.0;
  double max_i1 = 3.0;         // largest I1 in Parts I and II
  double max_i1_r = 0.0;       // ... at this reference radius
  double max_i1_radius = 0.0;  // ... and this current radius
  double residual = 0.0;       // lambda2 - L0 at the clamp
  int evaluations = 0;
  bool integrated = false;    // every part was integrated (residual and depth are defined)
  double shooting_tol = 0.0;  // the clamp tolerance it was judged against
  // A failure to reach a depth that carries the deepest state the stage reaches (its fields
  // are that state's; the message says why no deeper state exists).
  bool deepest_state = false;
  // Where the hoop stress first turns compressive (reference and current radius; -1: nowhere),
  // found on the states whose largest I1 is searched.
  double wrinkle_r = -1.0;
  double wrinkle_radius = -1.0;
  std::vector<PartOneSample> part_one;
  std::vector<PartTwoSample> part_two;
  // A non-uniform Part III (the flat punch with friction under pressure): R, lambda1, lambda2
  // from the pole to its edge; empty when it is uniform.
  std::vector<std::array<double, 3>> part_three;
  bool ok() const { return status == Status::Converged; }
};

// Largest I1 anywhere in the membrane, Part III (I1 = 2 L^2 + L^-4) included.
inline double max_first_invariant_of(const ScaledSolution& sol) {
  const double l3 = sol.part_three_stretch;
  return std::max(sol.max_i1, 2.0 * l3 * l3 + 1.0 / (l3 * l3 * l3 * l3));
}

// A state that meets the clamp condition, accepted as an equilibrium of the loading path unless
// it is none: every acceptance (the shooting's judgement, a collapsed bracket, depth control)
// goes through here.
//  - A probe pushing the membrane lies below where it first touched (the flat membrane, the
//    inflated pole): a root with the tip above it is not on the loading path (under pressure,
//    beyond a limit load or on another inflated branch, Part I can meet the clamp condition
//    again).  Numerical: the path's state was not found.
//  - A state whose hoop stress turns compressive (found where the largest I1 was searched)
//    wrinkles, outside the tension-only theory (the message, with the place in mm, is the
//    physical state's: to_physical).
inline void accept_state(ScaledSolution& sol) {
  sol.message.clear();
  if (sol.depth < 0.0 && sol.f > 0.0) {
    sol.status = Status::NoConvergence;
    sol.message = fmt::format(
        "the clamp condition is met only by a root with the probe above the membrane's first "
        "contact (normalised depth {:.3g}, Part III stretch {:.3g}): not on the loading path",
        sol.depth,
        sol.part_three_stretch);
  } else {
    sol.status = sol.wrinkle_r >= 0.0 ? Status::Wrinkles : Status::Converged;
  }
}

// After a bracketing shooting whose bracket has shrunk to adjacent floating-point numbers, the
// clamp residual left is the integration's noise; when the clamp condition is then met to within
// a hundred times the tolerance (1e-8 by default) the solution is accepted.
inline void accept_collapsed_bracket(ScaledSolution& sol, double tol_factor = 100.0) {
  if (sol.status == Status::NoConvergence && sol.integrated &&
      std::abs(sol.residual) <= tol_factor * sol.shooting_tol)
    accept_state(sol);
}

}  // namespace puncture::detail
