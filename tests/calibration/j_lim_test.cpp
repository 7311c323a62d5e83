// J_lim from one puncture force: forces predicted with a known J_lim must give it back; noisy
// forces must move it the right way and reproduce themselves; forces no J_lim gives are
// reported as such.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "calibration_test_support.hpp"
#include "puncture/calibration.hpp"
#include "seeded_noise.hpp"

namespace puncture {
namespace {

using test::kRecoveryTol;
using test::quiet;

double puncture_force(Problem p, double j_lim) {
  p.material.law = Gent{j_lim};
  const auto punct = predict_puncture(p, quiet());
  EXPECT_TRUE(punct.ok()) << punct.message;
  return punct.force_n;
}

// The inversion runs in log(J_lim - (I1c - 3)) and log F to 1e-10, and each force is converged
// to ~1e-9 relative; near J_lim = 110 d log F / d log J_lim ~ -4, so J_lim is good to ~1e-9:
// 1e-6 relative leaves a wide margin.

TEST(JLimFromPunctureForce, RecoversJLim) {
  Problem lubricated;  // 2 mm, mu' = 0.18
  Problem dry;
  dry.indenter = FlatPunch{1.0};
  dry.friction = 1.95;
  for (const auto& [problem, j_lim] :
       {std::pair{lubricated, 110.0}, std::pair{dry, 125.0}, std::pair{lubricated, 400.0}}) {
    const double force = puncture_force(problem, j_lim);
    const auto e = j_lim_from_puncture_force(problem, force);
    ASSERT_TRUE(e.j_lim.ok()) << e.j_lim.message;
    EXPECT_NEAR(e.j_lim.value, j_lim, kRecoveryTol * j_lim);
    EXPECT_EQ(e.j_lim.solutions.size(), 1u);
    ASSERT_TRUE(e.puncture.ok());
    EXPECT_NEAR(e.puncture.force_n, force, 1e-8 * force);
    // The paper's equivalent check: at that force the largest I1 is the critical one.
    ASSERT_TRUE(e.max_first_invariant_at_force);
    EXPECT_NEAR(*e.max_first_invariant_at_force, problem.critical_i1, 1e-6);
    EXPECT_GT(e.largest_force_n, force);
    EXPECT_LT(e.smallest_force_n, force);
  }
}

TEST(JLimFromPunctureForce, NoisyForcesMoveJLimTheRightWay) {
  const Problem p;
  const double j_true = 125.0;
  const double exact = puncture_force(p, j_true);
  test::SeededNoise noise(4, 0.02);
  JLimOptions coarse;
  coarse.points_per_decade = 2;  // one root: any grid brackets it
  for (int draw = 0; draw < 3; ++draw) {
    const double force = exact * (1.0 + noise());
    const auto e = j_lim_from_puncture_force(p, force, coarse);
    ASSERT_TRUE(e.j_lim.ok()) << e.j_lim.message;
    // The predicted force falls as J_lim grows.
    if (force > exact)
      EXPECT_LT(e.j_lim.value, j_true);
    else
      EXPECT_GT(e.j_lim.value, j_true);
    EXPECT_NEAR(puncture_force(p, e.j_lim.value), force, 1e-8 * force);
  }
}

TEST(JLimFromPunctureForce, ReportsForcesOutOfReach) {
  const Problem p;
  JLimOptions coarse;
  coarse.points_per_decade = 2;
  // Below the neo-Hookean force (J_lim -> infinity), 0.231 N for the default membrane.
  const auto low = j_lim_from_puncture_force(p, 0.2, coarse);
  EXPECT_FALSE(low.j_lim.ok());
  EXPECT_TRUE(low.j_lim.solutions.empty());
  EXPECT_NE(low.j_lim.message.find("neo-Hookean"), std::string::npos) << low.j_lim.message;
  EXPECT_NEAR(low.neo_hookean_force_n, 0.231, 0.001);
  // Above what any J_lim above critical I1 - 3 gives.
  const auto high = j_lim_from_puncture_force(p, 1e7, coarse);
  EXPECT_FALSE(high.j_lim.ok());
  EXPECT_NE(high.j_lim.message.find("above"), std::string::npos) << high.j_lim.message;
  // Above the neo-Hookean force but beyond the J_lim searched.
  JLimOptions short_scan = coarse;
  short_scan.max_gap = 10.0;  // J_lim up to 11 (I1c - 3) = 1014
  const auto beyond = j_lim_from_puncture_force(p, 0.235, short_scan);
  EXPECT_FALSE(beyond.j_lim.ok());
  EXPECT_NE(beyond.j_lim.message.find("larger still"), std::string::npos) << beyond.j_lim.message;
}

TEST(JLimFromPunctureForce, RefusesInvalidInput) {
  Problem p;
  EXPECT_THROW(j_lim_from_puncture_force(p, 0.0), std::invalid_argument);
  EXPECT_THROW(j_lim_from_puncture_force(p, NAN), std::invalid_argument);
  p.material.law = NeoHookean{};
  EXPECT_THROW(j_lim_from_puncture_force(p, 0.7), std::invalid_argument);
  Problem low_i1;
  low_i1.critical_i1 = 2.0;
  EXPECT_THROW(j_lim_from_puncture_force(low_i1, 0.7), std::invalid_argument);
}

// The unknown's own value is ignored, every other parameter is still checked.
TEST(ValidationOfTheUnknown, IgnoresOnlyTheCalibratedParameter) {
  Problem p;
  p.material.law = Gent{125.0};
  p.critical_i1 = 200.0;  // beyond 3 + J_lim: invalid, but J_lim is what is calibrated
  p.friction = -1.0;      // invalid, but the friction is what is calibrated
  const auto parameters = [](const std::vector<ValidationError>& errors) {
    std::vector<std::string> out;
    for (const auto& e : errors) out.push_back(e.parameter);
    return out;
  };
  EXPECT_EQ(parameters(validation_errors(p)),
            (std::vector<std::string>{"friction", "critical_i1"}));
  EXPECT_EQ(parameters(validation_errors(p, Unknown::JLim)), std::vector<std::string>{"friction"});
  EXPECT_EQ(parameters(validation_errors(p, Unknown::Friction)),
            std::vector<std::string>{"critical_i1"});
  p.geometry.thickness_mm = -1.0;
  EXPECT_EQ(parameters(validation_errors(p, Unknown::JLim)),
            (std::vector<std::string>{"geometry.thickness_mm", "friction"}));
  EXPECT_THROW(j_lim_from_puncture_force(p, 0.7), InvalidInput);
  p.geometry.thickness_mm = 0.2;
  p.friction = 0.18;
  EXPECT_NO_THROW(j_lim_from_puncture_force(p, 0.7));  // J_lim 125 is ignored
}

}  // namespace
}  // namespace puncture
