// Bad input through the public API, and a random sweep of valid inputs: every result is either
// converged with finite fields or a non-converged status with a message, never a crash or NaN.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(BadInput, InvalidForceIsReported) {
  const Problem p = paper_problem();
  for (double force : {-1.0, -1e-12, kNaN, kInf, -kInf}) {
    for (Stage stage : {Stage::Stick, Stage::Slip}) {
      try {
        solve_at_force(p, force, stage);
        ADD_FAILURE() << "F = " << force << " accepted";
      } catch (const InvalidInput& e) {
        ASSERT_EQ(e.errors().size(), 1u);
        EXPECT_EQ(e.errors().front().parameter, "force_n");
        EXPECT_NE(e.errors().front().message.find("force"), std::string::npos) << e.what();
      }
    }
  }
}

TEST(BadInput, InvalidDepthIsReported) {
  const Problem p = paper_problem();
  for (double depth : {-2.0, kNaN, kInf}) {
    try {
      solve_at_depth(p, depth, Stage::Slip);
      ADD_FAILURE() << "depth = " << depth << " accepted";
    } catch (const InvalidInput& e) {
      ASSERT_EQ(e.errors().size(), 1u);
      EXPECT_EQ(e.errors().front().parameter, "depth_mm");
      EXPECT_NE(e.errors().front().message.find("depth"), std::string::npos) << e.what();
    }
  }
}

// Gent locks at I1 = 3 + J_lim: a critical I1 at or beyond it can never be reached.
TEST(BadInput, CriticalInvariantAtOrBeyondLockingIsRejected) {
  for (double i1c : {128.0, 130.0, 1e6}) {
    Problem p = paper_problem(Gent{125.0});
    p.critical_i1 = i1c;
    const auto errors = validation_errors(p);
    ASSERT_EQ(errors.size(), 1u) << "I1c = " << i1c;
    EXPECT_EQ(errors.front().parameter, "critical_i1");
    EXPECT_NE(errors.front().message.find("critical I1"), std::string::npos)
        << errors.front().message;
    EXPECT_THROW(validate(p), std::invalid_argument);
    EXPECT_THROW(solve_at_force(p, 0.5, Stage::Slip), InvalidInput);
    EXPECT_THROW(predict_puncture(p), InvalidInput);
    EXPECT_THROW(loading_curve(p), InvalidInput);
  }
  // Just below locking is valid.
  Problem p = paper_problem(Gent{125.0});
  p.critical_i1 = 127.9;
  EXPECT_TRUE(validation_errors(p).empty());
}

// Uniform number in [lo, hi) from the standard-specified mt19937 sequence (the distributions of
// <random> differ between standard libraries; this does not).
double uniform(std::mt19937& gen, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(gen()) / 4294967296.0);
}

void expect_sound(const Equilibrium& e, const std::string& what) {
  if (!e.ok()) {
    EXPECT_FALSE(e.message.empty()) << what << ": " << to_string(e.status) << " without a message";
    return;
  }
  EXPECT_GT(e.fields.size(), 0u) << what;
  EXPECT_TRUE(fields_finite(e.fields)) << what << ": a field holds NaN or infinity";
  EXPECT_TRUE(std::isfinite(e.force_n) && std::isfinite(e.depth_mm) &&
              std::isfinite(e.part_three_stretch) && std::isfinite(e.max_first_invariant) &&
              std::isfinite(e.corner_slope_rad) && std::isfinite(e.part_two_length_mm))
      << what;
  // A held membrane reports an infinite capstan ratio by design (docs/model.md, §9).
  if (e.stage == Stage::Slip) {
    EXPECT_TRUE(std::isfinite(e.corner_tension_ratio)) << what;
  }
}

// 30 seeded random problems: indenter radius 0.5-5 mm, friction 0-3, Gent J_lim 30-300, shear
// modulus 0.01-1 MPa, a critical I1 below locking; at each, a force with f = F / (2 pi G H A)
// in 0.01-2 and a depth in 1-60 mm, in both stages, and the puncture prediction.
TEST(RandomInputs, EveryResultIsFiniteOrExplained) {
  std::mt19937 gen(20180102);
  int converged = 0, total = 0;
  for (int sample = 0; sample < 30; ++sample) {
    Problem p;
    p.indenter = FlatPunch{uniform(gen, 0.5, 5.0)};
    p.friction = uniform(gen, 0.0, 3.0);
    const double j_lim = uniform(gen, 30.0, 300.0);
    p.material.law = Gent{j_lim};
    p.material.shear_modulus_mpa = uniform(gen, 0.01, 1.0);
    p.critical_i1 = std::min(95.2, 3.0 + 0.8 * j_lim);
    const double f = uniform(gen, 0.01, 2.0), depth = uniform(gen, 1.0, 60.0);
    ASSERT_TRUE(validation_errors(p).empty()) << validation_errors(p).front().message;
    const std::string what =
        "sample " + std::to_string(sample) + ": a = " + std::to_string(radius_mm(p.indenter)) +
        " mm, mu' = " + std::to_string(p.friction) + ", J_lim = " + std::to_string(j_lim) +
        ", G = " + std::to_string(p.material.shear_modulus_mpa);
    for (Stage stage : {Stage::Stick, Stage::Slip}) {
      const auto at_force = solve_at_force(p, force_at(p, f), stage);
      expect_sound(at_force, what + ", f = " + std::to_string(f) + ", " + to_string(stage));
      const auto at_depth = solve_at_depth(p, depth, stage);
      expect_sound(at_depth, what + ", depth = " + std::to_string(depth) + ", " + to_string(stage));
      converged += at_force.ok() + at_depth.ok();
      total += 2;
      if (at_depth.ok()) {
        EXPECT_NEAR(at_depth.depth_mm, depth, 1e-8 * depth) << what;
      }
    }
    const auto punct = predict_puncture(p);
    if (punct.ok()) {
      EXPECT_TRUE(std::isfinite(punct.force_n) && punct.force_n > 0.0) << what;
      EXPECT_TRUE(fields_finite(punct.state.fields)) << what;
      EXPECT_NEAR(punct.state.max_first_invariant, p.critical_i1, 1e-6) << what;
    } else {
      EXPECT_FALSE(punct.message.empty()) << what;
    }
  }
  // The sweep must exercise the solver, not only its failure paths.
  EXPECT_GE(converged, total / 2);
  record("converged_fraction", static_cast<double>(converged) / total);
}

// The density of the recorded fields (SolverOptions::field_points, which caps the integration
// step) must not decide whether an equilibrium is found: held and sliding states at a few
// forces, with 200 to 2000 field points.
TEST(FieldDensity, RecordedFieldsAtAnyDensity) {
  for (double mu : {0.0, 0.18}) {
    const Problem p = paper_problem(Gent{125.0}, mu);
    for (double force : {0.0675084045723, 0.3}) {
      for (Stage stage : {Stage::Stick, Stage::Slip}) {
        for (int points = 200; points <= 2000; points += 100) {
          SolverOptions o;
          o.field_points = points;
          const auto e = solve_at_force(p, force, stage, o);
          EXPECT_TRUE(e.ok()) << "mu' = " << mu << ", F = " << force << " N, " << to_string(stage)
                              << ", field_points = " << points << ": " << e.message;
          if (e.ok()) {
            EXPECT_GE(e.fields.size(), static_cast<std::size_t>(points));
          }
        }
      }
    }
  }
}

// Found by the property tests (a random seed): a thin, soft Mooney-Rivlin membrane with a large
// friction and the printed Eq. (18), whose Part II search handed Boost's TOMS 748 an interval that
// did not bracket the corner, and the exception escaped the loading curve.  Now the steps that do
// not bracket are reported and the curve reaches the puncture (the critical I1 at its end).
TEST(NoThrow, PartTwoSearchThatDoesNotBracketIsAStatus) {
  Problem p;
  p.indenter = FlatPunch{0.25};
  p.geometry.thickness_mm = 0.02;
  p.material.shear_modulus_mpa = 0.005;
  p.material.law = MooneyRivlin{0.095803};
  p.friction = 3.84775;
  p.critical_i1 = 145.79356;
  p.part_two_equation = PartTwoEquation::PaperEq18;
  LoadingCurve curve;
  ASSERT_NO_THROW(curve = loading_curve(p));
  ASSERT_TRUE(curve.ok()) << curve.message;
  ASSERT_TRUE(curve.puncture.ok()) << curve.puncture.message;
  // predict_puncture's tolerance on the critical I1 (1e-10 relative shooting, 1e-8 here).
  EXPECT_NEAR(curve.puncture.state.max_first_invariant, p.critical_i1, 1e-8 * p.critical_i1);
}

}  // namespace
}  // namespace puncture::test
