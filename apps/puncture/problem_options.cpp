#include "problem_options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli_error.hpp"
#include "criterion_spec.hpp"
#include "parameter_flags.hpp"
#include "puncture/material_presets.hpp"
#include "standard_test.hpp"
#include "stick_spec.hpp"

namespace puncture::cli {

namespace {

constexpr const char* kGeometry = "Geometry";
constexpr const char* kMaterial = "Material";
constexpr const char* kContact = "Contact and failure";

bool given(const CLI::Option* o) { return o && o->count() > 0; }

// Ogden from --ogden-mu [MPa] and --ogden-alpha: G = sum mu_p alpha_p / 2 (so --shear-modulus
// is refused); the terms' own conditions are the library's.
Material ogden_of(const ProblemFlags& f, std::vector<std::string>& errors) {
  Material m;
  if (!given(f.ogden_mu_option) || !given(f.ogden_alpha_option)) {
    errors.push_back(
        "--ogden-mu, --ogden-alpha: --material ogden needs both lists, mu_1,...,mu_N [MPa] and "
        "alpha_1,...,alpha_N, N = 1 to 3");
    return m;
  }
  if (given(f.shear_modulus_option))
    errors.push_back(
        "--shear-modulus: with --ogden-mu the shear modulus is G = sum mu_p alpha_p / 2; do not "
        "give it too");
  try {
    m = ogden_material(f.ogden_mu_mpa, f.ogden_alpha);
  } catch (const InvalidInput& e) {
    for (const auto& error : e.errors())
      errors.push_back(fmt::format(
          "{}: {}", error.parameter == "alpha" ? "--ogden-alpha" : "--ogden-mu", error.message));
  }
  return m;
}

// Arruda-Boyce from --chain-segments N or --chain-stretch sqrt(N), one of them.
ArrudaBoyce arruda_boyce_of(const ProblemFlags& f, std::vector<std::string>& errors) {
  if (given(f.chain_segments_option) == given(f.chain_stretch_option)) {
    errors.push_back(
        "--chain-segments, --chain-stretch: --material arruda-boyce needs one of them, N or the "
        "chain locking stretch sqrt(N)");
    return {};
  }
  if (!given(f.chain_stretch_option)) return ArrudaBoyce{f.chain_segments};
  const double l = f.chain_stretch;
  if (!std::isfinite(l) || !(l > 1.0))
    errors.push_back(fmt::format(
        "--chain-stretch: the chain locking stretch must be a finite number > 1, got {}", l));
  return ArrudaBoyce{l * l};
}

// A preset's material: it sets the law and every parameter, so a material flag given as well
// contradicts it.
Material preset_of(const ProblemFlags& f, std::vector<std::string>& errors) {
  for (const auto* option : {f.material_option,
                             f.shear_modulus_option,
                             f.j_lim_option,
                             f.mr_alpha_option,
                             f.yeoh_option,
                             f.ogden_mu_option,
                             f.ogden_alpha_option,
                             f.chain_segments_option,
                             f.chain_stretch_option,
                             f.gent_gent_beta_option})
    if (given(option))
      errors.push_back(fmt::format(
          "--material-preset, {}: the preset {} sets the law and its parameters; give one of "
          "them, not both",
          option->get_name(),
          f.material_preset));
  try {
    return material_preset(f.material_preset).material;
  } catch (const InvalidInput& e) {
    errors.push_back("--material-preset: " + e.errors().front().message);
    return {};
  }
}

// The material the flags describe: a preset, or --shear-modulus and the law's flags, or
// --yeoh's C10, C20, C30 (G = 2 C10), or Ogden's lists.
Material material_of(const ProblemFlags& f, std::vector<std::string>& errors) {
  if (given(f.material_preset_option)) return preset_of(f, errors);
  if (f.material != "gent" && f.material != "gent-gent" && given(f.j_lim_option))
    errors.push_back(
        fmt::format("--jlim: applies only to --material gent and gent-gent, not {}", f.material));
  if (f.material != "mooney-rivlin" && given(f.mr_alpha_option))
    errors.push_back(
        fmt::format("--mr-alpha: applies only to --material mooney-rivlin, not {}", f.material));
  if (f.material != "yeoh" && given(f.yeoh_option))
    errors.push_back(fmt::format("--yeoh: applies only to --material yeoh, not {}", f.material));
  for (const auto& [option, flag] : {std::pair{f.ogden_mu_option, "--ogden-mu"},
                                     std::pair{f.ogden_alpha_option, "--ogden-alpha"}})
    if (f.material != "ogden" && given(option))
      errors.push_back(
          fmt::format("{}: applies only to --material ogden, not {}", flag, f.material));
  for (const auto& [option, flag] : {std::pair{f.chain_segments_option, "--chain-segments"},
                                     std::pair{f.chain_stretch_option, "--chain-stretch"}})
    if (f.material != "arruda-boyce" && given(option))
      errors.push_back(
          fmt::format("{}: applies only to --material arruda-boyce, not {}", flag, f.material));
  if (f.material != "gent-gent" && given(f.gent_gent_beta_option))
    errors.push_back(
        fmt::format("--i2-share: applies only to --material gent-gent, not {}", f.material));
  Material m;
  m.shear_modulus_mpa = f.shear_modulus_mpa;
  if (f.material == "ogden") return ogden_of(f, errors);
  if (f.material == "arruda-boyce") {
    m.law = arruda_boyce_of(f, errors);
  } else if (f.material == "gent-gent") {
    m.law = GentGent{f.j_lim, f.gent_gent_beta};
  } else if (f.material == "neo-hookean") {
    m.law = NeoHookean{};
  } else if (f.material == "mooney-rivlin") {
    m.law = MooneyRivlin{f.mr_alpha};
  } else if (f.material == "yeoh") {
    if (!given(f.yeoh_option) || f.yeoh_mpa.size() != 3) {
      errors.push_back(
          fmt::format("--yeoh: --material yeoh needs its three coefficients C10,C20,C30 [MPa], "
                      "got {}",
                      given(f.yeoh_option) ? std::to_string(f.yeoh_mpa.size()) + " values"
                                           : std::string("none")));
      return m;
    }
    if (given(f.shear_modulus_option))
      errors.push_back(
          "--shear-modulus: with --yeoh the shear modulus is G = 2 C10; do not give "
          "it too");
    const double c10 = f.yeoh_mpa[0];
    if (!std::isfinite(c10) || c10 <= 0.0) {
      errors.push_back(
          fmt::format("--yeoh: C10 must be a finite number > 0 MPa (G = 2 C10), got {}", c10));
      return m;
    }
    m.shear_modulus_mpa = 2.0 * c10;
    m.law = Yeoh{f.yeoh_mpa[1] / m.shear_modulus_mpa, f.yeoh_mpa[2] / m.shear_modulus_mpa};
  } else {
    m.law = Gent{f.j_lim};
  }
  return m;
}

}  // namespace

void add_problem_options(CLI::App& app, ProblemFlags& f) {
  f.clamp_radius_option =
      app.add_option(
             "--clamp-radius", f.clamp_radius_mm, "Inner radius A of the clamping rings [mm] (> 0)")
          ->group(kGeometry)
          ->capture_default_str();
  app.add_option("--test",
                 f.test,
                 "A standard test's probe and opening, the membrane from the other\n"
                 "flags: none, or astm-f1306 (ASTM F1306, puncture of flexible barrier\n"
                 "films: sphere-tipped probe of tip radius 1.6 mm (3.2 mm diameter),\n"
                 "opening radius 17.45 mm; 'puncture' and 'curve' add the standard's\n"
                 "outputs: maximum force [N], probe penetration to perforation [mm],\n"
                 "energy to perforation [mJ]).  Not with --indenter,\n"
                 "--indenter-radius or --clamp-radius")
      ->group(kGeometry)
      ->check(CLI::IsMember(std::vector<std::string>{"none", kAstmF1306}))
      ->capture_default_str();
  f.indenter_option =
      app.add_option("--indenter",
                     f.indenter,
                     "Probe shape: flat (the paper's flat-ended cylinder, its corner\n"
                     "sharp or rounded by --fillet-radius),\n"
                     "sphere-tipped (a cylinder ending in a hemisphere of the same radius;\n"
                     "held (--stick; not over --gas-volume) or sliding, with Coulomb slip on\n"
                     "the hemisphere and the cylinder side), ball (a sphere of radius\n"
                     "--ball-radius on a rod of radius --indenter-radius; solved up to the\n"
                     "ball's equator) or\n"
                     "cone (half-angle --cone-half-angle, spherical tip of radius\n"
                     "--tip-radius tangent to it, shank of radius --indenter-radius;\n"
                     "solved until the contact reaches the shank).  All of them held\n"
                     "(--stick; not over --gas-volume) or sliding")
          ->group(kGeometry)
          ->check(CLI::IsMember(
              std::vector<std::string>(kIndenterShapes.begin(), kIndenterShapes.end())))
          ->capture_default_str();
  f.indenter_radius_option =
      app.add_option("--indenter-radius",
                     f.indenter_radius_mm,
                     "Radius a of the indenter's cylinder (and of the sphere-tipped\n"
                     "probe's hemisphere; the ball's rod; the cone's shank) [mm] (> 0 and\n"
                     "smaller than the clamp radius)")
          ->group(kGeometry)
          ->capture_default_str();
  f.fillet_radius_option =
      app.add_option("--fillet-radius",
                     f.fillet_radius_mm,
                     "Radius rho of the flat punch's rounded corner (a toroidal fillet\n"
                     "between the flat face, of radius a - rho, and the cylinder) [mm]\n"
                     "(>= 0 and smaller than --indenter-radius; 0: the paper's sharp\n"
                     "corner)")
          ->group(kGeometry)
          ->capture_default_str();
  app.add_option("--ball-radius",
                 f.ball_radius_mm,
                 "Radius RB of the ball, with --indenter ball [mm] (larger than the\n"
                 "rod's --indenter-radius, smaller than the clamp radius)")
      ->group(kGeometry);
  app.add_option("--cone-half-angle",
                 f.cone_half_angle_deg,
                 "Half-angle of the cone from its axis, with --indenter cone [degrees]\n"
                 "(in (0, 90))")
      ->group(kGeometry);
  app.add_option("--tip-radius",
                 f.tip_radius_mm,
                 "Radius RT of the cone's spherical tip, with --indenter cone [mm] (> 0:\n"
                 "a sharp cone makes the stretch at its apex unbounded at a finite\n"
                 "force; RT cos(half-angle) <= --indenter-radius)")
      ->group(kGeometry);
  app.add_option("--thickness", f.thickness_mm, "Undeformed membrane thickness H [mm] (> 0)")
      ->group(kGeometry)
      ->capture_default_str();
  f.prestretch_option =
      app.add_option("--prestretch",
                     f.prestretch,
                     "Equibiaxial pre-stretch L0 [dimensionless] (>= 1): the stress-free\n"
                     "disc of radius A / L0 is stretched by L0 and clamped at radius A\n"
                     "before indentation (or inflation); H is its stress-free thickness,\n"
                     "stretches and I1 count from it (1: mounted stress-free, the paper's\n"
                     "case)")
          ->group(kGeometry)
          ->capture_default_str();
  f.pressure_option =
      app.add_option("--pressure",
                     f.pressure_mpa,
                     "Gas pressure p under the membrane [MPa] (>= 0), held constant: the\n"
                     "membrane is inflated by p first (its first inflated state, or the\n"
                     "one --inflated-state chooses), then\n"
                     "indented at its pole from the convex side; depths are measured from\n"
                     "the inflated pole; a held membrane (--stick) is held from the\n"
                     "inflated pole on.  (After 'inflate',\n"
                     "--pressure is that command's own: the states at p.)")
          ->group(kGeometry)
          ->capture_default_str();
  f.inflated_state_option =
      app.add_option("--inflated-state",
                     f.inflated_state,
                     "Which inflated state at --pressure is indented where the membrane has\n"
                     "several (a Gent membrane past its limit point stiffens again):\n"
                     "'first' (reached by inflating slowly from flat), 'last' (the\n"
                     "stiffest) or k >= 1, the k-th in order of pole stretch ('puncture\n"
                     "inflate --pressure P' lists them).  The first is indented also\n"
                     "beyond a hemisphere (overhanging its clamp); a later one that\n"
                     "overhangs is followed in depth from its own dome, and where its\n"
                     "path turns back (a fold: the unstable middle state) the curve\n"
                     "snaps through onto the first state (docs/model.md 8.1)")
          ->group(kGeometry)
          ->capture_default_str();
  f.gas_volume_option =
      app.add_option("--gas-volume",
                     f.gas_volume_mm3,
                     "Seal the gas instead of holding its pressure: V0, the chamber's volume\n"
                     "under the flat membrane [mm^3] (> 0).  The chamber is closed at the\n"
                     "inflated state of --pressure (gauge; 0: closed flat), and the\n"
                     "isothermal ideal gas keeps (p + p_atm)(V0 + V) fixed, V the volume\n"
                     "between the membrane and its clamp plane: indenting compresses it.\n"
                     "Depths from the sealed dome's pole; outputs report p and V.  Also a\n"
                     "dome beyond a hemisphere, up to the inflation limit point (a gas\n"
                     "compressed past it: exit 2), with friction (the energy to puncture\n"
                     "along the path) and in 'verify' (closed at --pressure > 0); a stick\n"
                     "stage (--stick) and 'inflate' are refused")
          ->group(kGeometry);
  f.atmospheric_pressure_option =
      app.add_option("--atmospheric-pressure",
                     f.atmospheric_pressure_mpa,
                     "Atmospheric pressure p_atm above the membrane [MPa] (> 0), with\n"
                     "--gas-volume only: --pressure and the chamber's pressure are gauge,\n"
                     "the gas law holds for the absolute p + p_atm")
          ->group(kGeometry)
          ->capture_default_str();

  f.shear_modulus_option = app.add_option("--shear-modulus",
                                          f.shear_modulus_mpa,
                                          "Initial shear modulus G of the rubber [MPa] (> 0)")
                               ->group(kMaterial)
                               ->capture_default_str();
  f.material_option =
      app.add_option("--material",
                     f.material,
                     "Strain-energy law: gent (the paper's, locks at I1 = 3 + J_lim),\n"
                     "neo-hookean, mooney-rivlin (with --mr-alpha), yeoh (with\n"
                     "--yeoh), ogden (with --ogden-mu, --ogden-alpha), arruda-boyce\n"
                     "(with --chain-segments or --chain-stretch; locks at I1 = 3 N)\n"
                     "or gent-gent (Gent plus a ln(I2/3) term: --jlim, --i2-share)")
          ->group(kMaterial)
          ->check(CLI::IsMember({"gent",
                                 "neo-hookean",
                                 "mooney-rivlin",
                                 "yeoh",
                                 "ogden",
                                 "arruda-boyce",
                                 "gent-gent"}))
          ->capture_default_str();
  std::string presets =
      "A published material: law and parameters at once (no other\n"
      "material flag; sources in docs/materials.md):";
  for (const auto& preset : material_presets())
    presets += fmt::format("\n  {}: {}", preset.name, preset.description);
  f.material_preset_option = app.add_option("--material-preset", f.material_preset, presets)
                                 ->group(kMaterial)
                                 ->type_name("NAME");
  f.j_lim_option = app.add_option("--jlim",
                                  f.j_lim,
                                  "Gent locking parameter J_lim: the largest I1 - 3\n"
                                  "[dimensionless] (> 0; gent and gent-gent only)")
                       ->group(kMaterial)
                       ->capture_default_str();
  f.mr_alpha_option = app.add_option("--mr-alpha",
                                     f.mr_alpha,
                                     "Mooney-Rivlin share of G in the I2 term, C2 / (C1 + C2)\n"
                                     "[dimensionless] (in [0, 1); mooney-rivlin only)")
                          ->group(kMaterial)
                          ->capture_default_str();
  f.yeoh_option =
      app.add_option("--yeoh",
                     f.yeoh_mpa,
                     "Yeoh coefficients C10,C20,C30 of W = C10 (I1 - 3) + C20 (I1 - 3)^2\n"
                     "+ C30 (I1 - 3)^3 [MPa] (C10 > 0, C20 >= 0, C30 >= 0; sets\n"
                     "G = 2 C10; yeoh only)")
          ->delimiter(',')
          ->group(kMaterial);
  f.ogden_mu_option =
      app.add_option("--ogden-mu",
                     f.ogden_mu_mpa,
                     "Ogden coefficients mu_1,...,mu_N of W = sum mu_p / alpha_p\n"
                     "(l1^alpha_p + l2^alpha_p + l3^alpha_p - 3) [MPa] (N = 1 to 3,\n"
                     "one per --ogden-alpha; each mu_p alpha_p > 0; sets\n"
                     "G = sum mu_p alpha_p / 2, so no --shear-modulus; ogden only)")
          ->delimiter(',')
          ->group(kMaterial);
  f.ogden_alpha_option = app.add_option("--ogden-alpha",
                                        f.ogden_alpha,
                                        "Ogden exponents alpha_1,...,alpha_N [dimensionless]\n"
                                        "(|alpha_p| >= 1; ogden only)")
                             ->delimiter(',')
                             ->group(kMaterial);
  f.chain_segments_option =
      app.add_option("--chain-segments",
                     f.chain_segments,
                     "Arruda-Boyce N, Kuhn segments per chain [dimensionless]\n"
                     "(> 1; the law locks at I1 = 3 N; arruda-boyce only, or\n"
                     "--chain-stretch)")
          ->group(kMaterial);
  f.chain_stretch_option =
      app.add_option("--chain-stretch",
                     f.chain_stretch,
                     "Arruda-Boyce chain locking stretch sqrt(N) [dimensionless]\n"
                     "(> 1; arruda-boyce only, or --chain-segments)")
          ->group(kMaterial);
  f.gent_gent_beta_option =
      app.add_option("--i2-share",
                     f.gent_gent_beta,
                     "Gent-Gent share of G in the ln(I2/3) term, beta = 2 C2 / (3 G)\n"
                     "[dimensionless] (in [0, 1), and small enough that the radial\n"
                     "stress grows with stretch; 0 is Gent; gent-gent only)")
          ->group(kMaterial)
          ->capture_default_str();

  app.add_option("--friction",
                 f.friction,
                 "Coulomb friction coefficient mu' between membrane and indenter\n"
                 "[dimensionless] (>= 0; 0.18 lubricated, 1.95 dry)")
      ->group(kContact)
      ->capture_default_str();
  f.critical_i1_option =
      app.add_option("--critical-i1",
                     f.critical_i1,
                     "First strain invariant I1 at which the membrane punctures\n"
                     "[dimensionless] (> 3; < 3 + J_lim for gent and gent-gent, < 3 N\n"
                     "for arruda-boyce)")
          ->group(kContact)
          ->capture_default_str();
  app.add_option("--criterion",
                 f.criteria,
                 "Failure criteria NAME:VALUE instead of --critical-i1 (repeat the flag\n"
                 "or separate with commas); the membrane punctures where the first of\n"
                 "them is met, each at the place its measure is largest:\n"
                 "  i1:<I1>           first invariant I1 of C [dimensionless] (> 3),\n"
                 "                    the paper's (inflation test)\n"
                 "  max-stretch:<l>   largest principal stretch [dimensionless] (> 1;\n"
                 "                    Nguyen & Vu-Khanh 2004, Deris & Nadler 2015)\n"
                 "  energy-density:<MPa>\n"
                 "                    strain-energy density W per reference volume\n"
                 "                    [MPa = MJ/m^3] (> 0)\n"
                 "  true-stress:<MPa> largest principal Cauchy stress lambda_i s_i\n"
                 "                    [MPa] (> 0)\n"
                 "  energy-release:<N/mm>\n"
                 "                    tearing energy Gamma [N/mm = kJ/m^2] (> 0): cut\n"
                 "                    along the corner's ring when the energy released,\n"
                 "                    at the same depth, reaches Gamma 2 pi R_c H\n"
                 "                    (Steigmann 2005; flat punch, --friction 0 only)\n"
                 "Each must be reachable below the law's locking limit.  Default: the\n"
                 "critical I1 of --critical-i1, e.g. --criterion i1:95.2,max-stretch:6")
      ->delimiter(',')
      ->group(kContact);
  app.add_option("--stick",
                 f.stick,
                 "When the membrane, held at the indenter's edge at first, starts to\n"
                 "slide over it.  Coulomb friction alone cannot hold the unstretched\n"
                 "membrane under the tip, so by default ('none') the membrane slides\n"
                 "from the first touch.  Rules:\n"
                 "  none          Coulomb friction only: slides from the first touch\n"
                 "  force:<N>     held until the indenter force reaches <N> [N]\n"
                 "  depth:<mm>    held until the indentation depth reaches <mm> [mm]\n"
                 "  edge-tension:<N/mm>\n"
                 "                held by adhesion until the radial line tension at\n"
                 "                the indenter's edge reaches <N/mm> [N/mm] (with\n"
                 "                --prestretch: beyond the pre-tension)\n"
                 "  always        never slides (fully stuck)\n"
                 "  coulomb       curved probes: held where it touched while\n"
                 "                --friction times the contact pressure holds every\n"
                 "                held point (tangential traction [MPa] <= mu p);\n"
                 "                then a slip zone spreads from the contact's edge\n"
                 "                to the pole (partial slip), then it all slides\n"
                 "On the curved probes (sphere-tipped, ball, cone, a filleted flat\n"
                 "punch) each material point is held where it touched the probe.\n"
                 "Under --pressure every probe is held from the inflated dome; over\n"
                 "a sealed chamber (--gas-volume) only 'none' is solved.\n"
                 "Thresholds must be > 0, e.g. --stick force:0.5")
      ->group(kContact)
      ->capture_default_str();
  app.add_option("--part-two-equation",
                 f.part_two_equation,
                 "Equilibrium of Part II (membrane on the indenter's side):\n"
                 "ring-balance (vertical balance of a ring, consistent) or\n"
                 "paper-eq18 (the paper's Eq. 18 as printed, for comparison)")
      ->group(kContact)
      ->check(CLI::IsMember({"ring-balance", "paper-eq18"}))
      ->capture_default_str();
}

namespace {

// The ball's and the cone's dimensions: required with their shape, refused with another.
void append_probe_shape_flag_errors(const ProblemFlags& f, std::vector<std::string>& errors) {
  struct ShapeDimension {
    const std::optional<double>& value;
    const char* flag;
    const char* shape;
  };
  const std::array<ShapeDimension, 3> dimensions{
      {{f.ball_radius_mm, "--ball-radius", "ball"},
       {f.cone_half_angle_deg, "--cone-half-angle", "cone"},
       {f.tip_radius_mm, "--tip-radius", "cone"}}};
  for (const auto& [value, flag, shape] : dimensions) {
    if (f.indenter == shape && !value)
      errors.push_back(fmt::format(
          "{}: required with --indenter {} (no default: give the probe's dimension)", flag, shape));
    else if (f.indenter != shape && value)
      errors.push_back(
          fmt::format("{}: applies only to --indenter {}, not {}", flag, shape, f.indenter));
  }
}

Problem problem_of(const ProblemFlags& f, std::vector<std::string>& errors) {
  Problem p;
  p.geometry.clamp_radius_mm = f.clamp_radius_mm;
  if (f.indenter == "sphere-tipped")
    p.indenter = SphereTipped{f.indenter_radius_mm};
  else if (f.indenter == "ball")
    p.indenter = Ball{f.indenter_radius_mm, f.ball_radius_mm.value_or(0.0)};
  else if (f.indenter == "cone")
    p.indenter = Cone{
        f.indenter_radius_mm, f.cone_half_angle_deg.value_or(0.0), f.tip_radius_mm.value_or(0.0)};
  else
    p.indenter = FlatPunch{f.indenter_radius_mm, f.fillet_radius_mm};
  if (f.indenter != "flat" && (given(f.fillet_radius_option) || f.fillet_radius_mm != 0.0))
    errors.push_back(
        "--fillet-radius: applies to the flat punch only (--indenter flat); the other "
        "probes are rounded by their own shape");
  append_probe_shape_flag_errors(f, errors);
  if (f.test == kAstmF1306) {
    // The standard fixes the probe and the opening: a flag that sets them too is a conflict.
    for (const CLI::Option* given : {f.indenter_option,
                                     f.indenter_radius_option,
                                     f.fillet_radius_option,
                                     f.clamp_radius_option})
      if (given && given->count() > 0)
        errors.push_back(fmt::format(
            "{}: conflicts with --test {}, which sets the probe (sphere-tipped, tip radius {} mm) "
            "and the opening (radius {} mm); give one or the other",
            given->get_name(),
            kAstmF1306,
            kAstmF1306TipRadiusMm,
            kAstmF1306OpeningRadiusMm));
    p.indenter = SphereTipped{kAstmF1306TipRadiusMm};
    p.geometry.clamp_radius_mm = kAstmF1306OpeningRadiusMm;
  }
  p.geometry.thickness_mm = f.thickness_mm;
  p.preload.prestretch = f.prestretch;
  p.preload.pressure_mpa = f.pressure_mpa;
  if (f.inflated_state == "first") {
    p.preload.inflated_state = 1;
  } else if (f.inflated_state == "last") {
    p.preload.inflated_state = kLastInflatedState;
  } else {
    int k = 0;
    std::size_t used = 0;
    try {
      k = std::stoi(f.inflated_state, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != f.inflated_state.size() || k < 1)
      errors.push_back(
          fmt::format("--inflated-state: must be 'first', 'last' or a number >= 1, got '{}'",
                      f.inflated_state));
    else
      p.preload.inflated_state = k;
  }
  if (given(f.gas_volume_option)) p.preload.gas_volume_mm3 = f.gas_volume_mm3;
  p.preload.atmospheric_pressure_mpa = f.atmospheric_pressure_mpa;
  if (given(f.atmospheric_pressure_option) && !given(f.gas_volume_option))
    errors.push_back(
        "--atmospheric-pressure: applies to a sealed chamber only; give --gas-volume too");
  p.material = material_of(f, errors);
  p.friction = f.friction;
  p.critical_i1 = f.critical_i1;
  if (!f.criteria.empty()) {
    if (given(f.critical_i1_option))
      errors.push_back(
          "--critical-i1: with --criterion give the critical I1 as --criterion i1:<I1>");
    p.criteria = parse_criteria(f.criteria, errors);
  }
  p.part_two_equation = f.part_two_equation == "paper-eq18" ? PartTwoEquation::PaperEq18
                                                            : PartTwoEquation::RingBalance;
  if (const auto stick = parse_stick(f.stick))
    p.stick = *stick;
  else
    errors.push_back(fmt::format("--stick: expected {}, got '{}'", kStickForms, f.stick));
  return p;
}

}  // namespace

namespace {

// The library names Ogden's exponents and Mooney-Rivlin's share both material.law.alpha: with
// --material ogden its flag is --ogden-alpha (moved to the CLI's own, worded errors).
std::vector<ValidationError> with_law_flags(std::vector<ValidationError> validation,
                                            const ProblemFlags& f,
                                            std::vector<std::string>& errors) {
  if (f.material != "ogden") return validation;
  std::vector<ValidationError> rest;
  for (auto& e : validation)
    if (e.parameter == "material.law.alpha")
      errors.push_back("--ogden-alpha: " + e.message);
    else
      rest.push_back(std::move(e));
  return rest;
}

}  // namespace

bool is_indenter_shape(const std::string& name) {
  return std::find(kIndenterShapes.begin(), kIndenterShapes.end(), name) != kIndenterShapes.end();
}

Problem make_problem(const ProblemFlags& f) {
  std::vector<std::string> errors;
  const Problem p = problem_of(f, errors);
  const auto validation = with_law_flags(validation_errors(p), f, errors);
  throw_if_invalid("invalid input:", errors, validation);
  return p;
}

Problem make_problem(const ProblemFlags& f, Unknown unknown) {
  std::vector<std::string> errors;
  const Problem p = problem_of(f, errors);
  const auto validation = with_law_flags(validation_errors(p, unknown), f, errors);
  throw_if_invalid("invalid input:", errors, validation);
  return p;
}

MaterialLaw make_law(const ProblemFlags& f) {
  std::vector<std::string> errors;
  const MaterialLaw law = material_of(f, errors).law;
  throw_if_invalid("invalid input:", errors, {});
  return law;
}

InflationProblem make_inflation_problem(const ProblemFlags& f) {
  std::vector<std::string> errors;
  InflationProblem p;
  if (f.pressure_option && f.pressure_option->count() > 0)
    errors.push_back(
        "--pressure: before 'inflate' it is the gas pressure of an indentation; the inflation's "
        "states at a pressure are 'inflate --pressure P'");
  for (const CLI::Option* o : {f.gas_volume_option, f.atmospheric_pressure_option})
    if (given(o))
      errors.push_back(o->get_name() +
                       ": the sealed chamber is an indentation's; 'inflate' holds the pressure");
  if (given(f.inflated_state_option))
    errors.push_back(
        "--inflated-state: chooses the inflated state an indentation starts from; 'inflate "
        "--pressure P' lists every state at P");
  p.clamp_radius_mm = f.clamp_radius_mm;
  p.thickness_mm = f.thickness_mm;
  p.material = material_of(f, errors);
  p.critical_i1 = f.critical_i1;
  if (!f.criteria.empty())
    errors.push_back(
        "--criterion: the inflation bursts at --critical-i1; the other criteria apply to "
        "indentation (their critical values from bursts: calibrate critical-i1 --measure)");
  p.prestretch = f.prestretch;
  const auto validation = with_law_flags(validation_errors(p), f, errors);
  throw_if_invalid("invalid input:", errors, validation);
  return p;
}

bool given(const CLI::App& app, const char* flag) {
  const auto* option = app.get_option_no_throw(flag);
  return option && option->count() > 0;
}

}  // namespace puncture::cli
