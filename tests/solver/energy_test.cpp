// Energy identity, an independent check of force against depth: where the process is
// conservative (no friction work), the work of the indenter along the loading curve equals the
// elastic energy stored in the membrane,
//   int_0^depth F ddepth = U = 2 pi H int_0^A W(lambda1, lambda2) R dR.
// The left side uses only the curve's forces, the right side only the deformation fields of one
// equilibrium at the final depth; neither uses the other's numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

struct EnergyCase {
  std::string name;
  Problem problem;
  Stage stage;
  double depth_mm;
  Configuration expected;
};
void PrintTo(const EnergyCase& c, std::ostream* os) { *os << c.name; }

Problem frictionless_sliding() { return paper_problem(Gent{125.0}, 0.0); }
Problem always_held() {
  Problem p = paper_problem();
  p.stick = {StickRule::Always, 0.0};
  return p;
}
Problem prestretched(Problem p) {
  p.preload.prestretch = 1.25;
  return p;
}

class EnergyIdentity : public ::testing::TestWithParam<EnergyCase> {};

// Frictionless sliding (mu' = 0: the corner and the side do no work) before and after the onset
// of Part II (13.4 mm), and the fully held membrane (StickRule::Always: the material at the
// indenter's edge does not move relative to it), puncture at 33.8 mm and 118 mm respectively.
INSTANTIATE_TEST_SUITE_P(
    Energy, EnergyIdentity,
    ::testing::Values(
        EnergyCase{"SlidingWithoutPartTwo",
                   frictionless_sliding(),
                   Stage::Slip,
                   10.0,
                   Configuration::SlipWithoutPartTwo},
        EnergyCase{"SlidingWithoutPartTwoAt8mm",
                   frictionless_sliding(),
                   Stage::Slip,
                   8.0,
                   Configuration::SlipWithoutPartTwo},
        EnergyCase{"SlidingWithPartTwo",
                   frictionless_sliding(),
                   Stage::Slip,
                   30.0,
                   Configuration::SlipWithPartTwo},
        EnergyCase{"HeldShallow", always_held(), Stage::Stick, 10.0, Configuration::Stick},
        EnergyCase{"HeldDeep", always_held(), Stage::Stick, 30.0, Configuration::Stick},
        // Pre-stretched by 1.25: the work is the energy stored beyond the flat pre-stretched
        // membrane's.
        EnergyCase{"PrestretchedSliding",
                   prestretched(frictionless_sliding()),
                   Stage::Slip,
                   4.0,
                   Configuration::SlipWithoutPartTwo},
        EnergyCase{"PrestretchedSlidingWithPartTwo",
                   prestretched(frictionless_sliding()),
                   Stage::Slip,
                   30.0,
                   Configuration::SlipWithPartTwo},
        EnergyCase{"PrestretchedHeld",
                   prestretched(always_held()),
                   Stage::Stick,
                   20.0,
                   Configuration::Stick}),
    [](const auto& info) { return info.param.name; });

// Stored energy [mJ] of an equilibrium from its fields: Part III exactly, Parts II and I by the
// trapezoid rule with Richardson extrapolation; `error` is the estimated error of the plain
// trapezoid value, (U_h - U_2h) / 3.
struct StoredEnergy {
  double value;
  double error;
};
StoredEnergy stored_energy(const Problem& p, const Equilibrium& e) {
  const auto& m = e.fields;
  const double scale = 2.0 * kPi * p.geometry.thickness_mm;
  const double r_b = e.corner_reference_radius_mm, lambda = e.part_three_stretch;
  const double u_tip = scale * energy_density_mpa(p, lambda, lambda) * 0.5 * r_b * r_b;
  std::vector<double> r, integrand;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m.part[i] == MembranePart::Tip) continue;
    r.push_back(m.reference_radius_mm[i]);
    integrand.push_back(energy_density_mpa(p, m.radial_stretch[i], m.hoop_stretch[i]) * r.back());
  }
  for (std::size_t i = 1; i < r.size(); ++i) EXPECT_GE(r[i], r[i - 1]);
  const double t_fine = trapezoid(r, integrand, 1), t_coarse = trapezoid(r, integrand, 2);
  return {u_tip + scale * (t_fine + (t_fine - t_coarse) / 3.0),
          scale * std::abs(t_fine - t_coarse) / 3.0};
}

// Work [mJ] along a curve of equally spaced depths (odd number of points) by Simpson's rule, and
// its error bound |S_h - S_2h| from Simpson on every other point.
struct Work {
  double value;
  double error;
};
Work simpson_work(const LoadingCurve& curve) {
  const std::size_t n = curve.points.size() - 1;  // intervals, even
  EXPECT_EQ(n % 2, 0u);
  const double h = curve.points.back().depth_mm / static_cast<double>(n);
  double fine = 0.0, coarse = 0.0;
  for (std::size_t k = 0; k <= n; ++k) {
    const auto& pt = curve.points[k];
    EXPECT_NEAR(pt.depth_mm, static_cast<double>(k) * h, 1e-12 * curve.points.back().depth_mm)
        << "depths must be equally spaced";
    const bool end = k == 0 || k == n;
    fine += (end ? 1.0 : (k % 2 ? 4.0 : 2.0)) * pt.force_n;
    if (k % 2 == 0) coarse += (end ? 1.0 : ((k / 2) % 2 ? 4.0 : 2.0)) * pt.force_n;
  }
  fine *= h / 3.0;
  coarse *= 2.0 * h / 3.0;
  return {fine, std::abs(fine - coarse)};
}

LoadingCurve curve_to(const Problem& p, double depth_mm) {
  CurveOptions options;
  options.points = 401;
  options.max_depth_mm = depth_mm;
  return loading_curve(p, options);
}

Equilibrium finely_sampled(const Problem& p, double depth_mm, Stage stage) {
  SolverOptions fine;
  fine.field_points = 1000;
  return solve_at_depth(p, depth_mm, stage, fine);
}

// Tolerance from the two quadratures.  Work: Simpson's rule on the curve's 401 equally spaced
// depths; its error is bounded by the difference from Simpson on every other point (S_h - S_2h
// is 15 times the error where F is smooth, and still bounds it across the kink of dF/ddepth at
// the onset of Part II).  Energy: Part III (homogeneous) exactly, W(Lambda, Lambda) R_b^2 / 2;
// Parts II and I by the trapezoid rule on >= 1000 samples, whose O(h^2) error, estimated by
// (U_h - U_2h) / 3 from every other sample, is removed by Richardson extrapolation; a tenth of
// that estimate is allowed for the O(h^4) remainder and the unevenness of the adaptive samples.
// The solver's 1e-8 relative accuracy of each force and state adds 2e-8 relative.
TEST_P(EnergyIdentity, WorkEqualsStoredEnergy) {
  const EnergyCase& c = GetParam();
  const auto curve = curve_to(c.problem, c.depth_mm);
  ASSERT_TRUE(curve.ok()) << curve.message;
  ASSERT_FALSE(curve.stick_slip.occurs);
  for (const auto& pt : curve.points) ASSERT_EQ(pt.stage, c.stage);
  const Work work = simpson_work(curve);

  const auto e = finely_sampled(c.problem, c.depth_mm, c.stage);
  ASSERT_TRUE(e.ok()) << e.message;
  ASSERT_EQ(e.configuration, c.expected) << to_string(e.configuration);
  ASSERT_GE(e.fields.size(), 1000u);
  StoredEnergy energy = stored_energy(c.problem, e);
  // The flat membrane at its pre-stretch L0 (none: zero) stores W(L0, L0) over the stress-free
  // disc of radius A / L0 before the indenter touches it.
  const double l0 = c.problem.preload.prestretch, r_free = reference_clamp_radius_mm(c.problem);
  energy.value -= 2.0 * kPi * c.problem.geometry.thickness_mm *
                  energy_density_mpa(c.problem, l0, l0) * 0.5 * r_free * r_free;

  const double tol = work.error + 0.1 * energy.error + 2e-8 * work.value;
  EXPECT_NEAR(energy.value, work.value, tol)
      << "work " << work.value << " mJ, stored energy " << energy.value << " mJ";
  record("work_mj", work.value);
  record("relative_difference", std::abs(energy.value / work.value - 1.0));
  record("difference_over_tolerance", std::abs(energy.value - work.value) / tol);
  record("trapezoid_error_estimate_relative", energy.error / work.value);
}

// Negative control: with friction (mu' = 0.18) the indenter's work exceeds the stored energy by
// what friction dissipates on the corner and the side.  The same quadratures, accurate to well
// below 1e-6 relative (above), must show a deficit of the stored energy far larger than that:
// more than 1e-4 relative.
TEST(EnergyWithFriction, WorkExceedsStoredEnergy) {
  const Problem p = paper_problem(Gent{125.0}, 0.18);
  const double depth = 30.0;
  const auto curve = curve_to(p, depth);
  ASSERT_TRUE(curve.ok()) << curve.message;
  const Work work = simpson_work(curve);
  const auto e = finely_sampled(p, depth, Stage::Slip);
  ASSERT_TRUE(e.ok()) << e.message;
  const StoredEnergy energy = stored_energy(p, e);
  EXPECT_GT(work.value - energy.value, 1e-4 * work.value)
      << "work " << work.value << " mJ, stored " << energy.value << " mJ";
  record("dissipated_fraction", (work.value - energy.value) / work.value);
}

}  // namespace
}  // namespace puncture::test
