#pragma once
// One equilibrium state of the indented membrane, at a prescribed indenter force or depth.
#include <optional>
#include <string>
#include <vector>

#include "puncture/chamber_gas.hpp"
#include "puncture/membrane_fields.hpp"
#include "puncture/options.hpp"
#include "puncture/outcome.hpp"
#include "puncture/problem.hpp"

namespace puncture {

enum class Configuration {
  Unloaded,            // flat membrane, zero force
  Stick,               // membrane held at the indenter's edge; Part III unstretched
  SlipWithoutPartTwo,  // Part III stretched, capstan across the corner, Part I from the corner
  SlipWithPartTwo,     // Part III, corner wrapped by pi/2, Part II on the side, then Part I
  // After a `coulomb` release on a curved probe: a held core, a slipping annulus from the slip
  // front to the contact's edge, then Part I (docs/model.md §15.4).
  PartialSlip,
};

enum class Stage { Stick, Slip };

std::string to_string(Configuration configuration);
// Machine-readable name, as written in CSV and JSON: "slip_with_part_two" and so on.
std::string to_token(Configuration configuration);
std::string to_string(Stage stage);

struct Equilibrium : Outcome {
  Configuration configuration = Configuration::Unloaded;
  Stage stage = Stage::Slip;

  double force_n = 0.0;             // indenter force F [N]
  double normalized_force = 0.0;    // F / (2 pi G H A), the paper's normalisation
  double depth_mm = 0.0;            // indentation depth of the tip below the clamp plane [mm]
  double part_three_stretch = 1.0;  // homogeneous equibiaxial stretch under the tip
  double corner_reference_radius_mm = 0.0;        // R of the material at the corner (Part III edge)
  double part_two_top_reference_radius_mm = 0.0;  // R at the Part II / Part I boundary
  double part_two_length_mm = 0.0;                // current length of Part II along the side
  double corner_slope_rad = 0.0;                  // slope of Part I where it leaves the indenter
  // Where Part I leaves the indenter (the contact's edge): current radius and height above the
  // tip [mm].
  double contact_edge_radius_mm = 0.0;
  double contact_edge_height_mm = 0.0;
  // Partial slip (Configuration::PartialSlip): the slip front's reference radius R_s and current
  // distance from the axis [mm] (0 and 0 otherwise).
  double slip_front_reference_radius_mm = 0.0;
  double slip_front_radius_mm = 0.0;
  double corner_tension_ratio = 1.0;  // s1 just outside the corner / s1 in Part III
  double max_first_invariant = 3.0;   // largest I1 in the membrane: where a crack starts
  double max_first_invariant_reference_radius_mm = 0.0;        // where it is: reference radius R
  double max_first_invariant_radius_mm = 0.0;                  // ... and current radius r
  MembranePart max_first_invariant_part = MembranePart::Free;  // ... in this part
  // The failure criterion is exceeded in this state: loaded to it, the membrane would already
  // have punctured (a state of the model, not of the real membrane).
  bool beyond_puncture = false;
  double clamp_residual = 0.0;   // |lambda2(A) - 1| reached by the shooting
  int shooting_evaluations = 0;  // integrations of Part I used
  MembraneFields fields;
  // A sealed chamber (Preload::gas_volume_mm3): its gas in this state.  Empty otherwise.
  std::optional<ChamberGas> gas;
};

// Equilibrium at indenter force F [N] in the given stage (the solver picks the configuration).
Equilibrium solve_at_force(const Problem& problem, double force_n, Stage stage,
                           const SolverOptions& options = {});
// Equilibrium at indentation depth [mm] in the given stage.
Equilibrium solve_at_depth(const Problem& problem, double depth_mm, Stage stage,
                           const SolverOptions& options = {});

}  // namespace puncture
