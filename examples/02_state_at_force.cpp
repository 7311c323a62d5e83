// One equilibrium at a prescribed force, and a look along the membrane's fields.
#include <fmt/format.h>

#include "puncture/equilibrium.hpp"

int main() {
  puncture::Problem problem;
  problem.indenter = puncture::FlatPunch{3.0};
  const auto e = puncture::solve_at_force(problem, 0.8, puncture::Stage::Slip);  // 0.8 N
  if (!e.ok()) {
    fmt::print("{}: {}\n", puncture::to_string(e.status), e.message);
    return 1;
  }
  fmt::print("configuration: {}\n", puncture::to_string(e.configuration));
  fmt::print("depth {:.3f} mm, Part III stretch {:.3f}, Part II length {:.3f} mm\n",
             e.depth_mm,
             e.part_three_stretch,
             e.part_two_length_mm);
  const auto& m = e.fields;
  for (std::size_t i = 0; i < m.size(); i += m.size() / 8)
    fmt::print("  part {}  R = {:7.3f} mm  r = {:7.3f} mm  z = {:7.3f} mm  I1 = {:6.2f}\n",
               static_cast<int>(m.part[i]),
               m.reference_radius_mm[i],
               m.radius_mm[i],
               m.deflection_mm[i],
               m.first_invariant[i]);
}
