// `verify` (verification.hpp): passes on the paper's membrane with every check present, and can
// fail: the paper's printed Part II equation is not the stationarity of the stored energy.
#include <gtest/gtest.h>

#include <stdexcept>

#include "puncture/verification.hpp"

namespace puncture {
namespace {

int count_quantity(const VerificationReport& r, const std::string& group,
                   const std::string& quantity) {
  int n = 0;
  for (const auto& c : r.checks) n += c.group == group && c.quantity == quantity;
  return n;
}

TEST(Verify, PassesOnThePapersMembraneWithEveryCheck) {
  VerifyOptions options;
  options.elements = 64;
  options.depths = 2;
  int calls = 0;
  options.progress = [&](int done, int total, std::string_view) {
    EXPECT_LT(done, total);
    ++calls;
  };
  const VerificationReport r = verify(Problem{}, options);
  for (const auto& c : r.checks)
    EXPECT_EQ(c.verdict, Verdict::Pass) << c.group << " " << c.quantity << " " << c.condition
                                        << ": " << c.difference << " (" << c.note << ")";
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(count_quantity(r, "frictionless", "force [N]"), 2);
  EXPECT_EQ(count_quantity(r, "frictionless", "Part III stretch"), 2);
  EXPECT_EQ(count_quantity(r, "held at the edge", "largest I1"), 2);
  EXPECT_EQ(count_quantity(r, "frictionless", "work of F = stored energy [N mm]"), 1);
  EXPECT_EQ(count_quantity(r, "held at the edge", "work of F = stored energy [N mm]"), 1);
  EXPECT_EQ(r.count(Verdict::Pass), int(r.checks.size()));
  EXPECT_GT(calls, 5);
}

// Pre-stretched (L0 = 1.2): the same checks, the work against the energy stored beyond the flat
// pre-stretched membrane's, and the small-deflection rows against the pre-tensioned membrane's
// linear stiffness (docs/model.md §16) instead of Foppl's cubic law.
TEST(Verify, PassesOnAPrestretchedMembrane) {
  VerifyOptions options;
  options.elements = 64;
  options.depths = 2;
  Problem p;
  p.preload.prestretch = 1.2;
  const VerificationReport r = verify(p, options);
  for (const auto& c : r.checks)
    EXPECT_EQ(c.verdict, Verdict::Pass) << c.group << " " << c.quantity << " " << c.condition
                                        << ": " << c.difference << " (" << c.note << ")";
  EXPECT_TRUE(r.ok());
  const std::string work = "work of F = stored energy - flat pre-stretched energy [N mm]";
  EXPECT_EQ(count_quantity(r, "frictionless", work), 1);
  EXPECT_EQ(count_quantity(r, "held at the edge", work), 1);
  EXPECT_EQ(count_quantity(r, "small deflection", "F / delta [N/mm], held edge, pre-tensioned"), 1);
  EXPECT_EQ(r.count(Verdict::Pass), int(r.checks.size()));
}

// The sphere-tipped probe: the frictionless limit against the finite elements on its profile
// (force, pole stretch, contact edge, largest I1 at each depth, and the work), with the user's
// friction replaced by mu' = 0; no held rows without the stick rule `always`
// (tests/fe/held_smooth_probe_test.cpp) and no Foppl rows (the flat punch's disc).
TEST(Verify, PassesOnTheSphereTippedProbe) {
  VerifyOptions options;
  options.elements = 64;
  options.depths = 2;
  Problem p;
  p.indenter = SphereTipped{2.0};
  const VerificationReport r = verify(p, options);
  for (const auto& c : r.checks)
    EXPECT_EQ(c.verdict, Verdict::Pass) << c.group << " " << c.quantity << " " << c.condition
                                        << ": " << c.difference << " (" << c.note << ")";
  EXPECT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(count_quantity(r, "frictionless", "force [N]"), 2);
  EXPECT_EQ(count_quantity(r, "frictionless", "pole stretch"), 2);
  EXPECT_EQ(count_quantity(r, "frictionless", "contact edge R [mm]"), 2);
  EXPECT_EQ(count_quantity(r, "frictionless", "largest I1"), 2);
  EXPECT_EQ(count_quantity(r, "frictionless", "work of F = stored energy [N mm]"), 1);
  EXPECT_EQ(count_quantity(r, "frictionless", "Part III stretch"), 0);
  EXPECT_EQ(int(r.checks.size()), 9);  // nothing held, no small-deflection rows
}

// The other smooth probes on the paper's membrane: the same rows as the sphere-tipped probe's.
// The filleted punch up to its puncture; the cone and the ball up to the end of their model
// (the cone's membrane then leaves the kink onto the shank, the ball's contact nears its
// equator): their curves end there with OutsideModel before the puncture.
TEST(Verify, PassesOnTheFilletedPunchTheConeAndTheBall) {
  VerifyOptions options;
  options.elements = 32;
  options.depths = 2;
  for (const Indenter& indenter :
       {Indenter{FlatPunch{2.0, 0.5}}, Indenter{Cone{2.0, 30.0, 0.5}}, Indenter{Ball{1.0, 2.0}}}) {
    Problem p;
    p.indenter = indenter;
    const VerificationReport r = verify(p, options);
    for (const auto& c : r.checks)
      EXPECT_EQ(c.verdict, Verdict::Pass)
          << describe(indenter) << ": " << c.group << " " << c.quantity << " " << c.condition
          << ": " << c.difference << " (" << c.note << ")";
    EXPECT_TRUE(r.ok()) << describe(indenter) << ": " << r.message;
    EXPECT_EQ(count_quantity(r, "frictionless", "force [N]"), 2);
    EXPECT_EQ(count_quantity(r, "frictionless", "pole stretch"), 2);
    EXPECT_EQ(count_quantity(r, "frictionless", "contact edge R [mm]"), 2);
    EXPECT_EQ(count_quantity(r, "frictionless", "work of F = stored energy [N mm]"), 1);
    EXPECT_EQ(int(r.checks.size()), 9) << describe(indenter);
  }
}

// With mu' = 0 the printed Eq. (18) keeps s1 constant along Part II, the energy R s1
// (docs/model.md §4): once the membrane wraps the side the forces differ by percents.
TEST(Verify, FailsForThePrintedPartTwoEquation) {
  Problem p;
  p.part_two_equation = PartTwoEquation::PaperEq18;
  VerifyOptions options;
  options.elements = 32;
  options.depths = 4;
  const VerificationReport r = verify(p, options);
  EXPECT_FALSE(r.ok());
  bool force_failed = false;
  for (const auto& c : r.checks)
    if (c.group == "frictionless" && c.quantity == "force [N]" && c.verdict == Verdict::Fail &&
        has_numbers(c))
      force_failed = force_failed || std::abs(c.difference) > 1e-2;
  EXPECT_TRUE(force_failed);
  // ... and says why, so that the failure is not taken for a solver fault.
  EXPECT_NE(r.message.find("paper's Eq. (18) as printed is not the membrane's equilibrium"),
            std::string::npos)
      << r.message;
  // The held membrane never touches the side: Eq. (18) plays no part, those checks pass.
  for (const auto& c : r.checks)
    if (c.group == "held at the edge") EXPECT_EQ(c.verdict, Verdict::Pass) << c.quantity;
}

TEST(Verify, RejectsInvalidOptions) {
  VerifyOptions few;
  few.elements = 2;
  EXPECT_THROW(verify(Problem{}, few), std::invalid_argument);
  VerifyOptions none;
  none.depths = 0;
  EXPECT_THROW(verify(Problem{}, none), std::invalid_argument);
  Problem bad;
  bad.geometry.thickness_mm = -1.0;
  EXPECT_THROW(verify(bad), std::invalid_argument);
}

}  // namespace
}  // namespace puncture
