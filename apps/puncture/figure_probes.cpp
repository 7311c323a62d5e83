// `puncture figures`' probe comparison (figure_probes.hpp).  Without friction: the shapes alone
// compared, each followed to puncture.
#include "figure_probes.hpp"

#include <array>
#include <cmath>

#include "puncture/loading_curve.hpp"

namespace puncture::cli {

namespace {

using json = nlohmann::ordered_json;

constexpr double kRadiusMm = 2.0;  // every probe's radius (the cone's shank)
constexpr double kFilletMm = 0.5;  // the rounded flat punch's corner
constexpr double kConeHalfAngleDeg = 30.0;
constexpr double kConeTipMm = 0.2;  // punctures at the pole before the contact reaches the shank
constexpr double kShankMm = 6.0;    // how much of the shank the outline shows

struct ProbeCase {
  const char* key;
  Indenter indenter;
};

json number_or_null(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

// The probe's meridian from its tip up its shank, to kShankMm above the shank's start [mm].
json outline_json(const Indenter& indenter) {
  json r = json::array(), z = json::array();
  for (const auto& p : outline(indenter)) {
    r.push_back(p.r_mm);
    z.push_back(p.height_mm);
  }
  r.push_back(r.back());
  z.push_back(z.back().get<double>() + kShankMm);
  return {{"r_mm", r}, {"z_mm", z}};
}

}  // namespace

nlohmann::ordered_json probes_figure(const Problem& base, int points) {
  const std::array<ProbeCase, 4> cases{{
      {"flat", FlatPunch{kRadiusMm}},
      {"rounded", FlatPunch{kRadiusMm, kFilletMm}},
      {"sphere-tipped", SphereTipped{kRadiusMm}},
      {"cone", Cone{kRadiusMm, kConeHalfAngleDeg, kConeTipMm}},
  }};
  json probes = json::array();
  for (const auto& c : cases) {
    Problem p = base;
    p.indenter = c.indenter;
    p.friction = 0.0;
    p.stick = {};
    CurveOptions options;
    options.points = points;
    SolverOptions solver;
    solver.energy_to_puncture = true;
    const auto curve = loading_curve(p, options, solver);
    json depth = json::array(), force = json::array();
    for (const auto& q : curve.points) {
      depth.push_back(number_or_null(q.depth_mm));
      force.push_back(number_or_null(q.force_n));
    }
    json probe = {{"key", c.key},
                  {"description", describe(c.indenter)},
                  {"outline", outline_json(c.indenter)},
                  {"depth_mm", depth},
                  {"force_n", force}};
    if (!curve.ok())
      probe["failure"] = {{"status", to_string(curve.status)},
                          {"failure_kind", to_token(failure_kind(curve.status))},
                          {"message", curve.message}};
    if (curve.ok() && curve.puncture.ok())
      probe["puncture"] = {{"depth_mm", number_or_null(curve.puncture.depth_mm)},
                           {"force_n", number_or_null(curve.puncture.force_n)},
                           {"energy_mj",
                            curve.puncture.energy_to_puncture_mj
                                ? number_or_null(*curve.puncture.energy_to_puncture_mj)
                                : json(nullptr)},
                           {"crack_location", curve.puncture.crack_location}};
    else
      probe["puncture"] = nullptr;
    probes.push_back(probe);
  }
  return {{"indenter_radius_mm", kRadiusMm}, {"friction", 0.0}, {"probes", probes}};
}

}  // namespace puncture::cli
