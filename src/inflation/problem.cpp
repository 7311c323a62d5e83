// The inflation problem: validation, scales and the membrane of an indentation problem.
#include <fmt/format.h>

#include <cmath>

#include "mechanics/membrane_validation.hpp"
#include "puncture/inflation.hpp"

namespace puncture {

InflationProblem inflation_problem(const Problem& problem) {
  return {problem.geometry.clamp_radius_mm,
          problem.geometry.thickness_mm,
          problem.material,
          problem.critical_i1,
          problem.preload.prestretch};
}

// The checks and words of validation_errors(const Problem&) (membrane_validation.hpp).
std::vector<ValidationError> validation_errors(const InflationProblem& p) {
  std::vector<ValidationError> errors;
  detail::require_positive(errors, "clamp_radius_mm", "clamp radius", p.clamp_radius_mm, "mm");
  detail::require_positive(errors, "thickness_mm", "thickness", p.thickness_mm, "mm");
  detail::append_material_errors(errors, p.material);
  detail::append_critical_i1_errors(errors, p.critical_i1, p.material.law);
  detail::append_prestretch_errors(errors, "prestretch", p.prestretch, p.critical_i1);
  return errors;
}

void validate(const InflationProblem& problem) {
  detail::throw_if_invalid("invalid inflation problem:", validation_errors(problem));
}

double pressure_scale_mpa(const InflationProblem& p) {
  return p.material.shear_modulus_mpa * p.thickness_mm / p.clamp_radius_mm;
}

std::string to_string(ExtremumKind kind) {
  return kind == ExtremumKind::Maximum ? "maximum" : "minimum";
}

}  // namespace puncture
