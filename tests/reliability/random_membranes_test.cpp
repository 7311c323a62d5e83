// The reliability sweep: seeded random membranes over the documented ranges through the library.
// Every result is a converged state with finite numbers or a failure with a kind and a reason,
// checked independently where a criterion exists; the counts by outcome are printed.
// PUNCTURE_RELIABILITY_CASES sets the number of membranes.
#include "random_membranes.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

#include "independent_reasons.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::test {
namespace {

int cases_from_environment(int fallback) {
  const char* text = std::getenv("PUNCTURE_RELIABILITY_CASES");
  return text ? std::max(1, std::atoi(text)) : fallback;
}

// The failure's reason without its numbers: "beyond locking: the corner of Part II ..." cut at
// the first digit, so that counts group by cause.
std::string reason(const Outcome& o) {
  std::string text = to_string(o.status) + ": " + o.message;
  const auto digit = text.find_first_of("0123456789", to_string(o.status).size());
  if (digit != std::string::npos) text.resize(digit);
  if (text.size() > 110) text.resize(110);
  return text;
}

std::string summary_of(const Problem& p) {
  return fmt::format(
      "A = {} mm, {}, H = {} mm, L0 = {}, p = {} MPa, G = {} MPa, {}, friction {}, critical I1 "
      "{}, stick {}, {}",
      p.geometry.clamp_radius_mm,
      describe(p.indenter),
      p.geometry.thickness_mm,
      p.preload.prestretch,
      p.preload.pressure_mpa,
      p.material.shear_modulus_mpa,
      describe(p.material),
      p.friction,
      p.critical_i1,
      describe(p.stick),
      to_string(p.part_two_equation));
}

// Every membrane of the sweep gives a converged state with finite numbers, or a physical
// failure whose reason is confirmed independently; none fails numerically.  The one known
// exception, counted apart: inflated membranes, where the 10^4 sweep met 17 numerical
// failures or unconfirmed ends (mostly large spheres; force searches closing on roots of another
// inflated branch near Part II's onset; docs/model.md §17): at most 0.5 % of them, so that more
// fails.
void sweep(std::uint64_t seed, Laws laws, Mounting mounting = Mounting::StressFree) {
  const int cases = cases_from_environment(300);
  std::map<std::string, int> counts;
  int numerical = 0, converged = 0, unconfirmed = 0;
  int inflated = 0, inflated_failures = 0;
  for (int k = 0; k < cases; ++k) {
    const Problem p = random_membrane(seed, k, laws, mounting);
    const bool known = mounting == Mounting::Inflated;
    inflated += known;
    ASSERT_TRUE(validation_errors(p).empty()) << k << ": " << validation_errors(p).front().message;
    const PuncturePrediction at = predict_puncture(p);
    if (at.ok()) {
      ++converged;
      ASSERT_TRUE(std::isfinite(at.force_n) && at.force_n > 0.0 && std::isfinite(at.depth_mm) &&
                  at.depth_mm > 0.0)
          << k << ": " << summary_of(p);
      ++counts["converged"];
      continue;
    }
    EXPECT_FALSE(at.message.empty()) << k;
    ++counts[to_token(at.failure_kind()) + " | " + reason(at)];
    if (const std::string why = unconfirmed_reason(p, at); !why.empty()) {
      ++(known ? inflated_failures : unconfirmed);
      fmt::print("unconfirmed physical reason, case {} ({}): {}\n  {}\n",
                 k,
                 why,
                 summary_of(p),
                 at.message);
    }
    if (at.failure_kind() == FailureKind::Numerical) {
      ++(known ? inflated_failures : numerical);
      fmt::print("numerical failure, case {}: {}\n  {}\n", k, summary_of(p), at.message);
    }
  }
  fmt::print("{} membranes (seed {}):\n", cases, seed);
  for (const auto& [what, n] : counts) fmt::print("  {:6d}  {}\n", n, what);
  ::testing::Test::RecordProperty("numerical_failures", numerical);
  ::testing::Test::RecordProperty("converged", converged);
  // Every numerical failure is a solver bug: none, of 300 (the default) or of 10^4 (the slow
  // test).  When the sweep was written 28 of the first 300 failed numerically, 7 of 10^4 before
  // the held branch's end and steep Part II states were fixed (known_cases_test.cpp).
  EXPECT_EQ(numerical, 0);
  // Every "not reached" and "would wrap the side" is confirmed by the stage's own end, found
  // by bisection on solve_at_force (independent_reasons.hpp).
  EXPECT_EQ(unconfirmed, 0);
  EXPECT_LE(inflated_failures, 0.005 * inflated + 1);
  ::testing::Test::RecordProperty("inflated_known_failures", inflated_failures);
  // The sweep must exercise the solver, not only its failure paths.
  EXPECT_GE(converged, cases / 2);
}

TEST(Reliability, RandomMembranesGiveAStateOrAPhysicalReason) { sweep(20261123, Laws::Paper); }

// The Yeoh law over the same ranges.  10^4 membranes: 9696 converged, 304 physical (267 not
// reached, 37 would wrap the side), all confirmed, none numerical.
TEST(Reliability, RandomYeohMembranesGiveAStateOrAPhysicalReason) { sweep(20261125, Laws::Yeoh); }

// Pre-stretched membranes (L0 up to 3) over the same ranges.  10^4 of them: 9158 converged, 842
// physical failures (529 not reached, 313 would wrap the side), all confirmed, none numerical.
TEST(Reliability, RandomPrestretchedMembranesGiveAStateOrAPhysicalReason) {
  sweep(20261126, Laws::Paper, Mounting::Prestretched);
}

// Inflated membranes indented at constant pressure (sliding, frictionless; the flat punch and the
// sphere-tipped probe alternately) over the same ranges (of 300, every one converges).
TEST(Reliability, RandomInflatedMembranesGiveAStateOrAPhysicalReason) {
  sweep(20261127, Laws::Paper, Mounting::Inflated);
}

}  // namespace
}  // namespace puncture::test
