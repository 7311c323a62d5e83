#pragma once
// The rigid probe pushed into the membrane's centre.  A shape is a struct here and an
// alternative of Indenter, with its contact model in src/indentation/contact/
// (docs/architecture.md).
#include <string>
#include <variant>

namespace puncture {

// The paper's sharp flat-ended cylinder: Part III under the flat tip, Part II on the side.
struct FlatPunch {
  double radius_mm = 2.0;  // cylinder radius a [mm]
};

using Indenter = std::variant<FlatPunch>;

// The probe's radius a [mm] (the cylinder's, for the flat punch).
double radius_mm(const Indenter& indenter);
// Name and dimensions, e.g. "flat punch, radius 2 mm".
std::string describe(const Indenter& indenter);

}  // namespace puncture
