// A second indenter plugs into the shooting and the loading-curve driver without changing them: a
// test-only contact model, a rigid disc bonded to the membrane (the membrane is held at the disc's
// edge in every stage), written here from the held-edge conditions alone.  Its loading curve and
// puncture, computed by the unchanged driver, must be the flat punch's with the membrane always
// held (--stick always): the same physics reached through another contact model.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "indentation/curve_following.hpp"
#include "indentation/dispatch.hpp"
#include "indentation/shooting.hpp"
#include "mechanics/inverse_stretch.hpp"
#include "solver_test_support.hpp"

namespace puncture::detail {
namespace {

struct BondedDiscSettings {
  double a;  // disc radius / clamp radius
};

// The membrane bonded to a rigid disc of radius a: no material crosses the disc's edge, so Part I
// starts at R = a with lambda2 = 1; its shooting parameter is lambda1 there.
template <class Law>
class BondedDiscContact {
 public:
  using law_type = Law;
  using Settings = BondedDiscSettings;

  BondedDiscContact(const FreePart<Law>& part_one, const BondedDiscSettings& settings)
      : part_one_(part_one), a_(settings.a) {}

  double parameter_floor(Configuration) const { return 1.0; }

  std::optional<FreeStart> free_start(Configuration, double f, double l1) const {
    if (!(l1 > 0.0) || !std::isfinite(l1)) return std::nullopt;
    const auto st = membrane_stress(part_one_.law(), l1, 1.0);
    if (!(st.i1 < part_one_.locking_i1())) return std::nullopt;
    const double rs1 = a_ * st.s1;  // R s1 = sqrt(t^2 + f^2): the vertical balance fixes t
    if (!(rs1 >= f * (1.0 - 1e-8))) return std::nullopt;
    const double t = std::sqrt(std::max(0.0, (rs1 - f) * (rs1 + f)));
    return FreeStart{{t, l1, 1.0, 0.0}, a_, std::atan2(f, t), kUnbounded};
  }

  bool attach(Configuration, const FreeStart&, double, bool, ScaledSolution& sol) const {
    sol.r_corner = a_;  // the disc's face carries the membrane unstretched
    return true;
  }

  template <class Residual>
  ShootingPlan plan(Stage, double f, Residual&& counted) const {
    ShootingPlan plan;
    plan.configuration = Configuration::Stick;
    // From the vertical exit (R s1 = f at the edge) up to the locking stretch.
    auto l1 = invert_radial_stress(part_one_.law(), f / a_, 1.0);
    while (l1 && a_ * membrane_stress(part_one_.law(), *l1, 1.0).s1 < f)
      l1 = std::nextafter(*l1, 2.0 * *l1);
    const double g = l1 ? counted(Configuration::Stick, *l1).value_or(1.0) : 1.0;
    if (!(g < 0.0)) {
      plan.status = Status::StickWrapsSide;
      plan.message = "the bonded membrane cannot carry this force";
      return plan;
    }
    plan.lo = *l1;
    plan.g_lo = g;
    plan.cap = locking_radial_stretch(part_one_.law(), 1.0);
    plan.no_root_message = "no edge stretch meets the clamp condition";
    return plan;
  }

  ScaledSolution unloaded(bool) const {
    ScaledSolution flat;
    flat.status = Status::Converged;
    flat.r_corner = flat.r_top = a_;
    return flat;
  }

  Configuration configuration(Stage, bool) const { return Configuration::Stick; }
  template <class Shooting>
  std::optional<ScaledSolution> slip_change(const Shooting&) const {
    return std::nullopt;
  }
  template <class Shooting>
  std::optional<ScaledSolution> direct_puncture(const Shooting&, double,
                                                std::optional<double> = {}) const {
    return std::nullopt;
  }
  std::string crack_location(const ScaledSolution&) const { return "Part I"; }

  // I1 is largest in the free membrane (the disc's face is unstretched).
  LargestFirstInvariant largest_first_invariant(const ScaledSolution& sol) const {
    return {MembranePart::Free, sol.max_i1_r, sol.max_i1_radius};
  }
  const Law& law() const { return part_one_.law(); }
  double free_part_inner_height(const ScaledSolution&) const { return 0.0; }
  // The bonded face: unstretched, at the tip's depth, from the centre to the edge.
  void append_contact_fields(const ScaledSolution& sol, const FieldScales& u,
                             MembraneFields& m) const {
    for (const double r : {0.0, a_}) {
      append_point(m,
                   MembranePart::Tip,
                   r * u.clamp_radius_mm,
                   r * u.clamp_radius_mm,
                   sol.depth * u.clamp_radius_mm,
                   0.0,
                   1.0,
                   1.0,
                   membrane_stress(part_one_.law(), 1.0, 1.0),
                   u.shear_modulus_mpa,
                   0.0,
                   0.0);
    }
  }

 private:
  static constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  const FreePart<Law>& part_one_;
  double a_;
};

TEST(PluggableContact, BondedDiscGivesTheAlwaysHeldFlatPunch) {
  const Problem disc_problem = test::paper_problem();  // stick rule none: one stage, "slip"
  Problem held = disc_problem;
  held.stick.rule = StickRule::Always;
  SolverOptions options;
  options.record_fields = false;
  CurveOptions curve;
  curve.points = 40;

  const IndentationShooting<BondedDiscContact<Gent>> shooting(
      std::get<Gent>(disc_problem.material.law),
      shooting_settings(options),
      {radius_mm(disc_problem.indenter) / disc_problem.geometry.clamp_radius_mm});
  const LoadingCurve disc = curve_to_puncture(disc_problem, shooting, curve, options);
  const LoadingCurve punch = loading_curve(held, curve, options);

  ASSERT_TRUE(disc.ok()) << disc.message;
  ASSERT_TRUE(punch.ok()) << punch.message;
  ASSERT_TRUE(disc.puncture.ok()) << disc.puncture.message;
  // Both puncture forces are roots of max I1 = I1c bracketed to a few ulps of the force; the
  // states there meet the clamp condition to the shooting tolerance (1e-10), which moves the
  // force by ~1e-10 relative: 1e-8 leaves a margin and would catch any difference of physics.
  EXPECT_NEAR(disc.puncture.force_n, punch.puncture.force_n, 1e-8 * punch.puncture.force_n);
  EXPECT_NEAR(disc.puncture.depth_mm, punch.puncture.depth_mm, 1e-8 * punch.puncture.depth_mm);
  ASSERT_EQ(disc.points.size(), punch.points.size());
  for (std::size_t i = 1; i < disc.points.size(); ++i) {
    const auto& d = disc.points[i];
    const auto& p = punch.points[i];
    EXPECT_EQ(d.configuration, Configuration::Stick);
    // Same depth grid up to the puncture depths' 1e-8; curve points are converged to 1e-8
    // relative in force (README, "Speed") and F ~ depth^3 at small depths.
    EXPECT_NEAR(d.depth_mm, p.depth_mm, 1e-8 * p.depth_mm) << i;
    EXPECT_NEAR(d.force_n, p.force_n, 1e-7 * p.force_n) << i;
    EXPECT_NEAR(d.max_first_invariant, p.max_first_invariant, 1e-7 * p.max_first_invariant) << i;
  }
  // The state at puncture made physical through the disc's own contact fields: its Part I is
  // the held flat punch's.
  EXPECT_EQ(disc.puncture.state.max_first_invariant_part, MembranePart::Free);
  EXPECT_NEAR(disc.puncture.state.max_first_invariant_reference_radius_mm,
              punch.puncture.state.max_first_invariant_reference_radius_mm,
              1e-6 * disc_problem.geometry.clamp_radius_mm);
  // The driver worked with the disc's own configuration rule: no change on the sliding branch.
  EXPECT_FALSE(disc.part_two_onset_depth_mm.has_value());
}

}  // namespace
}  // namespace puncture::detail
