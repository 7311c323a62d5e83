// The one-line reports: they state the status and the result's own numbers with units, and a
// failure's reason.
#include "puncture/reports.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

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
  // Gent with J_lim = 5 locks at I1 = 8: 50 N is far beyond what the membrane carries.
  Problem p = test::paper_problem(Gent{5.0});
  p.critical_i1 = 7.0;  // below the locking I1, else the problem is invalid
  const auto state = solve_at_force(p, 50.0, Stage::Slip);
  ASSERT_EQ(state.status, Status::BeyondLocking) << state.message;
  EXPECT_EQ(brief_report(state), "beyond locking: " + state.message);
  PuncturePrediction none;
  none.status = Status::NotReached;
  none.message = "I1 does not reach 20";
  EXPECT_EQ(brief_report(none), "not found: I1 does not reach 20");
}

}  // namespace
}  // namespace puncture
