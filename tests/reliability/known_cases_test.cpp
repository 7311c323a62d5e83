// Membranes of the 10^4-membrane sweep (seed 20261123) that once ended in a numerical failure,
// each with the independent fact behind its answer now.
#include <gtest/gtest.h>

#include <cmath>

#include "puncture/loading_curve.hpp"
#include "random_membranes.hpp"

namespace puncture::test {
namespace {

constexpr std::uint64_t kSeed = 20261123;

// Held at the edge to the end of the held branch, where the membrane leaves the edge vertically
// and would have to wrap the side: the search for the force at which the largest I1 reaches the
// critical value closes on that end, whose clamp residual at t = 0 (-4e-14 for case 2353) is
// already within the tolerance while the root t ~ 1e-18 took TOMS 748 past its iteration limit
// ("stick shooting found no edge tension meeting the clamp condition").  Now: not reached, with
// the largest I1 below the critical value, ending where the held membrane would wrap the side.
TEST(KnownCases, HeldToTheBranchEndIsNotReached) {
  for (const int k : {2353, 2502, 2570, 4198, 9147}) {
    const Problem p = random_membrane(kSeed, k);
    ASSERT_EQ(p.stick.rule, StickRule::Always) << k;
    const PuncturePrediction at = predict_puncture(p);
    EXPECT_EQ(at.status, Status::NotReached) << k << ": " << at.message;
    EXPECT_NE(at.message.find("wrap its side"), std::string::npos) << k << ": " << at.message;
  }
}

// A sliding Part II whose top stretch is 0.30 (material from beyond the indenter's radius
// climbs its side): the clamp residual changes by 6e-8 for 1e-12 of the parameter, so a sampled
// integration that took other steps than the shooting's moved it by 1e-8 from the shooting's
// root ("the shooting stalled at clamp residual 1e-08").  Samples are now taken between the
// shooting's own steps: the puncture is where the largest I1 is the critical one.
TEST(KnownCases, SteepPartTwoPunctureConverges) {
  const Problem p = random_membrane(kSeed, 4309);
  const PuncturePrediction at = predict_puncture(p);
  ASSERT_TRUE(at.ok()) << at.message;
  EXPECT_LE(at.state.clamp_residual, 1e-10);
  EXPECT_NEAR(at.state.max_first_invariant / p.critical_i1, 1.0, 1e-6);
}

// A 0.018 mm probe on a 7.7 mm neo-Hookean membrane: 10 times the puncture force its largest I1
// is 1e24, and the search along the path, secant through that value, went to forces of 1e-25
// whose strains (1e-16) the shooting cannot resolve ("the shooting stalled at clamp residual
// -1", taken for the end of the states).  On asinh of the excess it brackets the puncture: the
// largest I1 there is the critical one.
TEST(KnownCases, SoftLawPastItsPunctureKeepsTheSearchInRange) {
  const Problem p = random_membrane(kSeed, 3577);
  const PuncturePrediction at = predict_puncture(p);
  ASSERT_TRUE(at.ok()) << at.message;
  EXPECT_NEAR(at.state.max_first_invariant / p.critical_i1, 1.0, 1e-6);
  EXPECT_LE(at.state.clamp_residual, 1e-10);
}

// Mooney-Rivlin membranes sliding with mu' ~ 10 (a capstan factor of ~5e6) after a stick stage:
// the corner of Part II, located to ulps, was rejected because its capstan gap (a difference of
// two stresses of ~5e6 s_eq) kept ~1e-8 of them in rounding, and reported as "beyond the
// material's locking limit" although Mooney-Rivlin does not lock; the search took the first such
// force for the end of the states.  The independent check of the sweep (a state exists beyond
// that end; for 1904 the largest I1 there passes the critical value) found them.  Now the
// puncture is where the largest I1 is the critical one.
TEST(KnownCases, HighFrictionCornerIsLocatedToRounding) {
  for (const int k : {1904, 2007, 3189}) {
    const Problem p = random_membrane(kSeed, k);
    const PuncturePrediction at = predict_puncture(p);
    ASSERT_TRUE(at.ok()) << k << ": " << at.message;
    EXPECT_NEAR(at.state.max_first_invariant / p.critical_i1, 1.0, 1e-6) << k;
  }
}

// Held until a depth of 12.84 mm that the held branch does not reach: it ends (vertical exit)
// shallower, a physical answer, not "neither the force search nor depth control reaches it".
TEST(KnownCases, HeldDepthBeyondTheBranchEndWrapsTheSide) {
  const Problem p = random_membrane(kSeed, 6250);
  ASSERT_EQ(p.stick.rule, StickRule::Depth);
  const PuncturePrediction at = predict_puncture(p);
  EXPECT_EQ(at.status, Status::StickWrapsSide) << at.message;
  EXPECT_EQ(at.failure_kind(), FailureKind::Physical);
}

}  // namespace
}  // namespace puncture::test
