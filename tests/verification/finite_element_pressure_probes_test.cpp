// The second method under a gas pressure on the filleted flat punch and the cone (docs/model.md
// §17, §17.2): the finite elements minimise U - p V from their own inflated dome on the probe's
// rigid profile (src/fe/smooth_probe.cpp) and must reproduce the shooting, and `verify` runs them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../solver/solver_test_support.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/finite_element.hpp"
#include "puncture/verification.hpp"

namespace puncture {
namespace fe_pressure_probes_test {

// The paper's Gent membrane (A = 25 mm, J_lim = 125), frictionless, inflated by 0.3 kPa.
Problem inflated_probe(const Indenter& indenter) {
  Problem p = test::paper_problem(Gent{125.0}, 0.0);
  p.indenter = indenter;
  p.preload.pressure_mpa = 3e-4;
  return p;
}

struct ProbeDepths {
  Indenter indenter;
  std::vector<double> depths_mm;
};

// Force, pole (face) stretch, contact edge and largest I1 at depths over each probe's stages
// (128 quadratic elements): the fillet on its face (0.05 mm), on the arc (10 mm) and with the side
// (25, 40 mm); the cone on its tip sphere (2 mm), on the cone (8, 12 mm) and leaving over the kink
// (15.5 mm; the shank at 15.8 mm).  Tolerances as for the sphere and the sharp punch
// (finite_element_pressure_test.cpp): the force to the elements' error, h^4.
TEST(FiniteElementPressureProbes, MatchShootingOnTheFilletAndTheCone) {
  for (const ProbeDepths& c : {ProbeDepths{FlatPunch{2.0, 0.5}, {0.05, 10.0, 25.0, 40.0}},
                               ProbeDepths{Cone{2.0, 30.0, 0.5}, {2.0, 8.0, 12.0, 15.5}}}) {
    SCOPED_TRACE(describe(c.indenter));
    const Problem p = inflated_probe(c.indenter);
    FeOptions options;
    options.elements = 128;
    const std::vector<FeState> fe =
        fe_solve_at_depths(p, c.depths_mm, FeContact::Frictionless, options);
    ASSERT_EQ(fe.size(), c.depths_mm.size());
    for (std::size_t k = 0; k < fe.size(); ++k) {
      SCOPED_TRACE(c.depths_mm[k]);
      ASSERT_TRUE(fe[k].ok()) << fe[k].message;
      const Equilibrium e = solve_at_depth(p, c.depths_mm[k], Stage::Slip, test::tight_options());
      ASSERT_TRUE(e.ok()) << e.message;
      const double force = fe[k].force_n / e.force_n - 1.0;
      const double pole = fe[k].part_three_stretch / e.part_three_stretch - 1.0;
      const double edge =
          fe[k].part_two_top_reference_radius_mm / e.part_two_top_reference_radius_mm - 1.0;
      const double i1 = fe[k].max_first_invariant / e.max_first_invariant - 1.0;
      std::printf("%s %.3g mm: force %.2e, pole %.2e, edge %.2e, I1 %.2e\n",
                  describe(c.indenter).c_str(),
                  c.depths_mm[k],
                  force,
                  pole,
                  edge,
                  i1);
      EXPECT_LT(std::abs(force), 3e-6);
      EXPECT_LT(std::abs(pole), 5e-4);
      EXPECT_LT(std::abs(edge), 1e-3);
      EXPECT_LT(std::abs(i1), 3e-3);
      EXPECT_EQ(fe[k].part_two, e.configuration == Configuration::SlipWithPartTwo);
    }
  }
}

// `verify --pressure` on both probes: every row passes (32 elements, two depths; the tolerances
// scale with the elements' own error).
TEST(FiniteElementPressureProbes, VerifyRunsOnTheFilletAndTheCone) {
  for (const Indenter& indenter : {Indenter{FlatPunch{2.0, 0.5}}, Indenter{Cone{2.0, 30.0, 0.5}}}) {
    SCOPED_TRACE(describe(indenter));
    VerifyOptions options;
    options.elements = 32;
    options.depths = 2;
    const VerificationReport report = verify(inflated_probe(indenter), options);
    EXPECT_TRUE(report.ok()) << report.message;
    int dome_rows = 0;
    for (const VerificationCheck& c : report.checks) {
      EXPECT_EQ(c.verdict, Verdict::Pass) << c.group << " " << c.quantity << " " << c.condition
                                          << ": " << c.difference << " " << c.note;
      dome_rows += c.group == "inflated dome";
    }
    EXPECT_EQ(dome_rows, 3);
  }
}

}  // namespace fe_pressure_probes_test
}  // namespace puncture
