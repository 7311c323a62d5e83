// Flat punches much smaller than the clamp (a/A ~ 0.004): the wrapped membrane's top at the
// clamp would need a hoop stretch a/A so small that the material locks there, so the top-stretch
// bracket starts above it.  Checked against the finite elements, which know nothing of brackets.
#include <gtest/gtest.h>

#include <cmath>

#include "puncture/finite_element.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

// A membrane of the reliability sweep (case 250 of seed 20261123) that used to fail with "the
// force is beyond what the membrane can carry before the material locks" (paper-eq18) and "where
// the solutions end" (ring-balance) while I1 was far below the critical value.
Problem small_probe(PartTwoEquation equation) {
  Problem p;
  p.geometry.clamp_radius_mm = 18.082547537558224;
  p.indenter = FlatPunch{0.07020407110835516};
  p.geometry.thickness_mm = 0.07074516817332478;
  p.material.shear_modulus_mpa = 0.010790893249742558;
  p.material.law = Gent{422.634};
  p.friction = 0.0;
  p.critical_i1 = 38.75682371969951;
  p.stick.rule = StickRule::None;
  p.part_two_equation = equation;
  return p;
}

TEST(SmallFlatProbe, PunctureIsFoundWithEitherPartTwoEquation) {
  for (const auto equation : {PartTwoEquation::RingBalance, PartTwoEquation::PaperEq18}) {
    const PuncturePrediction at = predict_puncture(small_probe(equation));
    ASSERT_TRUE(at.ok()) << at.message;
    EXPECT_EQ(at.state.configuration, Configuration::SlipWithPartTwo);
    EXPECT_NEAR(at.state.max_first_invariant / 38.75682371969951, 1.0, 1e-8);
  }
}

// Frictionless, so the finite elements apply: the force at the puncture depth agrees to 1e-4
// relative (measured 2.3e-5; 128 quadratic elements, whose own error, against 64, is ~9e-5 here).
TEST(SmallFlatProbe, PunctureForceMatchesFiniteElements) {
  const Problem p = small_probe(PartTwoEquation::RingBalance);
  const PuncturePrediction at = predict_puncture(p);
  ASSERT_TRUE(at.ok()) << at.message;
  FeOptions fine;
  fine.elements = 128;
  const FeState fe = fe_solve_at_depth(p, at.depth_mm, FeContact::Frictionless, fine);
  ASSERT_TRUE(fe.ok()) << fe.message;
  EXPECT_TRUE(fe.part_two);
  EXPECT_NEAR(fe.force_n / at.force_n, 1.0, 1e-4);
  record("small_flat_probe_fe_force_relative_difference", fe.force_n / at.force_n - 1.0);
}

}  // namespace
}  // namespace puncture::test
