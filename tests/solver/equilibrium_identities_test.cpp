// Identities every equilibrium must satisfy, checked on the fields solve_at_force returns (in
// physical units), independently of how the solver reached them: the vertical balance of Part I,
// the slope against the shape, the clamp, continuity across the part boundaries, the capstan law
// at the corner, and Part II's ring balance and contact pressure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

struct Case {
  std::string name;
  MaterialLaw law;
  double friction;
  Stage stage;
  double f;  // normalised force F / (2 pi G H A)
  Configuration expected;
};

std::string case_name(const ::testing::TestParamInfo<Case>& info) { return info.param.name; }
void PrintTo(const Case& c, std::ostream* os) { *os << c.name << " at f = " << c.f; }

const Gent kGent{125.0};
const NeoHookean kNeo{};
const MooneyRivlin kMooney{0.2};

// Forces picked (by a scan of solve_at_force) to land in each configuration for each law.
const std::vector<Case> kStickCases = {
    {"GentStick", kGent, 0.18, Stage::Stick, 0.3, Configuration::Stick},
    {"NeoHookeanStick", kNeo, 0.18, Stage::Stick, 0.3, Configuration::Stick},
    {"MooneyRivlinStick", kMooney, 0.18, Stage::Stick, 0.3, Configuration::Stick},
};
const std::vector<Case> kSlipWithoutCases = {
    {"GentSlipWithoutPartTwo", kGent, 0.18, Stage::Slip, 0.1, Configuration::SlipWithoutPartTwo},
    {"GentDrySlipWithoutPartTwo", kGent, 1.95, Stage::Slip, 0.1, Configuration::SlipWithoutPartTwo},
    {"NeoHookeanSlipWithoutPartTwo",
     kNeo,
     0.18,
     Stage::Slip,
     0.1,
     Configuration::SlipWithoutPartTwo},
    {"MooneyRivlinSlipWithoutPartTwo",
     kMooney,
     0.18,
     Stage::Slip,
     0.1,
     Configuration::SlipWithoutPartTwo},
};
const std::vector<Case> kSlipWithCases = {
    {"GentSlipWithPartTwo", kGent, 0.18, Stage::Slip, 0.5, Configuration::SlipWithPartTwo},
    {"GentDrySlipWithPartTwo", kGent, 1.95, Stage::Slip, 2.0, Configuration::SlipWithPartTwo},
    {"NeoHookeanSlipWithPartTwo", kNeo, 0.18, Stage::Slip, 0.115, Configuration::SlipWithPartTwo},
    {"MooneyRivlinSlipWithPartTwo",
     kMooney,
     0.18,
     Stage::Slip,
     0.5,
     Configuration::SlipWithPartTwo},
};

std::vector<Case> join(std::initializer_list<std::vector<Case>> lists) {
  std::vector<Case> out;
  for (const auto& l : lists) out.insert(out.end(), l.begin(), l.end());
  return out;
}

class EquilibriumFixture : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    const Case& c = GetParam();
    problem_ = paper_problem(c.law, c.friction);
    e_ = solve_at_force(problem_, force_at(problem_, c.f), c.stage);
    ASSERT_TRUE(e_.ok()) << to_string(e_.status) << ": " << e_.message;
    ASSERT_EQ(e_.configuration, c.expected) << to_string(e_.configuration);
    one_ = part_indices(e_.fields, 1);
    two_ = part_indices(e_.fields, 2);
    three_ = part_indices(e_.fields, 3);
    ASSERT_FALSE(one_.empty());
    ASSERT_FALSE(three_.empty());
    ASSERT_EQ(two_.empty(), c.expected != Configuration::SlipWithPartTwo);
  }
  const MembraneFields& m() const { return e_.fields; }
  // First sample outside Part III: the material just outside the corner.
  std::size_t corner_outside() const { return two_.empty() ? one_.front() : two_.front(); }

  Problem problem_;
  Equilibrium e_;
  std::vector<std::size_t> one_, two_, three_;
};

class AnyConfiguration : public EquilibriumFixture {};
class SlipConfiguration : public EquilibriumFixture {};
class PartTwoConfiguration : public EquilibriumFixture {};

INSTANTIATE_TEST_SUITE_P(
    Solver, AnyConfiguration,
    ::testing::ValuesIn(join({kStickCases, kSlipWithoutCases, kSlipWithCases})), case_name);
INSTANTIATE_TEST_SUITE_P(Solver, SlipConfiguration,
                         ::testing::ValuesIn(join({kSlipWithoutCases, kSlipWithCases})), case_name);
INSTANTIATE_TEST_SUITE_P(Solver, PartTwoConfiguration, ::testing::ValuesIn(kSlipWithCases),
                         case_name);

// Eq. (12): the membrane inside radius R carries the whole indenter force vertically,
// 2 pi R H s1 sin(phi) = F, at every point of Part I.  The solver integrates t = R s1 cos(phi)
// and lambda1 separately, so this holds only to the accumulated integration error: ten times the
// local relative tolerance of 1e-10, 1e-9 relative, allows for its accumulation over the steps.
TEST_P(AnyConfiguration, VerticalForceBalanceInPartOne) {
  const double h = problem_.geometry.thickness_mm;
  double worst = 0.0;
  for (std::size_t i : one_) {
    const double vertical = 2.0 * kPi * m().reference_radius_mm[i] * h * m().radial_stress_mpa[i] *
                            std::sin(m().slope_rad[i]);
    worst = std::max(worst, std::abs(vertical / e_.force_n - 1.0));
  }
  EXPECT_LE(worst, 1e-9) << "largest relative imbalance";
  record("max_relative_imbalance", worst);
}

// The slope reported by the solver against the shape (r, z): on each interval of Part I the
// chord's angle atan(-dz/dr) is compared with the mean of the end slopes.  For a smooth curve
// phi(s) the chord angle is the mean of phi over the interval, phi_mid + phi'' ds^2 / 24, the
// mean of the ends phi_mid + phi'' ds^2 / 8: they differ by |phi''| ds^2 / 12.  The tolerance is
// three times that leading term, with phi'' from the neighbouring samples, plus 1e-9 rad for the
// round-off of differencing z and r (~1e-13 mm over ds >= 1e-4 mm) and the integration's noise.
// The comparison is on angles, not dz/dr = tan(phi), which is unbounded where Part I leaves the
// indenter vertically.
TEST_P(AnyConfiguration, SlopeAgreesWithShape) {
  ASSERT_GE(one_.size(), 200u) << "too few Part I samples to difference";
  const auto& r = m().radius_mm;
  const auto& z = m().deflection_mm;
  const auto& phi = m().slope_rad;
  const std::size_t n = one_.size();
  std::vector<double> ds(n - 1), chord(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const std::size_t i = one_[k], j = one_[k + 1];
    const double dr = r[j] - r[i], dz = z[i] - z[j];  // z falls outward
    ds[k] = std::hypot(dr, dz);
    chord[k] = std::atan2(dz, dr);
  }
  // |phi''| at each interior sample, from the three-point formula on the nonuniform grid.
  std::vector<double> curvature_rate(n, 0.0);
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double left = (phi[one_[k]] - phi[one_[k - 1]]) / ds[k - 1];
    const double right = (phi[one_[k + 1]] - phi[one_[k]]) / ds[k];
    curvature_rate[k] = std::abs(2.0 * (right - left) / (ds[k - 1] + ds[k]));
  }
  double worst_ratio = 0.0, worst_error = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double mean_slope = 0.5 * (phi[one_[k]] + phi[one_[k + 1]]);
    double second = curvature_rate[k];
    second = std::max(second, curvature_rate[k + 1]);
    if (k > 0) second = std::max(second, curvature_rate[k - 1]);
    if (k + 2 < n) second = std::max(second, curvature_rate[k + 2]);
    const double tol = 3.0 * second * ds[k] * ds[k] / 12.0 + 1e-9;
    const double error = std::abs(chord[k] - mean_slope);
    EXPECT_LE(error, tol) << "interval " << k
                          << " of Part I, R = " << m().reference_radius_mm[one_[k]] << " mm";
    worst_ratio = std::max(worst_ratio, error / tol);
    worst_error = std::max(worst_error, error);
  }
  record("worst_error_over_tolerance", worst_ratio);
  record("worst_slope_error_rad", worst_error);
}

// Eq. (24): the last sample is the clamped edge, R = r = A, z = 0, lambda2 = 1.  lambda2 is the
// shooting's residual, accepted at 1e-10 (up to 100 x that when the bracket collapses): 1e-8.
// z(A) = depth - (Part II length + Part I rise) is zero up to round-off on a ~100 mm depth.
TEST_P(AnyConfiguration, ClampCondition) {
  const std::size_t last = m().size() - 1;
  const double big_a = problem_.geometry.clamp_radius_mm;
  EXPECT_EQ(m().part[last], MembranePart::Free);
  EXPECT_NEAR(m().reference_radius_mm[last], big_a, 1e-12 * big_a);
  EXPECT_NEAR(m().hoop_stretch[last], 1.0, 1e-8);
  EXPECT_NEAR(m().radius_mm[last], big_a, 1e-8 * big_a);
  EXPECT_NEAR(m().deflection_mm[last], 0.0, 1e-12 * std::max(1.0, e_.depth_mm));
  EXPECT_LE(e_.clamp_residual, 1e-8);
}

// Continuity across the part boundaries (all built from the same numbers, so round-off only:
// 1e-12 relative).  At the corner: r = a on both sides, lambda2 continuous (= Lambda) since R is
// continuous across a sharp corner, z = depth; along Part II, r = a and phi = pi/2; at the Part
// I/II boundary: R, lambda1, lambda2 and z continuous and phi = pi/2.
TEST_P(AnyConfiguration, ContinuityAtPartBoundaries) {
  const double a = radius_mm(problem_.indenter);
  const double depth = e_.depth_mm;
  constexpr double kRel = 1e-12;
  const std::size_t tip_edge = three_.back(), out = corner_outside();
  // Part III is flat, equibiaxial, at the tip's depth.
  for (std::size_t i : three_) {
    EXPECT_NEAR(m().deflection_mm[i], depth, kRel * depth);
    EXPECT_DOUBLE_EQ(m().radial_stretch[i], e_.part_three_stretch);
    EXPECT_DOUBLE_EQ(m().hoop_stretch[i], e_.part_three_stretch);
  }
  EXPECT_NEAR(m().reference_radius_mm[tip_edge],
              e_.corner_reference_radius_mm,
              kRel * e_.corner_reference_radius_mm);
  EXPECT_NEAR(m().radius_mm[tip_edge], a, kRel * a);
  EXPECT_NEAR(m().radius_mm[out], a, kRel * a);
  EXPECT_NEAR(m().reference_radius_mm[out],
              m().reference_radius_mm[tip_edge],
              kRel * e_.corner_reference_radius_mm);
  EXPECT_NEAR(m().hoop_stretch[out], m().hoop_stretch[tip_edge], kRel * e_.part_three_stretch);
  EXPECT_NEAR(m().deflection_mm[out], depth, kRel * depth);
  if (e_.configuration == Configuration::Stick) {
    EXPECT_EQ(e_.part_three_stretch, 1.0);
    EXPECT_NEAR(e_.corner_reference_radius_mm, a, kRel * a);
  }
  if (two_.empty()) {
    EXPECT_NEAR(m().slope_rad[out], e_.corner_slope_rad, 1e-12);
    return;
  }
  for (std::size_t i : two_) {
    EXPECT_NEAR(m().radius_mm[i], a, kRel * a) << "Part II leaves the indenter's side";
    EXPECT_NEAR(m().slope_rad[i], kHalfPi, 1e-12);
  }
  const std::size_t top = two_.back(), start = one_.front();
  EXPECT_NEAR(m().reference_radius_mm[start],
              m().reference_radius_mm[top],
              kRel * m().reference_radius_mm[top]);
  EXPECT_NEAR(m().reference_radius_mm[start],
              e_.part_two_top_reference_radius_mm,
              kRel * m().reference_radius_mm[top]);
  EXPECT_NEAR(m().radial_stretch[start], m().radial_stretch[top], kRel * m().radial_stretch[top]);
  EXPECT_NEAR(m().hoop_stretch[start], m().hoop_stretch[top], kRel * m().hoop_stretch[top]);
  EXPECT_NEAR(m().deflection_mm[start], m().deflection_mm[top], kRel * depth);
  EXPECT_NEAR(m().deflection_mm[top], depth - e_.part_two_length_mm, kRel * depth);
  EXPECT_NEAR(m().slope_rad[start], kHalfPi, 1e-12);
}

// The capstan law (M3) across the corner: s1 just outside / s1 in Part III = exp(mu theta) with
// theta the wrap angle, the exit slope without Part II and pi/2 with it.  Without Part II the
// exit slope solves sin(phi) exp(mu phi) = kappa to machine precision and lambda1 comes from an
// inversion converged to ~1e-15; with Part II the corner is located by a root search that the
// solver accepts at a capstan mismatch of 1e-8 relative: 1e-8 covers both.
TEST_P(SlipConfiguration, CapstanRatioAtCorner) {
  const double mu = problem_.friction;
  const std::size_t out = corner_outside();
  const double s1_tip = m().radial_stress_mpa[three_.back()];
  EXPECT_NEAR(s1_tip, equibiaxial_stress_mpa(problem_, e_.part_three_stretch), 1e-12 * s1_tip);
  const double wrap = two_.empty() ? m().slope_rad[out] : kHalfPi;
  const double expected = std::exp(mu * wrap);
  const double ratio = m().radial_stress_mpa[out] / s1_tip;
  EXPECT_NEAR(ratio / expected, 1.0, 1e-8) << "wrap angle " << wrap;
  EXPECT_NEAR(e_.corner_tension_ratio / expected, 1.0, 1e-8);
  if (two_.empty()) {
    EXPECT_GT(wrap, 0.0);
    EXPECT_LT(wrap, kHalfPi);
    // The exit slope is also the one Part I starts with in the fields.
    EXPECT_NEAR(e_.corner_slope_rad, wrap, 1e-12);
  }
  record("capstan_relative_error", std::abs(ratio / expected - 1.0));
}

// Part II's ring balance (M2), d(R s1)/dR = mu s2, by finite differences of the fields: on each
// interval the difference quotient of Q = R s1 against mu times the mean of s2 at its ends, both
// centred, differ by dR^2 (Q''' / 24 - mu s2'' / 8) = -mu s2'' dR^2 / 12 (Q''' = mu s2''); the
// tolerance is three times that, with s2'' from neighbouring samples, plus the integration noise in
// Q (1e-10 relative per step) divided by dR.  The printed Eq. (18) would differ by s1, far outside.
TEST_P(PartTwoConfiguration, RingBalanceOnTheSide) {
  const double mu = problem_.friction;
  const auto& big_r = m().reference_radius_mm;
  const auto& s1 = m().radial_stress_mpa;
  const auto& s2 = m().hoop_stress_mpa;
  const std::size_t n = two_.size();
  ASSERT_GE(n, 10u);
  std::vector<double> second(n, 0.0);
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const std::size_t i = two_[k - 1], j = two_[k], l = two_[k + 1];
    const double left = (s2[j] - s2[i]) / (big_r[j] - big_r[i]);
    const double right = (s2[l] - s2[j]) / (big_r[l] - big_r[j]);
    second[k] = std::abs(2.0 * (right - left) / (big_r[l] - big_r[i]));
  }
  double worst_ratio = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const std::size_t i = two_[k], j = two_[k + 1];
    const double dr = big_r[j] - big_r[i];
    ASSERT_GT(dr, 0.0) << "Part II samples must run up the side";
    const double q_i = big_r[i] * s1[i], q_j = big_r[j] * s1[j];
    const double lhs = (q_j - q_i) / dr;
    const double rhs = mu * 0.5 * (s2[i] + s2[j]);
    const double s2pp = std::max(
        {second[k], second[k + 1], k > 0 ? second[k - 1] : 0.0, k + 2 < n ? second[k + 2] : 0.0});
    const double tol = 3.0 * mu * s2pp * dr * dr / 12.0 + 1e-10 * std::abs(q_j) / dr + 1e-12;
    EXPECT_NEAR(lhs, rhs, tol) << "interval " << k << " of Part II, R = " << big_r[i] << " mm";
    worst_ratio = std::max(worst_ratio, std::abs(lhs - rhs) / tol);
  }
  record("worst_error_over_tolerance", worst_ratio);
}

// Eq. (16): the contact pressure on the side is the hoop line tension over the indenter's
// radius, P = s2 H / (lambda1 a), and the friction traction mu P; zero off the side.  Recomputed
// from the other fields: round-off only, 1e-12 relative.
TEST_P(PartTwoConfiguration, ContactPressureFromHoopTension) {
  const double h = problem_.geometry.thickness_mm, a = radius_mm(problem_.indenter);
  for (std::size_t i : two_) {
    const double p = m().hoop_stress_mpa[i] * h / (m().radial_stretch[i] * a);
    EXPECT_GT(p, 0.0) << "the side must press on the membrane";
    EXPECT_NEAR(m().contact_pressure_mpa[i], p, 1e-12 * p);
    EXPECT_NEAR(m().friction_traction_mpa[i], problem_.friction * p, 1e-12 * p);
  }
  for (std::size_t i : one_) EXPECT_EQ(m().contact_pressure_mpa[i], 0.0);
  for (std::size_t i : three_) EXPECT_EQ(m().contact_pressure_mpa[i], 0.0);
}

}  // namespace
}  // namespace puncture::test
