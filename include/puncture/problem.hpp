#pragma once
// What a user specifies: the membrane, the indenter, the contact and the failure criterion.
// Inputs are in mm, N and MPa; defaults are the paper's lubricated silicone membrane.
#include <optional>
#include <string>
#include <vector>

#include "puncture/failure_criteria.hpp"
#include "puncture/indenter.hpp"
#include "puncture/material.hpp"
#include "puncture/outcome.hpp"

namespace puncture {

// The membrane's dimensions.
struct Geometry {
  double clamp_radius_mm = 25.0;  // inner radius of the clamping rings, A [mm]
  double thickness_mm = 0.2;      // undeformed membrane thickness, H [mm]
};

// Preload::inflated_state: the last of the inflated states at the pressure.
inline constexpr int kLastInflatedState = -1;

// How the membrane is loaded before the indenter touches it.
struct Preload {
  // Equibiaxial pre-stretch L0 (>= 1): the stress-free disc of radius A / L0 is stretched by L0
  // and clamped at radius A, then indented (1: mounted stress-free, the paper's case).  Stretches
  // and I1 are measured from the stress-free disc, reference radii on it.
  double prestretch = 1.0;
  // Gas pressure p under the membrane [MPa] (>= 0), held constant: the clamped membrane is first
  // inflated by p (the first inflated state, reached by inflating slowly from flat), then
  // indented at its pole from the convex side.  Depths are measured from the inflated pole.
  double pressure_mpa = 0.0;
  // Which inflated state at pressure_mpa is indented where the membrane has several (a Gent
  // membrane between the pressure's minimum and its limit point: the curve rises again past its
  // limit point, docs/model.md §17): 1, the first, reached by inflating slowly from flat
  // (default); k >= 1 the k-th in order of pole stretch; kLastInflatedState the last, the
  // stiffest.  Other than 1 it needs pressure_mpa > 0 and no gas_volume_mm3, and k may not
  // exceed the number of states (validation_errors solves the inflation to count them).
  int inflated_state = 1;
  // A sealed chamber instead (docs/model.md §17.1): the volume V0 of gas under the flat membrane
  // [mm^3] (> 0), closed at the inflated state of pressure_mpa, so that the amount of gas is
  // fixed and its pressure follows the enclosed volume (isothermal ideal gas).  Empty: the
  // pressure is held constant.
  std::optional<double> gas_volume_mm3;
  // The atmosphere above the membrane [MPa] (> 0): pressure_mpa and the chamber's pressure are
  // gauge pressures, the gas law holds for the absolute ones.  Read with gas_volume_mm3 only.
  double atmospheric_pressure_mpa = 0.101325;
};

// When the membrane, held at the indenter's edge at first, starts to slide over it.  Coulomb
// friction alone cannot hold an unstretched membrane under the tip (docs/model.md, "Stick and
// slip"), so any stick stage needs a criterion the paper does not give; each rule is one.
enum class StickRule {
  None,         // Coulomb friction only: the membrane slides from the first touch (default)
  Force,        // held until the indenter force reaches `threshold` [N]
  Depth,        // held until the indentation depth reaches `threshold` [mm]
  EdgeTension,  // held by adhesion until the radial line tension at the edge reaches
                // `threshold` [N/mm], the adhesive strength of the edge (pre-stretched: the
                // tension beyond the pre-tension, which the membrane under the tip carries)
  Always,       // never slides (fully stuck, the infinite-friction limit)
  Coulomb,      // curved probes: held while every held point's tangential traction is within
                // `friction` times its contact pressure (docs/model.md §15.4); no threshold
};

struct StickCriterion {
  StickRule rule = StickRule::None;
  double threshold = 0.0;  // unit set by the rule: N, mm or N/mm
};

// Which Part II equilibrium equation to use (docs/model.md, "Part II").
enum class PartTwoEquation {
  RingBalance,  // d(R s1)/dR = mu s2: vertical balance of a whole ring (default, consistent)
  PaperEq18,    // ds1/dR = mu lambda2 s2 / a, as printed in the paper, for comparison
};

struct Problem {
  Geometry geometry;
  Preload preload;
  Indenter indenter = FlatPunch{2.0};  // the paper's 2 mm flat punch
  Material material;
  double friction = 0.18;     // Coulomb coefficient mu' (0.18 lubricated, 1.95 dry)
  double critical_i1 = 95.2;  // I1 at which the membrane punctures (inflation test, §2.3)
  // The failure criteria (failure_criteria.hpp): empty, the critical I1 above alone; otherwise
  // these, and the membrane punctures where the first of them is met (critical_i1 is unused).
  std::vector<FailureCriterion> criteria;
  StickCriterion stick;  // stick -> slip switch rule
  PartTwoEquation part_two_equation = PartTwoEquation::RingBalance;
};

// Every problem with the input, each with the attribute it is about and a message naming the
// parameter and its allowed range; empty if valid.
std::vector<ValidationError> validation_errors(const Problem& problem);
// Throws InvalidInput listing every problem.
void validate(const Problem& problem);

// A parameter a calibration determines: the problem's own value of it is ignored.
enum class Unknown { Friction, JLim };
// The errors of every other parameter: as validation_errors(problem) with the unknown at a
// value the rest allows (friction 0; J_lim = 2 (I1c - 3), as any J_lim > I1c - 3 would do).
std::vector<ValidationError> validation_errors(const Problem& problem, Unknown unknown);

// Force scale 2 pi G H A [N]: the paper's normalised force is F / force_scale.
double force_scale_n(const Problem& problem);
// The radius of the stress-free disc that is clamped, A / L0 [mm] (A without pre-stretch):
// reference radii lie in [0, A / L0].
double reference_clamp_radius_mm(const Problem& problem);

std::string to_string(StickRule rule);
// The stick rule in words, e.g. "force:0.3 (held until the force reaches 0.3 N)".
std::string describe(const StickCriterion& stick);
std::string to_string(PartTwoEquation equation);

}  // namespace puncture
