#pragma once
// The rigid probe pushed into the membrane's centre.  A shape is a struct here and an
// alternative of Indenter, with its contact model in src/indentation/contact/
// (docs/architecture.md).
#include <string>
#include <variant>

namespace puncture {

// The paper's flat-ended cylinder: Part III under the flat tip, Part II on the side.  Its corner
// is sharp, or rounded by a toroidal fillet of radius rho < a: then the flat face ends at a - rho
// and the membrane lies on the fillet, sliding (docs/model.md §19).
struct FlatPunch {
  double radius_mm = 2.0;         // cylinder radius a [mm]
  double fillet_radius_mm = 0.0;  // corner fillet radius rho [mm] (0: the sharp corner)
};

// A cylinder of radius a ending in a hemisphere of the same radius (the ASTM F1306 probe has
// a = 1.6 mm): the membrane lies on the hemisphere from the pole to the contact edge and leaves it
// tangentially.  Sliding only; with friction only while the contact stays on the hemisphere, for
// now (docs/model.md, §15).
struct SphereTipped {
  double radius_mm = 2.0;  // hemisphere and cylinder radius a [mm]
};

using Indenter = std::variant<FlatPunch, SphereTipped>;

// The probe's radius a [mm] (the cylinder's, for the flat punch; the hemisphere's and the
// cylinder's, for the sphere-tipped probe).
double radius_mm(const Indenter& indenter);
// Name and dimensions, e.g. "flat punch, radius 2 mm", "sphere-tipped probe, radius 1.6 mm",
// "flat punch, radius 2 mm, corner fillet radius 0.5 mm".
std::string describe(const Indenter& indenter);
// Whether it is the flat punch with a sharp corner (fillet radius 0), the probe of the finite
// elements, verify(), the friction calibration and the energy-release criterion.
bool sharp_flat_punch(const Indenter& indenter);

}  // namespace puncture
