#include "parameter_flags.hpp"

#include <fmt/format.h>

#include <array>
#include <string_view>
#include <utility>

#include "cli_error.hpp"

namespace puncture::cli {

namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 39> kFlagOfParameter{{
    {"geometry.clamp_radius_mm", "--clamp-radius"},
    {"indenter.radius_mm", "--indenter-radius"},
    {"indenter.fillet_radius_mm", "--fillet-radius"},
    {"indenter.ball_radius_mm", "--ball-radius"},
    {"indenter.half_angle_deg", "--cone-half-angle"},
    {"indenter.tip_radius_mm", "--tip-radius"},
    {"geometry.thickness_mm", "--thickness"},
    {"preload.prestretch", "--prestretch"},
    {"preload.pressure_mpa", "--pressure"},
    {"preload.inflated_state", "--inflated-state"},
    {"preload.gas_volume_mm3", "--gas-volume"},
    {"preload.atmospheric_pressure_mpa", "--atmospheric-pressure"},
    {"clamp_radius_mm", "--clamp-radius"},
    {"thickness_mm", "--thickness"},
    {"prestretch", "--prestretch"},
    {"material.shear_modulus_mpa", "--shear-modulus"},
    {"material.law.j_lim", "--jlim"},
    {"material.law.alpha", "--mr-alpha"},
    {"material.law.c2", "--yeoh"},
    {"material.law.c3", "--yeoh"},
    {"material.law.mu", "--ogden-mu"},  // material.law.alpha of Ogden: problem_options.cpp
    {"material.law.n", "--chain-segments"},
    {"material.law.beta", "--i2-share"},
    {"friction", "--friction"},
    {"critical_i1", "--critical-i1"},
    {"criteria", "--criterion"},
    {"stick.threshold", "--stick"},
    {"stick.rule", "--stick"},
    {"indenter", "--indenter"},
    {"pole_stretch", "--pole-stretch"},
    {"max_pole_stretch", "--max-pole-stretch"},
    {"pressure_mpa", "--pressure"},
    {"points", "--points"},
    {"scan_points", "--scan-points"},
    {"force_n", "--force"},
    {"depth_mm", "--depth"},
    {"material.law", "--material"},
    {"puncture_force_n", "--puncture-force"},
    {"hole.ratio", "--hole-ratio"},
}};

}  // namespace

std::string with_flag(const ValidationError& error) {
  for (const auto& [parameter, flag] : kFlagOfParameter)
    if (parameter == error.parameter) return fmt::format("{}: {}", flag, error.message);
  return error.message;
}

void throw_if_invalid(const char* heading, std::vector<std::string> errors,
                      const std::vector<ValidationError>& validation) {
  for (const auto& e : validation) errors.push_back(with_flag(e));
  if (errors.empty()) return;
  std::string all = heading;
  for (const auto& e : errors) all += "\n  " + e;
  throw InputError(all);
}

void rethrow_with_flags(const InvalidInput& e) {
  const auto& errors = e.errors();
  if (errors.size() == 1) throw InputError(with_flag(errors.front()));
  throw_if_invalid("invalid input:", {}, errors);
  throw InputError(e.what());
}

}  // namespace puncture::cli
