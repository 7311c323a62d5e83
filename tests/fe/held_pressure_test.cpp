// The elements held where the membrane touched under a held gas pressure
// (src/fe/held_smooth_probe.cpp, docs/model.md §15.3, §17.2) against the shooting's held states at
// that pressure (docs/model.md §17.3, through the public API): from the elements' own inflated
// dome, Pi = U - p V minimised, the force its derivative in the depth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../solver/solver_test_support.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/finite_element.hpp"

namespace puncture {
namespace fe_held_pressure_test {

using test::record;

// The paper's membrane (A = 25 mm, Gent J_lim = 125) inflated to `pressure_mpa`, held from the
// first touch of the dome's pole.
Problem inflated_held_problem(const Indenter& indenter, double pressure_mpa) {
  Problem p;
  p.indenter = indenter;
  p.friction = 0.0;
  p.stick.rule = StickRule::Always;
  p.preload.pressure_mpa = pressure_mpa;
  return p;
}

struct InflatedHeldCase {
  std::string name;
  Indenter indenter;
  double pressure_mpa;
  std::vector<double> depths_mm;  // from the inflated pole, inside the held model's range
  double pole_tolerance;          // the first element's stretch at 64 elements (order 2)
};

std::string inflated_held_name(const ::testing::TestParamInfo<InflatedHeldCase>& info) {
  return info.param.name;
}

// 0.9 kPa inflates the pole to L_d = 1.818 (0.3 kPa: 1.118); the sphere's held history there
// ends at 33.3 mm (no contact edge beyond), the elements' between 33.8 and 35.7 mm (32 to 128).
const std::vector<InflatedHeldCase> kInflatedHeld{
    {"SphereAt0p3kPa", SphereTipped{2.0}, 3e-4, {5.0, 20.0, 40.0}, 1e-3},
    {"SphereAt0p9kPa", SphereTipped{2.0}, 9e-4, {5.0, 20.0}, 6e-3},
    {"FilletAt0p3kPa", FlatPunch{2.0, 0.5}, 3e-4, {5.0, 15.0}, 1e-3},
    {"BallAt0p3kPa", Ball{1.0, 2.0}, 3e-4, {5.0, 15.0}, 1e-3},
    {"ConeAt0p3kPa", Cone{2.0, 30.0, 0.5}, 3e-4, {5.0, 15.0}, 1e-2}};

class FiniteElementHeldUnderPressure : public ::testing::TestWithParam<InflatedHeldCase> {};

// Force, pole stretch, contact edge and non-penetration at 64 elements (32 over the held reach).
// Measured force differences: at most 2.5e-4 (sphere, 0.3 kPa, 40 mm), 1.5e-4 (0.9 kPa), 1.7e-5
// (fillet), 8.2e-5 (ball), 7.5e-6 (cone); asserted 1e-3, the envelope without pressure.  The pole
// keeps the dome's stretch in the shooting; the elements' first element has it to O(h^2)
// (3.3e-4 at 0.3 kPa, 2.9e-3 at 0.9 kPa, 4.9e-3 on the cone's tip: its 0.5 mm sphere spans a
// few elements).  The edge is a node: within about a node's spacing (0.049 mm) of the
// shooting's.
TEST_P(FiniteElementHeldUnderPressure, MatchesTheShootingsHeldStates) {
  const InflatedHeldCase& c = GetParam();
  const Problem p = inflated_held_problem(c.indenter, c.pressure_mpa);
  FeOptions options;
  options.elements = 64;
  const std::vector<FeState> fe = fe_solve_at_depths(p, c.depths_mm, FeContact::Held, options);
  ASSERT_EQ(fe.size(), c.depths_mm.size());
  for (std::size_t k = 0; k < fe.size(); ++k) {
    ASSERT_TRUE(fe[k].ok()) << c.depths_mm[k] << " mm: " << fe[k].message;
    const Equilibrium e = solve_at_depth(p, c.depths_mm[k], Stage::Stick);
    ASSERT_TRUE(e.ok()) << e.message;
    EXPECT_EQ(fe[k].contact, FeContact::Held);
    EXPECT_EQ(fe[k].gas_pressure_mpa, c.pressure_mpa);
    // The probe pushes the membrane down: the enclosed volume falls with the depth.
    if (k > 0) {
      EXPECT_LT(fe[k].volume_mm3, fe[k - 1].volume_mm3) << c.depths_mm[k] << " mm";
    }
    const double force = fe[k].force_n / e.force_n - 1.0;
    record("force_error", force);
    EXPECT_LT(std::abs(force), 1e-3) << c.depths_mm[k] << " mm";
    EXPECT_NEAR(fe[k].part_three_stretch, e.part_three_stretch, c.pole_tolerance)
        << c.depths_mm[k] << " mm";
    EXPECT_NEAR(fe[k].part_two_top_reference_radius_mm, e.part_two_top_reference_radius_mm, 0.06)
        << c.depths_mm[k] << " mm";
    EXPECT_LE(fe[k].largest_penetration_mm, 1e-9) << c.depths_mm[k] << " mm";
  }
}

INSTANTIATE_TEST_SUITE_P(Probes, FiniteElementHeldUnderPressure, ::testing::ValuesIn(kInflatedHeld),
                         inflated_held_name);

// Along one held history at constant pressure the force is dPi/d(depth), Pi = U - p V: the held
// nodes' reaction includes the gas on every element (the held ones move with the probe).  Central
// differences over 1e-4 of the depth within one history (32 elements, sphere, 0.3 kPa, 20 mm):
// asserted 1e-6, the difference's own error (~1e-8) as without pressure.  dU/d(depth) alone
// misses by the gas's work, p dV/d(depth), here more than 10 %.
TEST(FiniteElementHeldUnderPressureHistory, ForceIsTheDerivativeOfUMinusPV) {
  const Problem p = inflated_held_problem(SphereTipped{2.0}, 3e-4);
  FeOptions options;
  options.elements = 32;
  const double depth = 20.0, h = 1e-4 * depth;
  const auto s = fe_solve_at_depths(p, {depth - h, depth, depth + h}, FeContact::Held, options);
  for (const FeState& state : s) ASSERT_TRUE(state.ok()) << state.message;
  auto potential = [&](const FeState& state) {
    return state.stored_energy_nmm - p.preload.pressure_mpa * state.volume_mm3;
  };
  const double derivative = (potential(s[2]) - potential(s[0])) / (2.0 * h);
  record("potential_derivative_ratio", derivative / s[1].force_n - 1.0);
  EXPECT_NEAR(derivative / s[1].force_n, 1.0, 1e-6);
  const double stored_only = (s[2].stored_energy_nmm - s[0].stored_energy_nmm) / (2.0 * h);
  record("stored_energy_derivative_ratio", stored_only / s[1].force_n - 1.0);
  EXPECT_GT(std::abs(stored_only / s[1].force_n - 1.0), 0.1);
}

// The force converges with the mesh under pressure as without (sphere, 0.3 kPa, 5 and 20 mm):
// measured 1.3e-4, 5.5e-5, 1.1e-5 and 2.0e-4, 7.6e-5, 8.0e-6 at 32, 64, 128 elements (orders
// 1.2, 2.3 and 1.4, 3.2: the sawtooth of the edge at a node).  Asserted: the error at 128 below
// 3e-5 and a fifth of the 32 elements' (an overall order above 1.15).
TEST(FiniteElementHeldUnderPressureHistory, ConvergesWithTheMesh) {
  const Problem p = inflated_held_problem(SphereTipped{2.0}, 3e-4);
  const std::vector<double> depths{5.0, 20.0};
  std::vector<double> shooting;
  for (double d : depths) {
    const Equilibrium e = solve_at_depth(p, d, Stage::Stick);
    ASSERT_TRUE(e.ok()) << e.message;
    shooting.push_back(e.force_n);
  }
  std::vector<double> worst;
  for (int elements : {32, 128}) {
    FeOptions options;
    options.elements = elements;
    const auto fe = fe_solve_at_depths(p, depths, FeContact::Held, options);
    double w = 0.0;
    for (std::size_t k = 0; k < depths.size(); ++k) {
      ASSERT_TRUE(fe[k].ok()) << fe[k].message;
      w = std::max(w, std::abs(fe[k].force_n / shooting[k] - 1.0));
    }
    record("worst_force_error_" + std::to_string(elements), w);
    worst.push_back(w);
  }
  EXPECT_LT(worst[1], 3e-5);
  EXPECT_LT(worst[1], worst[0] / 5.0);
}

// The held history starts from the elements' own dome: at a small depth the held state's volume
// is the dome's (fe_inflated_state, another mesh) less what the probe pushed down, and its pole
// stretch the dome's.
TEST(FiniteElementHeldUnderPressureHistory, StartsFromTheElementsDome) {
  const Problem p = inflated_held_problem(SphereTipped{2.0}, 3e-4);
  FeOptions options;
  options.elements = 64;
  const FeState dome = fe_inflated_state(p, options);
  ASSERT_TRUE(dome.ok()) << dome.message;
  const FeState held = fe_solve_at_depth(p, 0.01, FeContact::Held, options);
  ASSERT_TRUE(held.ok()) << held.message;
  record("held_volume_change_mm3", held.volume_mm3 - dome.volume_mm3);
  EXPECT_LT(held.volume_mm3, dome.volume_mm3);
  EXPECT_NEAR(held.volume_mm3 / dome.volume_mm3, 1.0, 1e-3);
  EXPECT_NEAR(held.part_three_stretch, dome.part_three_stretch, 1e-3);
  EXPECT_GT(held.force_n, 0.0);
}

}  // namespace fe_held_pressure_test
}  // namespace puncture
