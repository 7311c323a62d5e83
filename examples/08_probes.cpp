// Probes of one radius (2 mm) on the paper's membrane, without friction: where each punctures,
// at which force and depth, and the work it takes (ASTM F1306's energy to perforation).  Then the
// standard's own test: its 3.2 mm hemispherical probe over its 34.9 mm opening.
#include <fmt/format.h>

#include <string>
#include <utility>
#include <vector>

#include "puncture/loading_curve.hpp"

namespace {

void print_puncture(const std::string& name, const puncture::Problem& problem) {
  puncture::SolverOptions options;
  options.energy_to_puncture = true;  // the area under the force-depth curve
  const auto p = puncture::predict_puncture(problem, options);
  if (!p.ok()) {
    fmt::print("{:<26} no puncture: {}\n", name, p.message);
    return;
  }
  fmt::print("{:<26} F = {:.4f} N at {:6.2f} mm, {:7.4f} mJ, crack: {}\n",
             name,
             p.force_n,
             p.depth_mm,
             p.energy_to_puncture_mj.value_or(0.0),
             p.crack_location);
}

}  // namespace

int main() {
  using namespace puncture;
  const std::vector<std::pair<std::string, Indenter>> probes{
      {"flat, sharp corner", FlatPunch{2.0}},
      {"flat, 0.5 mm fillet", FlatPunch{2.0, 0.5}},
      {"sphere-tipped", SphereTipped{2.0}},
      {"cone 30 deg, 0.2 mm tip", Cone{2.0, 30.0, 0.2}},
  };
  for (const auto& [name, indenter] : probes) {
    Problem problem;  // the paper's silicone membrane: A = 25 mm, H = 0.2 mm, Gent, I1c = 95.2
    problem.indenter = indenter;
    problem.friction = 0.0;
    print_puncture(name, problem);
  }

  // ASTM F1306: tip radius 1.6 mm, opening radius 17.45 mm; the membrane stays the paper's.
  Problem astm;
  astm.indenter = SphereTipped{1.6};
  astm.geometry.clamp_radius_mm = 17.45;
  astm.friction = 0.0;
  print_puncture("ASTM F1306 (frictionless)", astm);
}
