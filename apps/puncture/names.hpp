#pragma once
// Machine-friendly names of library enums, used in CSV and JSON.
#include <string>

#include "puncture/equilibrium.hpp"
#include "puncture/material.hpp"

namespace puncture::cli {

// "unloaded", "stick", "slip_without_part_two", "slip_with_part_two".
std::string configuration_token(Configuration configuration);

// "gent", "neo-hookean", "mooney-rivlin".
std::string material_token(const MaterialLaw& law);

}  // namespace puncture::cli
