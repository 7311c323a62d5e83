// The parameters a force-depth fit can determine: their names, units, places in a Problem and
// default bounds.
#include <fmt/format.h>

#include <array>
#include <utility>

#include "puncture/curve_fit.hpp"

namespace puncture {

namespace {

constexpr std::array<std::pair<CurveParameter, std::string_view>, 6> kTokens{{
    {CurveParameter::ShearModulus, "shear-modulus"},
    {CurveParameter::JLim, "jlim"},
    {CurveParameter::Friction, "friction"},
    {CurveParameter::CriticalI1, "critical-i1"},
    {CurveParameter::StickThreshold, "stick-threshold"},
    {CurveParameter::ContactOffset, "contact-offset"},
}};

bool has_threshold(StickRule rule) {
  return rule == StickRule::Force || rule == StickRule::Depth || rule == StickRule::EdgeTension;
}

}  // namespace

std::string to_token(CurveParameter parameter) {
  for (const auto& [p, token] : kTokens)
    if (p == parameter) return std::string(token);
  return "?";
}

std::optional<CurveParameter> curve_parameter_from_token(std::string_view token) {
  for (const auto& [p, name] : kTokens)
    if (name == token) return p;
  return std::nullopt;
}

std::string curve_parameter_tokens() {
  std::string out;
  for (const auto& [p, token] : kTokens) out += (out.empty() ? "" : ", ") + std::string(token);
  return out;
}

std::string unit_of(CurveParameter parameter, const Problem& problem) {
  switch (parameter) {
    case CurveParameter::ShearModulus:
      return "MPa";
    case CurveParameter::ContactOffset:
      return "mm";
    case CurveParameter::StickThreshold:
      switch (problem.stick.rule) {
        case StickRule::Force:
          return "N";
        case StickRule::Depth:
          return "mm";
        case StickRule::EdgeTension:
          return "N/mm";
        default:
          return "";
      }
    default:
      return "";
  }
}

double value_of(CurveParameter parameter, const Problem& problem) {
  switch (parameter) {
    case CurveParameter::ShearModulus:
      return problem.material.shear_modulus_mpa;
    case CurveParameter::JLim:
      if (const auto* gent = std::get_if<Gent>(&problem.material.law)) return gent->j_lim;
      throw InvalidInput("free",
                         fmt::format("jlim is free but the material law is {}, not gent",
                                     law_name(problem.material.law)));
    case CurveParameter::Friction:
      return problem.friction;
    case CurveParameter::CriticalI1:
      return problem.critical_i1;
    case CurveParameter::StickThreshold:
      if (has_threshold(problem.stick.rule)) return problem.stick.threshold;
      throw InvalidInput("free",
                         fmt::format("stick-threshold is free but the stick rule '{}' has no "
                                     "threshold (use force, depth or edge-tension)",
                                     to_string(problem.stick.rule)));
    case CurveParameter::ContactOffset:
      throw InvalidInput("free",
                         "contact-offset belongs to a test's record (CurveTest::"
                         "contact_offset_mm), not to its Problem");
  }
  return 0.0;
}

void set_value(CurveParameter parameter, Problem& problem, double value) {
  value_of(parameter, problem);  // throws when the problem has no such parameter
  switch (parameter) {
    case CurveParameter::ShearModulus:
      problem.material.shear_modulus_mpa = value;
      break;
    case CurveParameter::JLim:
      std::get<Gent>(problem.material.law).j_lim = value;
      break;
    case CurveParameter::Friction:
      problem.friction = value;
      break;
    case CurveParameter::CriticalI1:
      problem.critical_i1 = value;
      break;
    case CurveParameter::StickThreshold:
      problem.stick.threshold = value;
      break;
    case CurveParameter::ContactOffset:
      break;  // value_of threw
  }
}

ParameterBounds default_bounds(CurveParameter parameter, const Problem& problem) {
  switch (parameter) {
    case CurveParameter::ShearModulus:
      return {parameter, 1e-6, 1e3};
    case CurveParameter::JLim:
      // J_lim must exceed critical I1 - 3 (the membrane punctures before it locks).
      return {parameter, (problem.critical_i1 - 3.0) * (1.0 + 1e-9), 1e6};
    case CurveParameter::Friction:
      return {parameter, 0.0, 10.0};
    case CurveParameter::CriticalI1:
      return {parameter, 3.0 + 1e-9, 1e4};
    case CurveParameter::StickThreshold:
      return {parameter, 1e-12, 1e6};
    case CurveParameter::ContactOffset:
      return {parameter, -1e3, 1e3};
  }
  return {parameter, 0.0, 0.0};
}

std::string to_string(RobustLoss loss) {
  switch (loss) {
    case RobustLoss::None:
      return "none";
    case RobustLoss::Huber:
      return "huber";
    case RobustLoss::Cauchy:
      return "cauchy";
  }
  return "none";
}

}  // namespace puncture
