// The inflation problem: validation, scales and the membrane of an indentation problem.
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "puncture/inflation.hpp"

namespace puncture {

namespace {

void require_positive(std::vector<std::string>& errors, const char* name, double value,
                      const char* unit) {
  if (!std::isfinite(value) || value <= 0.0)
    errors.push_back(fmt::format("{} must be a finite number > 0 {}, got {}", name, unit, value));
}

}  // namespace

InflationProblem inflation_problem(const Problem& problem) {
  return {problem.geometry.clamp_radius_mm,
          problem.geometry.thickness_mm,
          problem.material,
          problem.critical_i1};
}

// Same wording as validation_errors(const Problem&), so that the CLI and the Python bindings
// map each message to their flag or attribute the same way.
std::vector<std::string> validation_errors(const InflationProblem& p) {
  std::vector<std::string> errors;
  require_positive(errors, "clamp radius", p.clamp_radius_mm, "mm");
  require_positive(errors, "thickness", p.thickness_mm, "mm");
  require_positive(errors, "shear modulus", p.material.shear_modulus_mpa, "MPa");
  if (const auto* gent = std::get_if<Gent>(&p.material.law)) {
    if (!std::isfinite(gent->j_lim) || gent->j_lim <= 0.0)
      errors.push_back(fmt::format("J_lim must be a finite number > 0, got {}", gent->j_lim));
  }
  if (const auto* mr = std::get_if<MooneyRivlin>(&p.material.law)) {
    if (!std::isfinite(mr->alpha) || mr->alpha < 0.0 || mr->alpha >= 1.0)
      errors.push_back(
          fmt::format("Mooney-Rivlin alpha = C2/(C1+C2) must be in [0, 1), got {}", mr->alpha));
  }
  const double i1_max = max_first_invariant(p.material.law);
  if (!std::isfinite(p.critical_i1) || p.critical_i1 <= 3.0)
    errors.push_back(fmt::format("critical I1 must be a finite number > 3, got {}", p.critical_i1));
  else if (p.critical_i1 >= i1_max)
    errors.push_back(
        fmt::format("critical I1 must be below the Gent locking limit 3 + J_lim = {:g}, got {:g}",
                    i1_max,
                    p.critical_i1));
  return errors;
}

void validate(const InflationProblem& problem) {
  const auto errors = validation_errors(problem);
  if (errors.empty()) return;
  std::string all = "invalid inflation problem:";
  for (const auto& e : errors) all += "\n  " + e;
  throw std::invalid_argument(all);
}

double pressure_scale_mpa(const InflationProblem& p) {
  return p.material.shear_modulus_mpa * p.thickness_mm / p.clamp_radius_mm;
}

std::string to_string(ExtremumKind kind) {
  return kind == ExtremumKind::Maximum ? "maximum" : "minimum";
}

}  // namespace puncture
