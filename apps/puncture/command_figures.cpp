// `puncture figures`: data of the paper's analytical figures, drawn by python/puncture.
//   Fig. 11      uniaxial nominal stress against stretch of the material (Gent in the paper)
//   Fig. 12(a)   I1 along the radius near the tip, several friction coefficients, F/2piGHA = 1,
//                indenter radius 0.08 A
//   Fig. 12(b)   Part III stretch against friction for a = 0.04, 0.08, 0.12 A, F/2piGHA = 1
//   Fig. 13(a-e) loading curves to puncture: a = 1-4 mm lubricated (mu' = 0.18), 1 mm dry (1.95)
//   Fig. 14      the balloons: a = 1 mm on the membrane inflated by a gas pressure held
//                constant (--pressure, else 3e-4 MPa: the paper gives none), lubricated vs dry
//   probes       flat (sharp and rounded), sphere-tipped and cone probes of one radius, without
//                friction (figure_probes.hpp); not in the paper
// Figs. 12 and 13 are computed with the ring-balance Part II equation and with the paper's
// printed Eq. 18.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <system_error>

#include "cli_error.hpp"
#include "figure_probes.hpp"
#include "figures.hpp"
#include "plot.hpp"
#include "progress.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "puncture/material.hpp"

namespace puncture::cli {

namespace {

using json = nlohmann::ordered_json;

constexpr std::array kEquations{PartTwoEquation::RingBalance, PartTwoEquation::PaperEq18};
constexpr std::array kFig12aFriction{0.0, 0.18, 0.5, 1.0, 1.95};
constexpr std::array kFig12bRadiusRatio{0.04, 0.08, 0.12};
constexpr double kFig12RadiusRatio = 0.08;
constexpr double kFig12NormalizedForce = 1.0;
constexpr double kFig12bMaxFriction = 2.5;
constexpr int kFig12bSteps =
    250;  // fine enough that the bends where Part II vanishes are drawn, not cut

struct Fig13Panel {
  const char* label;
  double indenter_radius_mm;
  double friction;
};
constexpr std::array<Fig13Panel, 5> kFig13{{
    {"a", 1.0, 0.18},
    {"b", 2.0, 0.18},
    {"c", 3.0, 0.18},
    {"d", 4.0, 0.18},
    {"e", 1.0, 1.95},
}};

// Fig. 14's balloons: "two inflated balloons with the same air pressure are punctured by the
// cylindrical steel indenter with radius of 1 mm", lubricated and dry.  The paper gives neither
// the pressure nor the balloon: the flags' membrane, inflated by --pressure or else by 3e-4 MPa
// (the paper's membrane: pole stretch 1.118, dome 10.4 mm above the clamp).
constexpr double kFig14IndenterRadiusMm = 1.0;
constexpr double kFig14DefaultPressureMpa = 3e-4;
constexpr std::array kFig14Friction{0.18, 1.95};

// A number, or null when it is not finite (a failed or unbounded quantity).
json json_number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json figure_inputs_json(const Problem& p) {
  json material = {{"law", law_name(p.material.law)},
                   {"shear_modulus_mpa", p.material.shear_modulus_mpa}};
  if (const auto* gent = std::get_if<Gent>(&p.material.law)) material["j_lim"] = gent->j_lim;
  if (const auto* mr = std::get_if<MooneyRivlin>(&p.material.law)) material["alpha"] = mr->alpha;
  return {{"clamp_radius_mm", p.geometry.clamp_radius_mm},
          {"thickness_mm", p.geometry.thickness_mm},
          {"material", material},
          {"material_description", describe(p.material)},
          {"critical_i1", p.critical_i1},
          {"stick", to_string(p.stick.rule)},
          {"force_scale_n", force_scale_n(p)}};
}

// The stretch at which uniaxial tension locks the law (I1 = max I1), or `cap` if it never does.
double uniaxial_locking_stretch(const MaterialLaw& law, double cap) {
  const double i1_max = locking_first_invariant(law);
  auto i1 = [](double l) { return l * l + 2.0 / l; };
  if (!std::isfinite(i1_max) || i1(cap) < i1_max) return cap;
  double lo = 1.0, hi = cap;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (i1(mid) < i1_max ? lo : hi) = mid;
  }
  return lo;
}

json fig11(const Problem& base) {
  constexpr int kPoints = 400;
  constexpr double kCap = 12.0;
  const double top = uniaxial_locking_stretch(base.material.law, kCap);
  const double g = base.material.shear_modulus_mpa;
  json stretch = json::array(), stress = json::array(), neo = json::array();
  for (int k = 0; k <= kPoints; ++k) {
    // denser towards the locking stretch, where the stress rises steeply
    const double t = static_cast<double>(k) / kPoints;
    const double l = 1.0 + (top - 1.0) * std::min(1.0 - (1.0 - t) * (1.0 - t), 0.9999);
    stretch.push_back(l);
    stress.push_back(json_number(g * uniaxial_stress(base.material.law, l)));
    neo.push_back(json_number(g * uniaxial_stress(NeoHookean{}, l)));
  }
  return {{"material", describe(base.material)},
          {"shear_modulus_mpa", g},
          {"locking_stretch", json_number(top < kCap ? top : NAN)},
          {"stretch", stretch},
          {"stress_mpa", stress},
          {"neo_hookean_stress_mpa", neo}};
}

json failure(Status status, const std::string& message) {
  return {{"status", to_string(status)},
          {"failure_kind", to_token(failure_kind(status))},
          {"message", message}};
}

json fig12a(const Problem& base) {
  json cases = json::array();
  Problem p = base;
  p.indenter = FlatPunch{kFig12RadiusRatio * base.geometry.clamp_radius_mm};
  const double force = kFig12NormalizedForce * force_scale_n(p);
  for (const auto equation : kEquations)
    for (const double mu : kFig12aFriction) {
      p.friction = mu;
      p.part_two_equation = equation;
      json c = {{"friction", mu}, {"part_two_equation", to_string(equation)}};
      const auto e = solve_at_force(p, force, Stage::Slip);
      if (!e.ok()) {
        c["failure"] = failure(e.status, e.message);
      } else {
        json r = json::array(), i1 = json::array(), part = json::array();
        for (std::size_t i = 0; i < e.fields.size(); ++i) {
          r.push_back(e.fields.reference_radius_mm[i]);
          i1.push_back(json_number(e.fields.first_invariant[i]));
          part.push_back(e.fields.part[i]);
        }
        c["configuration"] = to_token(e.configuration);
        c["part_three_stretch"] = json_number(e.part_three_stretch);
        c["corner_reference_radius_mm"] = e.corner_reference_radius_mm;
        c["max_i1"] = json_number(e.max_first_invariant);
        c["R_mm"] = r;
        c["I1"] = i1;
        c["part"] = part;
      }
      cases.push_back(c);
    }
  return {{"normalized_force", kFig12NormalizedForce},
          {"indenter_radius_mm", radius_mm(p.indenter)},
          {"cases", cases}};
}

json fig12b(const Problem& base) {
  json series = json::array();
  SolverOptions options;
  options.record_fields = false;
  for (const auto equation : kEquations)
    for (const double ratio : kFig12bRadiusRatio) {
      Problem p = base;
      p.indenter = FlatPunch{ratio * base.geometry.clamp_radius_mm};
      p.part_two_equation = equation;
      const double force = kFig12NormalizedForce * force_scale_n(p);
      json friction = json::array(), stretch = json::array(), configuration = json::array();
      for (int k = 0; k <= kFig12bSteps; ++k) {
        p.friction = kFig12bMaxFriction * k / kFig12bSteps;
        const auto e = solve_at_force(p, force, Stage::Slip, options);
        friction.push_back(p.friction);
        stretch.push_back(e.ok() ? json_number(e.part_three_stretch) : json(nullptr));
        configuration.push_back(e.ok() ? to_token(e.configuration) : "failed");
      }
      series.push_back({{"indenter_radius_mm", radius_mm(p.indenter)},
                        {"radius_ratio", ratio},
                        {"part_two_equation", to_string(equation)},
                        {"friction", friction},
                        {"part_three_stretch", stretch},
                        {"configuration", configuration}});
    }
  return {{"normalized_force", kFig12NormalizedForce}, {"series", series}};
}

json figure_curve_json(const Problem& p, int points) {
  CurveOptions options;
  options.points = points;
  const auto c = loading_curve(p, options);
  json out = {{"part_two_equation", to_string(p.part_two_equation)}};
  if (!c.ok()) {
    out["failure"] = failure(c.status, c.message);
    return out;
  }
  json depth = json::array(), force = json::array(), configuration = json::array();
  for (const auto& q : c.points) {
    depth.push_back(json_number(q.depth_mm));
    force.push_back(json_number(q.force_n));
    configuration.push_back(to_token(q.configuration));
  }
  out["depth_mm"] = depth;
  out["force_n"] = force;
  out["configuration"] = configuration;
  // Under a gas pressure with friction: the points before it are not the membrane's states.
  if (c.face_slides_outward_from_mm)
    out["face_slides_outward_from_mm"] = json_number(*c.face_slides_outward_from_mm);
  if (c.puncture.ok())
    out["puncture"] = {{"depth_mm", json_number(c.puncture.depth_mm)},
                       {"force_n", json_number(c.puncture.force_n)},
                       {"part_three_stretch", json_number(c.puncture.part_three_stretch)},
                       {"crack_location", c.puncture.crack_location}};
  else
    out["puncture"] = nullptr;
  return out;
}

json fig13(const Problem& base, int points) {
  json panels = json::array();
  for (const auto& panel : kFig13) {
    Problem p = base;
    p.indenter = FlatPunch{panel.indenter_radius_mm};
    p.friction = panel.friction;
    json curves = json::array();
    for (const auto equation : kEquations) {
      p.part_two_equation = equation;
      curves.push_back(figure_curve_json(p, points));
    }
    panels.push_back({{"label", panel.label},
                      {"indenter_radius_mm", panel.indenter_radius_mm},
                      {"friction", panel.friction},
                      {"curves", curves}});
  }
  return {{"panels", panels}};
}

json fig14(const Problem& base, int points) {
  Problem p = base;
  p.indenter = FlatPunch{kFig14IndenterRadiusMm};
  p.stick = {};  // sliding, as the seed's Fig. 14 balloons (lubricated or dry)
  p.part_two_equation = PartTwoEquation::RingBalance;
  const bool assumed = !(base.preload.pressure_mpa > 0.0);
  if (assumed) p.preload.pressure_mpa = kFig14DefaultPressureMpa;
  json curves = json::array();
  for (const double mu : kFig14Friction) {
    p.friction = mu;
    json c = figure_curve_json(p, points);
    c["friction"] = mu;
    curves.push_back(c);
  }
  return {{"indenter_radius_mm", kFig14IndenterRadiusMm},
          {"pressure_mpa", p.preload.pressure_mpa},
          {"pressure_assumed", assumed},
          {"prestretch", p.preload.prestretch},
          {"curves", curves}};
}

}  // namespace

void add_figures_options(CLI::App& figures, FiguresFlags& f) {
  figures.add_option("--out", f.out_dir, "Directory for the figures (created if missing)")
      ->required()
      ->type_name("DIR");
}

std::string figures_json(const Problem& base, const CurveFlags& curve) {
  Progress progress("figures");
  json out = {{"inputs", figure_inputs_json(base)}};
  progress.note("Fig. 11");
  out["fig11"] = fig11(base);
  progress.note("Fig. 12(a)");
  out["fig12a"] = fig12a(base);
  progress.note("Fig. 12(b)");
  out["fig12b"] = fig12b(base);
  progress.note("Fig. 13");
  out["fig13"] = fig13(base, curve.points);
  progress.note("Fig. 14");
  out["fig14"] = fig14(base, curve.points);
  progress.note("probes");
  out["probes"] = probes_figure(base, curve.points);
  return out.dump(1) + "\n";
}

std::string run_figures(const Problem& base, const CurveFlags& curve, const FiguresFlags& f) {
  check_plot_tools();
  std::error_code ec;
  std::filesystem::create_directories(f.out_dir, ec);
  if (ec || !std::filesystem::is_directory(f.out_dir))
    throw InputError(fmt::format("--out: cannot create the directory '{}': {}",
                                 f.out_dir,
                                 ec ? ec.message() : "not a directory"));
  const auto data = figures_json(base, curve);
  const auto data_path = (std::filesystem::path(f.out_dir) / "figures-data.json").string();
  {
    std::ofstream out(data_path, std::ios::binary);
    out << data;
    out.close();
    if (!out) throw InputError(fmt::format("--out: cannot write '{}'", data_path));
  }
  run_plot_script("figures", data, f.out_dir);
  return fmt::format("figure data: {}\n", data_path);
}

}  // namespace puncture::cli
