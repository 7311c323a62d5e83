// Every result is an Outcome: its status and message are the base's, never redeclared (a
// redeclared `message` would hide the one Python's Outcome.message and ok() read).
#include "puncture/outcome.hpp"

#include <gtest/gtest.h>

#include <string>
#include <type_traits>

#include "puncture/calibration.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/finite_element.hpp"
#include "puncture/inflation.hpp"
#include "puncture/loading_curve.hpp"
#include "puncture/puncture_band.hpp"
#include "puncture/verification.hpp"

namespace puncture {
namespace {

template <class Result>
constexpr bool is_plain_outcome = std::is_base_of_v<Outcome, Result>&&
    std::is_same_v<decltype(&Result::message), std::string Outcome::*>&&
        std::is_same_v<decltype(&Result::status), Status Outcome::*>;

static_assert(is_plain_outcome<Equilibrium>);
static_assert(is_plain_outcome<StageBoundary>);
static_assert(is_plain_outcome<PuncturePrediction>);
static_assert(is_plain_outcome<LoadingCurve>);
static_assert(is_plain_outcome<InflationState>);
static_assert(is_plain_outcome<InflationBurst>);
static_assert(is_plain_outcome<InflationCurve>);
static_assert(is_plain_outcome<PressureExtrema>);
static_assert(is_plain_outcome<InflationAtPressure>);
static_assert(is_plain_outcome<Inversion>);
static_assert(is_plain_outcome<UniaxialFit>);
static_assert(is_plain_outcome<FeState>);
static_assert(is_plain_outcome<BandEvaluation>);
static_assert(is_plain_outcome<PunctureBand>);
static_assert(is_plain_outcome<VerificationReport>);

TEST(Outcome, IsOkOnlyWhenConverged) {
  Outcome o;
  EXPECT_FALSE(o.ok());  // a result nobody filled in is not usable
  for (const Status s : {Status::NoConvergence,
                         Status::BeyondLocking,
                         Status::StickWrapsSide,
                         Status::NotReached,
                         Status::Incomplete,
                         Status::ChecksFailed}) {
    o.status = s;
    EXPECT_FALSE(o.ok()) << to_string(s);
    EXPECT_NE(to_string(s), "?");
  }
  o.status = Status::Converged;
  EXPECT_TRUE(o.ok());
}

TEST(Outcome, InvalidInputCarriesTheParameter) {
  const InvalidInput e("geometry.thickness_mm", "thickness must be > 0 mm, got -1");
  ASSERT_EQ(e.errors().size(), 1u);
  EXPECT_EQ(e.errors().front().parameter, "geometry.thickness_mm");
  EXPECT_STREQ(e.what(), "thickness must be > 0 mm, got -1");
}

}  // namespace
}  // namespace puncture
