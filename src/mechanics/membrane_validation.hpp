#pragma once
// The checks of the parameters that the indentation and the inflation problems share (the
// membrane, its material and the failure criterion), in the words of validation_errors(Problem):
// the CLI and the Python bindings map each message to their flag or attribute by these words.
#include <string>
#include <vector>

#include "puncture/material.hpp"

namespace puncture::detail {

// "<name> must be a finite number > 0 <unit>, got <value>" unless value is finite and > 0.
void require_positive(std::vector<std::string>& errors, const char* name, double value,
                      const char* unit);

// The shear modulus and the law's own parameter (Gent's J_lim, Mooney-Rivlin's alpha).
void append_material_errors(std::vector<std::string>& errors, const Material& material);

// The critical I1: finite, > 3 and below the law's locking limit.
void append_critical_i1_errors(std::vector<std::string>& errors, double critical_i1,
                               const MaterialLaw& law);

// Throws std::invalid_argument: `heading` (e.g. "invalid problem:"), then each error on its own
// indented line; nothing when there is none.
void throw_if_invalid(const char* heading, const std::vector<std::string>& errors);

}  // namespace puncture::detail
