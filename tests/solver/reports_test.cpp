// The one-line reports: they state the status and the result's own numbers with units, and a
// failure's reason.
#include "puncture/reports.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <limits>

#include "solver_test_support.hpp"

namespace puncture {
namespace {

TEST(BriefReport, StatesTheResultsNumbersWithUnits) {
  const Problem p = test::paper_problem();
  const auto state = solve_at_force(p, 0.3, Stage::Slip);
  ASSERT_TRUE(state.ok()) << state.message;
  const std::string s = brief_report(state);
  EXPECT_EQ(s.rfind("converged: slip stage, ", 0), 0u) << s;
  EXPECT_NE(s.find(fmt::format("depth {:.6g} mm", state.depth_mm)), std::string::npos) << s;
  EXPECT_NE(s.find("force 0.3 N"), std::string::npos) << s;

  CurveOptions options;
  options.points = 5;
  const auto curve = loading_curve(p, options);
  ASSERT_TRUE(curve.ok()) << curve.message;
  EXPECT_NE(brief_report(curve).find(fmt::format("puncture at {:.6g} N", curve.puncture.force_n)),
            std::string::npos);
  EXPECT_NE(brief_report(curve.puncture).find(curve.puncture.crack_location), std::string::npos);
}

TEST(BriefReport, SaysWhyAResultFailed) {
  // A neo-Hookean membrane carries a force of order 2 pi G H a (0.15 N here): 50 N is beyond its
  // limit load.  (A Gent membrane carries any force, its stress unbounded towards locking.)
  const Problem p = test::paper_problem(NeoHookean{});
  const auto state = solve_at_force(p, 50.0, Stage::Slip);
  ASSERT_EQ(state.status, Status::LimitLoad) << state.message;
  EXPECT_EQ(brief_report(state), "limit load: " + state.message);
  PuncturePrediction none;
  none.status = Status::NotReached;
  none.message = "I1 does not reach 20";
  EXPECT_EQ(brief_report(none), "not found: I1 does not reach 20");
}

TEST(FullReport, ListsTheInputsWithUnits) {
  const Problem p = test::paper_problem();
  const std::string s = full_report(p);
  EXPECT_EQ(s.rfind("Inputs\n", 0), 0u) << s;
  EXPECT_NE(s.find("  clamp radius A          25 mm\n"), std::string::npos) << s;
  EXPECT_NE(s.find("flat punch, radius 2 mm"), std::string::npos) << s;
  EXPECT_NE(s.find(fmt::format("{:.5g} N (normalised force", force_scale_n(p))), std::string::npos)
      << s;
}

TEST(FullReport, StatesTheStateAgainstTheCriterion) {
  const Problem p = test::paper_problem();
  const auto state = solve_at_force(p, 0.3, Stage::Slip);
  ASSERT_TRUE(state.ok()) << state.message;
  const std::string s = full_report(state, p);
  EXPECT_NE(s.find(fmt::format("  depth                   {:.5g} mm\n", state.depth_mm)),
            std::string::npos)
      << s;
  EXPECT_NE(s.find(fmt::format("(below the critical {:.5g})", p.critical_i1)), std::string::npos)
      << s;
  // The puncture block of a curve is the puncture's own full report.
  CurveOptions options;
  options.points = 5;
  const auto curve = loading_curve(p, options);
  ASSERT_TRUE(curve.ok()) << curve.message;
  EXPECT_NE(full_report(curve, p).find(full_report(curve.puncture)), std::string::npos);
}

TEST(FullReport, WritesNoNonFiniteNumber) {
  Equilibrium e;
  e.status = Status::Converged;
  e.force_n = std::numeric_limits<double>::quiet_NaN();
  e.corner_tension_ratio = std::numeric_limits<double>::infinity();  // held at the edge
  const std::string s = full_report(e, test::paper_problem());
  EXPECT_NE(s.find("  force                   n/a N"), std::string::npos) << s;
  EXPECT_NE(s.find("n/a (the membrane is held at the edge)"), std::string::npos) << s;
  EXPECT_EQ(s.find("nan"), std::string::npos) << s;
  EXPECT_EQ(s.find("inf"), std::string::npos) << s;
  e.status = Status::NoConvergence;
  e.message = "the shooting did not reach the clamp";
  EXPECT_EQ(full_report(e, test::paper_problem()),
            "  no convergence: the shooting did not reach the clamp\n");
}

TEST(FullReport, CountsTheVerdicts) {
  VerificationReport v;
  VerificationCheck pass;
  pass.group = "frictionless";
  pass.quantity = "force [N]";
  pass.shooting = 1.0;
  pass.reference = 1.0 + 1e-7;
  pass.difference = 1e-7;
  pass.tolerance = 1e-5;
  pass.verdict = Verdict::Pass;
  VerificationCheck skipped = pass;
  skipped.verdict = Verdict::Skipped;
  skipped.note = "no equilibrium";
  v.checks = {pass, skipped};
  const std::string s = full_report(v);
  EXPECT_NE(s.find("Result: 1 passed, 0 failed, 1 skipped\n"), std::string::npos) << s;
  EXPECT_NE(s.find("skipped: no equilibrium"), std::string::npos) << s;
}

}  // namespace
}  // namespace puncture
