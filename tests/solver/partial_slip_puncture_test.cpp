// The puncture within the partial slip after a `coulomb` release on the sphere-tipped probe
// (docs/model.md §15.4): a critical I1 met between the release and the hand-over to sliding is
// found along the partial-slip family.  Checks: the largest I1 of the partial-slip states solved
// at depths (solve_at_depth, by the depth's own search) bracketing the reported depth crosses the
// critical value there, the state's fields (sampled on their own) reach it too, the curve ends
// there, and as the critical value rises through the hand-over's I1 the puncture depth moves
// continuously from the partial slip to the sliding model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "solver_test_support.hpp"

namespace puncture {
namespace {

// The paper's membrane pre-stretched by 1.2 on the 2 mm sphere-tipped probe, mu = 0.5: released
// at 0.913 mm, the front at the pole from 3.49 mm.
Problem pslip_puncture_problem(double critical_i1) {
  Problem p = test::paper_problem(Gent{125.0}, 0.5);
  p.indenter = SphereTipped{2.0};
  p.stick = {StickRule::Coulomb, 0.0};
  p.preload.prestretch = 1.2;
  p.critical_i1 = critical_i1;
  return p;
}

SolverOptions pslip_quiet() {
  SolverOptions o;
  o.record_fields = false;
  return o;
}

// I1 = 3.5 is reached at about 1.77 mm, inside the partial slip.
TEST(PartialSlipPuncture, FoundInsideThePartialSlipWhereTheStatesCrossTheCriterion) {
  const double critical = 3.5;
  const Problem p = pslip_puncture_problem(critical);
  const PuncturePrediction found = predict_puncture(p);
  ASSERT_TRUE(found.ok()) << found.message;
  const LoadingCurve curve = loading_curve(p, CurveOptions{.points = 40}, pslip_quiet());
  ASSERT_TRUE(curve.ok()) << curve.message;
  ASSERT_TRUE(curve.stick_slip.full_sliding_depth_mm);
  const double release = curve.stick_slip.depth_mm,
               handover = *curve.stick_slip.full_sliding_depth_mm;
  std::cout << fmt::format(
      "released at {:.9f} mm, full sliding from {:.9f} mm; puncture at {:.12f} mm, {:.12f} N, "
      "I1 {:.12f} ({})\n",
      release,
      handover,
      found.depth_mm,
      found.force_n,
      found.state.max_first_invariant,
      found.crack_location);
  EXPECT_EQ(found.stage, Stage::Slip);
  EXPECT_EQ(found.configuration, Configuration::PartialSlip);
  EXPECT_GT(found.depth_mm, release);
  EXPECT_LT(found.depth_mm, handover);
  EXPECT_NEAR(found.state.max_first_invariant, critical, 1e-9 * critical);
  EXPECT_FALSE(found.crack_location.empty());
  // The states at depths 1e-6 mm either side (the front's root resolves the depth to ~1e-12 mm):
  // below the criterion before, above it after; I1 grows ~0.06 / mm here, so 1e-6 mm moves it by
  // ~6e-8, far above the root's 1e-12.
  const double step_mm = 1e-6;
  const Equilibrium before =
      solve_at_depth(p, found.depth_mm - step_mm, Stage::Slip, pslip_quiet());
  const Equilibrium after = solve_at_depth(p, found.depth_mm + step_mm, Stage::Slip, pslip_quiet());
  ASSERT_TRUE(before.ok() && after.ok()) << before.message << after.message;
  EXPECT_EQ(before.configuration, Configuration::PartialSlip);
  EXPECT_EQ(after.configuration, Configuration::PartialSlip);
  EXPECT_LT(before.max_first_invariant, critical);
  EXPECT_GT(after.max_first_invariant, critical);
  EXPECT_FALSE(before.beyond_puncture);
  EXPECT_TRUE(after.beyond_puncture);
  // The force of the state solved at the reported depth is the puncture's.
  const Equilibrium at = solve_at_depth(p, found.depth_mm, Stage::Slip, pslip_quiet());
  ASSERT_TRUE(at.ok()) << at.message;
  EXPECT_NEAR(at.force_n, found.force_n, 1e-9 * found.force_n);
  // The puncture state's fields, sampled apart from the criterion's samples (16 annulus points,
  // Part I's even samples), reach the same I1: its largest sits at the contact edge, which both
  // sample.
  const auto& f = found.state.fields;
  ASSERT_GT(f.size(), 20u);
  const double fields_i1 = *std::max_element(f.first_invariant.begin(), f.first_invariant.end());
  EXPECT_NEAR(fields_i1, critical, 1e-6 * critical);
  // The curve ends at the puncture, inside the partial slip.
  EXPECT_NEAR(curve.points.back().depth_mm, found.depth_mm, 1e-9 * found.depth_mm);
  EXPECT_EQ(curve.points.back().configuration, Configuration::PartialSlip);
  EXPECT_NEAR(curve.points.back().force_n, found.force_n, 1e-8 * found.force_n);
  EXPECT_NEAR(curve.puncture.depth_mm, found.depth_mm, 1e-12 * found.depth_mm);
}

// As the critical I1 rises through the largest I1 at the hand-over, the puncture moves from the
// partial slip's last states to the sliding model's first: the depths on either side close in
// linearly with the critical value's distance (I1 is continuous across the hand-over, with a
// finite slope on each side).
TEST(PartialSlipPuncture, ContinuousAcrossTheHandOverToSliding) {
  const Problem p = pslip_puncture_problem(95.2);
  const LoadingCurve curve = loading_curve(p, CurveOptions{.max_depth_mm = 4.0}, pslip_quiet());
  ASSERT_TRUE(curve.ok()) << curve.message;
  ASSERT_TRUE(curve.stick_slip.full_sliding_depth_mm);
  const double handover = *curve.stick_slip.full_sliding_depth_mm;
  const Equilibrium sliding = solve_at_depth(p, handover, Stage::Slip, pslip_quiet());
  ASSERT_TRUE(sliding.ok()) << sliding.message;
  ASSERT_NE(sliding.configuration, Configuration::PartialSlip);
  const double i1_handover = sliding.max_first_invariant;
  double gaps[2] = {0.0, 0.0};
  int k = 0;
  for (const double eps : {1e-3, 1e-4}) {
    const PuncturePrediction below =
        predict_puncture(pslip_puncture_problem(i1_handover * (1.0 - eps)), pslip_quiet());
    const PuncturePrediction above =
        predict_puncture(pslip_puncture_problem(i1_handover * (1.0 + eps)), pslip_quiet());
    ASSERT_TRUE(below.ok() && above.ok()) << below.message << above.message;
    std::cout << fmt::format(
        "hand-over {:.9f} mm, I1 {:.9f}; critical -/+ {:g}: {:.9f} mm ({}), {:.9f} mm ({})\n",
        handover,
        i1_handover,
        eps,
        below.depth_mm,
        to_token(below.configuration),
        above.depth_mm,
        to_token(above.configuration));
    EXPECT_EQ(below.configuration, Configuration::PartialSlip);
    EXPECT_NE(above.configuration, Configuration::PartialSlip);
    EXPECT_LT(below.depth_mm, handover);
    EXPECT_GE(above.depth_mm, handover);
    gaps[k++] = above.depth_mm - below.depth_mm;
  }
  // Linear in eps: a tenth of the gap for a tenth of the distance (a jump would not shrink).
  EXPECT_GT(gaps[1] / gaps[0], 0.05);
  EXPECT_LT(gaps[1] / gaps[0], 0.2);
}

}  // namespace
}  // namespace puncture
