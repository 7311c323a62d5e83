// The inflation (bulge) test: the membrane clamped on a 30 mm radius, inflated to its burst.
#include <fmt/format.h>

#include <cmath>

#include "puncture/inflation.hpp"

int main() {
  puncture::InflationProblem problem;  // the paper's Gent rubber, critical I1 = 95.2
  problem.clamp_radius_mm = 30.0;      // the paper's inflation tests (§2.3)
  const auto curve = puncture::inflation_curve(problem);  // from flat to the burst
  if (!curve.ok()) {
    fmt::print("{}: {}\n", puncture::to_string(curve.status), curve.message);
    return 1;
  }
  for (const auto& e : curve.extrema)  // the pressure is not monotone in the stretch
    fmt::print("pressure {}: {:.4f} kPa at pole stretch {:.4f}, pole height {:.2f} mm\n",
               puncture::to_string(e.kind),
               e.state.pressure_mpa * 1e3,
               e.state.pole_stretch,
               e.state.pole_height_mm);
  const auto& burst = curve.burst.state;  // where the largest I1 reaches the critical I1
  fmt::print("burst at {:.4f} kPa, pole stretch {:.4f}, largest I1 at R = {:.2f} mm\n",
             burst.pressure_mpa * 1e3,
             burst.pole_stretch,
             burst.max_first_invariant_reference_radius_mm);
  // Check: at the pole the stretch is equibiaxial, I1 = 2 l^2 + l^-4; solved for l (x = l^2).
  double x = problem.critical_i1 / 2.0;
  for (int i = 0; i < 20; ++i) x = (problem.critical_i1 - 1.0 / (x * x)) / 2.0;
  fmt::print("pole stretch where 2 l^2 + l^-4 = {}: {:.4f}\n", problem.critical_i1, std::sqrt(x));
}
