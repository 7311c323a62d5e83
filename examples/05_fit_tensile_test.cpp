// Calibration from your own data: G and J_lim from a tensile test (CSV of displacement and force),
// then the puncture of a membrane of that rubber.
// Usage: 05_fit_tensile_test [test.csv]  (default: the test in examples/data)
#include <fmt/format.h>

#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "puncture/calibration.hpp"

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : PUNCTURE_EXAMPLE_DATA "/tensile_test.csv";
  const puncture::SpecimenGeometry strip{10.0, 0.2, 20.0};  // width, thickness, gauge [mm]
  std::vector<puncture::UniaxialPoint> data;                // stretch and nominal stress [MPa]
  try {  // columns displacement_mm,force_n or stretch,nominal_stress_mpa ('#' comments allowed)
    const auto table = puncture::read_numeric_csv(path, 3);
    const bool forces = table.has("force_n");  // forces need the strip's dimensions
    data =
        puncture::uniaxial_points_from_table(table, forces ? std::optional{strip} : std::nullopt);
  } catch (const std::exception& e) {  // CsvError names the file, line and column
    fmt::print(stderr, "{}\n", e.what());
    return 1;
  }

  const auto fit = puncture::fit_uniaxial(data, puncture::FitLaw::Gent);
  if (!fit.ok() || !fit.material) {
    fmt::print("{}: {}\n", puncture::to_string(fit.status), fit.message);
    return 1;
  }
  for (const auto& q : fit.parameters)  // G [MPa], then J_lim with its standard error
    fmt::print("{:5} = {:.4g} +- {:.2g}{}{}\n",
               q.name,
               q.value.value_or(0.0),
               q.standard_error.value_or(0.0),
               q.unit.empty() ? "" : " " + q.unit,
               q.identifiable ? "" : "  (not determined by these data)");
  fmt::print("rms residual {:.2g} MPa over {} points\n", fit.rms_residual_mpa, fit.points);

  puncture::Problem problem;  // the paper's membrane and 2 mm indenter, with the fitted rubber
  problem.material = *fit.material;
  const auto p = puncture::predict_puncture(problem);
  if (!p.ok()) {
    fmt::print("no puncture: {}\n", p.message);
    return 1;
  }
  fmt::print("puncture at F = {:.4f} N, depth {:.2f} mm\n", p.force_n, p.depth_mm);
}
