#pragma once
// Named materials from published fits, each with its source (docs/materials.md cites them and
// says how their numbers were converted).  A preset is a Material: the law and its parameters.
//   for (const auto& p : material_presets()) fmt::print("{}: {}\n", p.name, p.source);
//   problem.material = material_preset("ogden-1972-treloar").material;
#include <string>
#include <vector>

#include "puncture/material.hpp"

namespace puncture {

struct MaterialPreset {
  std::string name;         // how --material-preset and Python name it
  std::string description;  // the rubber and the fit, one line
  std::string source;       // the publication, and where in it the numbers are
  Material material;
};

// Every preset, in a fixed order.
const std::vector<MaterialPreset>& material_presets();
// The preset of that name; throws InvalidInput ("preset") naming the presets for another.
const MaterialPreset& material_preset(const std::string& name);

}  // namespace puncture
