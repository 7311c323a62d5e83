// Friction from the hole ratio: Part III stretches made by the solver with a known friction must
// give it back, by both methods; noisy ratios must move the estimate the right way and stay in
// the interval; ratios out of the model's reach must be reported as such.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "calibration_test_support.hpp"
#include "puncture/calibration.hpp"
#include "seeded_noise.hpp"

namespace puncture {
namespace {

using test::dry_small_indenter;
using test::kRecoveryTol;
using test::quiet;

// The paper's dry test: 1 mm indenter, mu' = 1.95 (§4.2).

double stretch_at_force(Problem p, double mu, double force) {
  p.friction = mu;
  const auto e = solve_at_force(p, force, Stage::Slip, quiet());
  EXPECT_TRUE(e.ok()) << e.message;
  return e.part_three_stretch;
}

// Each model evaluation is converged to ~1e-10 (shooting and integration tolerances) and the
// root is bracketed to 1e-8 in mu', so 1e-6 leaves two orders of margin.

TEST(FrictionFromHole, RecoversFrictionAtTheMeasuredForce) {
  for (const auto& [indenter, mu, force] :
       {std::tuple{1.0, 1.95, 1.5}, std::tuple{2.0, 0.18, 0.5}, std::tuple{1.0, 0.6, 0.8}}) {
    Problem p = dry_small_indenter();
    p.indenter = FlatPunch{indenter};
    const double ratio = stretch_at_force(p, mu, force);
    p.friction = 7.0;  // ignored: it is what is calibrated
    const auto e = friction_from_hole(p, {ratio, 0.0, force}, HoleMethod::AtMeasuredForce);
    ASSERT_TRUE(e.friction.ok()) << e.friction.message;
    EXPECT_NEAR(e.friction.value, mu, kRecoveryTol) << "indenter " << indenter;
    EXPECT_EQ(e.friction.solutions.size(), 1u);
    ASSERT_TRUE(e.max_first_invariant);
    EXPECT_GT(*e.stretch_at_zero_friction, ratio);
    EXPECT_LT(*e.stretch_at_max_friction, ratio);
    EXPECT_FALSE(e.friction_for_ratio_plus_sd.ok());  // no sd given
  }
}

TEST(FrictionFromHole, RecoversFrictionAtThePredictedPuncture) {
  Problem p = dry_small_indenter();
  const auto truth = predict_puncture(p, quiet());
  ASSERT_TRUE(truth.ok());
  const auto e = friction_from_hole(
      p, {truth.part_three_stretch, 0.0, std::nullopt}, HoleMethod::AtPredictedPuncture);
  ASSERT_TRUE(e.friction.ok()) << e.friction.message;
  EXPECT_NEAR(e.friction.value, 1.95, kRecoveryTol);
  ASSERT_TRUE(e.puncture_force_n);
  EXPECT_NEAR(*e.puncture_force_n, truth.force_n, 1e-6 * truth.force_n);
  // With mu' = 0 the crack is at the corner with lambda1 = Lambda: 2 Lambda^2 + Lambda^-4 = I1c.
  EXPECT_NEAR(*e.stretch_at_zero_friction, equibiaxial_stretch_for_first_invariant(95.2), 1e-6);
}

TEST(FrictionFromHole, AtPunctureTheEstimateDoesNotDependOnTheIndenter) {
  // docs/model.md §8: with the crack at the corner the Part III stretch at puncture depends on
  // the material, mu' and the critical I1 only, so the hole gives the same mu' for any indenter.
  Problem small = dry_small_indenter();
  Problem large = small;
  large.indenter = FlatPunch{3.0};
  const HoleMeasurement hole{1.58, 0.0, std::nullopt};
  const auto a = friction_from_hole(small, hole, HoleMethod::AtPredictedPuncture);
  const auto b = friction_from_hole(large, hole, HoleMethod::AtPredictedPuncture);
  ASSERT_TRUE(a.friction.ok() && b.friction.ok());
  EXPECT_NEAR(a.friction.value, b.friction.value, kRecoveryTol);
  EXPECT_GT(*b.puncture_force_n, 2.5 * *a.puncture_force_n);  // the force does depend on it
}

TEST(FrictionFromHole, NoisyRatiosMoveTheEstimateTheRightWayAndStayInTheInterval) {
  const Problem p = dry_small_indenter();
  const double force = 1.5;
  const double mu = 1.95;
  const double exact = stretch_at_force(p, mu, force);
  test::SeededNoise noise(20180101, 0.03);
  const double sd = 0.14;  // the paper's: wider than the noise, so the truth must be inside
  for (int draw = 0; draw < 4; ++draw) {
    const double dn = noise();
    ASSERT_LT(std::abs(dn), sd);  // the premise of the interval check below
    const auto e = friction_from_hole(p, {exact + dn, sd, force}, HoleMethod::AtMeasuredForce);
    ASSERT_TRUE(e.friction.ok()) << e.friction.message;
    // The stretch falls as the friction grows: a larger ratio means less friction.
    if (dn > 0)
      EXPECT_LT(e.friction.value, mu);
    else
      EXPECT_GT(e.friction.value, mu);
    // The estimate reproduces the noisy ratio it was given.
    EXPECT_NEAR(stretch_at_force(p, e.friction.value, force), exact + dn, 1e-7);
    ASSERT_TRUE(e.friction_for_ratio_plus_sd.ok() && e.friction_for_ratio_minus_sd.ok());
    EXPECT_LT(e.friction_for_ratio_plus_sd.value, mu);
    EXPECT_GT(e.friction_for_ratio_minus_sd.value, mu);
  }
}

TEST(FrictionFromHole, ReportsRatiosOutOfReach) {
  const Problem p = dry_small_indenter();
  const double force = 1.5;
  // Too large: more stretch than even frictionless sliding gives at this force.
  const auto big = friction_from_hole(p, {9.0, 0.0, force}, HoleMethod::AtMeasuredForce);
  EXPECT_FALSE(big.friction.ok());
  EXPECT_TRUE(big.friction.solutions.empty());
  EXPECT_NE(big.friction.message.find("largest attainable"), std::string::npos)
      << big.friction.message;
  EXPECT_LT(*big.stretch_at_zero_friction, 9.0);
  // Too small: no sliding at all would need mu' beyond the model's limit.
  const auto one = friction_from_hole(p, {1.0, 0.0, force}, HoleMethod::AtMeasuredForce);
  EXPECT_FALSE(one.friction.ok());
  EXPECT_NE(one.friction.message.find("smallest attainable"), std::string::npos)
      << one.friction.message;
  // At puncture, frictionless sliding gives at most 6.899 (I1c = 95.2).
  const auto punct =
      friction_from_hole(p, {7.5, 0.0, std::nullopt}, HoleMethod::AtPredictedPuncture);
  EXPECT_FALSE(punct.friction.ok());
  // One end of the interval out of reach, the value itself not.
  const auto wide = friction_from_hole(p, {1.3, 0.5, force}, HoleMethod::AtMeasuredForce);
  EXPECT_TRUE(wide.friction.ok());
  EXPECT_TRUE(wide.friction_for_ratio_plus_sd.ok());
  EXPECT_FALSE(wide.friction_for_ratio_minus_sd.ok());
  EXPECT_NE(wide.friction_for_ratio_minus_sd.message.find("0.8"), std::string::npos);
}

TEST(FrictionFromHole, RefusesInvalidInput) {
  const Problem p = dry_small_indenter();
  EXPECT_THROW(friction_from_hole(p, {-1.0, 0.0, 1.0}, HoleMethod::AtMeasuredForce),
               std::invalid_argument);
  EXPECT_THROW(friction_from_hole(p, {1.5, -0.1, 1.0}, HoleMethod::AtMeasuredForce),
               std::invalid_argument);
  EXPECT_THROW(friction_from_hole(p, {1.5, 0.1, std::nullopt}, HoleMethod::AtMeasuredForce),
               std::invalid_argument);
  EXPECT_THROW(friction_from_hole(p, {1.5, 0.1, 0.0}, HoleMethod::AtMeasuredForce),
               std::invalid_argument);
  Problem bad = p;
  bad.indenter = FlatPunch{30.0};
  EXPECT_THROW(friction_from_hole(bad, {1.5, 0.1, 1.0}, HoleMethod::AtMeasuredForce),
               std::invalid_argument);
}

}  // namespace
}  // namespace puncture
