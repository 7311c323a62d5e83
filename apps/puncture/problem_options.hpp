#pragma once
// The physical flags shared by every subcommand: membrane, indenter, material, contact and
// failure.  Defaults are the library's (the paper's lubricated silicone membrane).
#include <CLI/CLI.hpp>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "puncture/inflation.hpp"
#include "puncture/problem.hpp"

namespace puncture::cli {

// Whether the flag (e.g. "--critical-i1") was given on the command line or in the config.
bool given(const CLI::App& app, const char* flag);

struct ProblemFlags {
  Problem defaults;
  double clamp_radius_mm = defaults.geometry.clamp_radius_mm;
  std::string indenter = "flat";
  double indenter_radius_mm = radius_mm(defaults.indenter);
  double fillet_radius_mm = 0.0;  // the flat punch's corner fillet (0: sharp)
  // The ball's and the cone's dimensions have no default: empty until given (a flag, or a key of
  // a `fit curve` manifest), required with their shape and refused with another.
  std::optional<double> ball_radius_mm;
  std::optional<double> cone_half_angle_deg;
  std::optional<double> tip_radius_mm;
  double thickness_mm = defaults.geometry.thickness_mm;
  double prestretch = defaults.preload.prestretch;
  double pressure_mpa = defaults.preload.pressure_mpa;
  std::string inflated_state = "first";  // first, last or k >= 1
  double gas_volume_mm3 = 0.0;           // read only when --gas-volume is given
  double atmospheric_pressure_mpa = defaults.preload.atmospheric_pressure_mpa;
  double shear_modulus_mpa = defaults.material.shear_modulus_mpa;
  std::string material = "gent";
  std::string material_preset;  // a named published material (material_presets.hpp), or empty
  double j_lim = Gent{}.j_lim;
  double mr_alpha = MooneyRivlin{}.alpha;
  std::vector<double> yeoh_mpa;      // C10, C20, C30 [MPa]
  std::vector<double> ogden_mu_mpa;  // mu_p [MPa]
  std::vector<double> ogden_alpha;   // alpha_p [dimensionless]
  double chain_segments = ArrudaBoyce{}.n;
  double chain_stretch = ArrudaBoyce{}.chain_stretch();
  double gent_gent_beta = GentGent{}.beta;
  double friction = defaults.friction;
  double critical_i1 = defaults.critical_i1;
  std::vector<std::string> criteria;  // --criterion NAME:VALUE items (criterion_spec.hpp)
  std::string stick = "none";
  std::string part_two_equation = "ring-balance";
  CLI::Option* material_option = nullptr;
  CLI::Option* material_preset_option = nullptr;
  std::string test = "none";  // a standard test's probe and opening (standard_test.hpp)
  CLI::Option* clamp_radius_option = nullptr;
  CLI::Option* indenter_option = nullptr;
  CLI::Option* indenter_radius_option = nullptr;
  CLI::Option* fillet_radius_option = nullptr;
  CLI::Option* j_lim_option = nullptr;
  CLI::Option* mr_alpha_option = nullptr;
  CLI::Option* shear_modulus_option = nullptr;
  CLI::Option* yeoh_option = nullptr;
  CLI::Option* ogden_mu_option = nullptr;
  CLI::Option* ogden_alpha_option = nullptr;
  CLI::Option* chain_segments_option = nullptr;
  CLI::Option* chain_stretch_option = nullptr;
  CLI::Option* gent_gent_beta_option = nullptr;
  CLI::Option* prestretch_option = nullptr;
  CLI::Option* pressure_option = nullptr;
  CLI::Option* inflated_state_option = nullptr;
  CLI::Option* gas_volume_option = nullptr;
  CLI::Option* atmospheric_pressure_option = nullptr;
  CLI::Option* critical_i1_option = nullptr;
};

// Registers the flags on `app` (with units and allowed values in their help).
void add_problem_options(CLI::App& app, ProblemFlags& flags);

// The probe shapes --indenter takes.
inline constexpr std::array<const char*, 4> kIndenterShapes{
    "flat", "sphere-tipped", "ball", "cone"};
bool is_indenter_shape(const std::string& name);

// The problem the flags describe.  Throws InputError listing every invalid parameter, each
// prefixed with its flag, using the library's validation_errors().
Problem make_problem(const ProblemFlags& flags);

// The problem the flags describe for a calibration of `unknown`: its flag is not checked.
Problem make_problem(const ProblemFlags& flags, Unknown unknown);

// The membrane the flags describe, for `inflate` (no indenter: the indenter and contact flags
// are not read; the indentation's --pressure is refused: `inflate --pressure` is its own flag).
// Throws InputError like make_problem.
InflationProblem make_inflation_problem(const ProblemFlags& flags);

// The strain-energy law the material flags describe (--material and the law's flags).  Throws
// InputError for a flag that does not apply to the law; its parameters' ranges are the
// library's to check.
MaterialLaw make_law(const ProblemFlags& flags);

}  // namespace puncture::cli
