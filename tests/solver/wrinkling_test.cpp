// Wrinkling (docs/model.md §17): where the hoop stress would turn compressive the tension-only
// membrane theory no longer holds, and such a state is reported as Status::Wrinkles with the
// place, never as numbers.  The detector's sign rule against the laws' own stresses, its use on
// an integrated Part I, the status of a judged state, and no false alarm on the paper's states.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "indentation/dispatch.hpp"
#include "indentation/free_part.hpp"
#include "indentation/physical_state.hpp"
#include "solver_test_support.hpp"

namespace puncture::detail {
namespace {

std::vector<MaterialLaw> laws() {
  return {Gent{125.0},
          Gent{20.0},
          NeoHookean{},
          MooneyRivlin{0.1},
          MooneyRivlin{0.5},
          Yeoh{0.05, 0.001},
          std::get<Ogden>(ogden_material({0.63, 0.0012, -0.01}, {1.3, 5.0, -2.0}).law),
          ArrudaBoyce{50.0},
          GentGent{125.0, 0.2}};
}

// hoop_compressive(l1, l2) is the sign of s2 for every law: s2 = 2 (l2 - 1 / (l1^2 l2^3)) (W1 +
// l1^2 W2) with W1 + l1^2 W2 > 0.  Checked against membrane_stress on a grid of stretches in
// [0.3, 6]^2 (away from s2 = 0, where rounding decides: |l1^2 l2^4 - 1| > 1e-9).
TEST(Wrinkling, TheSignRuleIsTheHoopStresssSignForEveryLaw) {
  int compressive = 0, checked = 0;
  for (const auto& law : laws()) {
    const double locking = locking_first_invariant(law);
    for (double l1 = 0.3; l1 <= 6.0; l1 *= 1.07) {
      for (double l2 = 0.3; l2 <= 6.0; l2 *= 1.07) {
        if (!(first_invariant(l1, l2) < locking)) continue;
        if (std::abs(l1 * l1 * l2 * l2 * l2 * l2 - 1.0) < 1e-9) continue;
        const double s2 = membrane_stress(law, l1, l2).s2;
        EXPECT_EQ(hoop_compressive(l1, l2), s2 < 0.0) << describe(law) << " " << l1 << " " << l2;
        compressive += s2 < 0.0;
        ++checked;
      }
    }
  }
  EXPECT_GT(compressive, 100);  // the grid covers both signs
  EXPECT_GT(checked, 5000);
}

// Part I started hoop-compressed (lambda1 = 2, lambda2 = 0.6: l1^2 l2^4 = 0.52) reports that
// place when its largest I1 is searched (the final states), not in the shooting's iterations.
TEST(Wrinkling, PartIReportsWhereTheHoopStressIsCompressive) {
  const Gent law{125.0};
  SolverOptions o;
  const FreePart<Gent> part(law, shooting_settings(o));
  const double r0 = 0.1, f = 0.05;
  const auto st = membrane_stress(law, 2.0, 0.6);
  const FreeStart compressed{{r0 * st.s1, 2.0, 0.6, 0.0}, r0, 0.0, 1.0};
  const auto searched = part.run(f, compressed, nullptr, true);
  EXPECT_EQ(searched.wrinkle_r, r0);
  EXPECT_NEAR(searched.wrinkle_radius, 0.6 * r0, 1e-15);
  const auto iteration = part.run(f, compressed, nullptr, false);
  EXPECT_EQ(iteration.wrinkle_r, -1.0);
  // A taut start (lambda2 = 1.2) wrinkles nowhere.
  const auto taut = membrane_stress(law, 1.5, 1.2);
  const FreeStart tensile{{r0 * taut.s1, 1.5, 1.2, 0.0}, r0, 0.0, 1.0};
  EXPECT_EQ(part.run(f, tensile, nullptr, true).wrinkle_r, -1.0);
}

// A converged state that wrinkles is not Converged: accept_collapsed_bracket (the shooting's
// last step) keeps the wrinkle, and the physical state says where, in mm.
TEST(Wrinkling, AWrinkledStateIsAStatusWithThePlace) {
  ScaledSolution sol;
  sol.status = Status::NoConvergence;
  sol.integrated = true;
  sol.shooting_tol = 1e-10;
  sol.residual = 1e-9;
  sol.wrinkle_r = 0.2;
  sol.wrinkle_radius = 0.15;
  accept_collapsed_bracket(sol);
  EXPECT_EQ(sol.status, Status::Wrinkles);
  EXPECT_EQ(failure_kind(sol.status), FailureKind::Physical);
  Problem p;
  SolverOptions o;
  o.record_fields = false;
  const auto e = with_shooting(p, o, [&](const auto& shooting) {
    return to_physical(p, shooting.contact(), sol, Stage::Slip, o);
  });
  EXPECT_EQ(e.status, Status::Wrinkles);
  EXPECT_NE(e.message.find("R = 5 mm"), std::string::npos) << e.message;  // 0.2 A, A = 25 mm
  EXPECT_NE(e.message.find("wrinkles"), std::string::npos) << e.message;
}

// No false alarm: the paper's states (flat punch and sphere, lubricated, frictionless, held,
// pre-stretched, inflated) along their loading paths are taut everywhere (s2 = 0 exactly only in
// the held membrane under the tip, which stays unstretched).
TEST(Wrinkling, ThePapersStatesAreTaut) {
  std::vector<Problem> problems(6, test::paper_problem());
  problems[1].friction = 0.0;
  problems[2].stick = {StickRule::Always, 0.0};
  problems[3].preload.prestretch = 1.3;
  problems[4].indenter = SphereTipped{2.0};
  problems[4].friction = 0.0;
  problems[5].preload.pressure_mpa = 3e-4;
  problems[5].friction = 0.0;
  for (const auto& p : problems) {
    for (const double depth : {1.0, 10.0, 25.0}) {
      const Stage stage = p.stick.rule == StickRule::Always ? Stage::Stick : Stage::Slip;
      const auto e = solve_at_depth(p, depth, stage);
      EXPECT_TRUE(e.ok()) << describe(p.indenter) << " at " << depth << " mm: " << e.message;
      for (const double s2 : e.fields.hoop_stress_mpa) EXPECT_GE(s2, 0.0);
    }
  }
}

}  // namespace
}  // namespace puncture::detail
