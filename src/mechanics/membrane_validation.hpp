#pragma once
// The checks of the parameters that the indentation and the inflation problems share (the
// membrane, its material and the failure criterion), with the same words for both.  Each error
// names its attribute: `prefix` is the path of the membrane's dimensions in the problem
// ("geometry." for Problem, "" for InflationProblem).
#include <string>
#include <vector>

#include "puncture/material.hpp"
#include "puncture/outcome.hpp"

namespace puncture::detail {

// "<name> must be a finite number > 0 <unit>, got <value>" unless value is finite and > 0.
void require_positive(std::vector<ValidationError>& errors, std::string parameter, const char* name,
                      double value, const char* unit);

// The shear modulus and the law's own parameter (Gent's J_lim, Mooney-Rivlin's alpha), under
// "material.".
void append_material_errors(std::vector<ValidationError>& errors, const Material& material);

// The critical I1 ("critical_i1"): finite, > 3 and below the law's locking limit.
void append_critical_i1_errors(std::vector<ValidationError>& errors, double critical_i1,
                               const MaterialLaw& law);

// The equibiaxial pre-stretch L0 of the clamped membrane (under `parameter`): finite, >= 1 (a
// compressed membrane wrinkles) and with its mounted I1 below the critical I1.
void append_prestretch_errors(std::vector<ValidationError>& errors, const char* parameter,
                              double prestretch, double critical_i1);

// Throws InvalidInput: `heading` (e.g. "invalid problem:"), then each error on its own indented
// line; nothing when there is none.
void throw_if_invalid(const char* heading, const std::vector<ValidationError>& errors);

}  // namespace puncture::detail
