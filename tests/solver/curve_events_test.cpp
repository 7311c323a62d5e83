// The loading curve's events (force maxima, a shrinking contact) and the verdict on which
// failure of a pre-tensioned membrane comes first (docs/model.md §8.1): the locator against
// closed forms, the contact edge against the probe's geometry, and the paper's membranes, on
// which no event occurs.
#include "indentation/curve_events.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "pressurised_support.hpp"
#include "solver_test_support.hpp"

namespace puncture::test {
namespace {

// A cubic with a maximum at 1, a minimum at 2 and the maximum's value again at 2.5:
// c(d) = d^3/3 - 1.5 d^2 + 2 d = (d - 1)^2 (d/3 - 5/6) + 5/6.
double events_cubic(double d) { return d * d * d / 3.0 - 1.5 * d * d + 2.0 * d; }

// The cubic as the force [N] and 10 + the cubic as the contact's reach [mm], with a
// deterministic noise of 1e-10 relative (the solver's is ~1e-9 at worst).
detail::DepthSample events_cubic_sample(double d) {
  const double noise = 1e-10 * std::sin(1e7 * d);
  return {events_cubic(d) * (1.0 + noise), (10.0 + events_cubic(d)) * (1.0 + noise)};
}

std::vector<CurvePoint> events_cubic_points(int n, double from, double to) {
  std::vector<CurvePoint> out;
  for (int k = 0; k < n; ++k) {
    CurvePoint q;
    q.depth_mm = from + (to - from) * k / (n - 1);
    const auto s = events_cubic_sample(q.depth_mm);
    q.force_n = s.force_n;
    q.contact_edge_radius_mm = s.contact_reach_mm;  // the reach is radius + height
    q.stage = Stage::Slip;
    q.configuration = Configuration::SlipWithoutPartTwo;
    out.push_back(q);
  }
  return out;
}

TEST(CurveEvents, LocatesAForceMaximumAndAShrinkingContactToTheirClosedForms) {
  const auto points = events_cubic_points(15, 0.1, 2.9);  // spacing 0.2: 1 and 2 between points
  int samples = 0;
  const detail::DepthSampler at_depth = [&](double d, Stage) {
    ++samples;
    return std::optional<detail::DepthSample>(events_cubic_sample(d));
  };
  const auto events = detail::located_curve_events(points, at_depth);
  ASSERT_EQ(events.size(), 2u);
  for (const CurveEvent& e : events) {
    // The maximum at depth 1 exactly (both quantities turn there); the locator's own
    // uncertainty bounds its error and is far below the points' spacing.
    EXPECT_NEAR(e.depth_mm, 1.0, std::max(e.depth_uncertainty_mm, 1e-12));
    EXPECT_LT(e.depth_uncertainty_mm, 1e-4);
    EXPECT_NEAR(e.force_n, 5.0 / 6.0, 1e-9);
    ASSERT_TRUE(e.end_depth_mm.has_value());
  }
  const CurveEvent& force = events[0].kind == CurveEventKind::ForceMaximum ? events[0] : events[1];
  const CurveEvent& contact =
      events[0].kind == CurveEventKind::ContactShrinks ? events[0] : events[1];
  EXPECT_EQ(force.kind, CurveEventKind::ForceMaximum);
  EXPECT_EQ(contact.kind, CurveEventKind::ContactShrinks);
  // Force control lands where the cubic takes 5/6 again, 2.5; the contact grows again from the
  // minimum at 2.
  EXPECT_NEAR(*force.end_depth_mm, 2.5, 1e-8);
  EXPECT_NEAR(*contact.end_depth_mm, 2.0, 1e-4);
  EXPECT_NEAR(contact.contact_reach_mm, 10.0 + 5.0 / 6.0, 1e-8);
  EXPECT_LT(samples, 400);  // tens of solves per event, not a dense sampling
}

TEST(CurveEvents, AMonotoneCurveAndTheStickSlipJumpHaveNone) {
  // Rising curve (the cubic up to its maximum), then a force drop at one depth (the stick ->
  // slip switch repeats its depth with the sliding stage): no event.
  auto points = events_cubic_points(8, 0.1, 0.9);
  CurvePoint sliding = points.back();
  sliding.stage = Stage::Slip;
  sliding.force_n *= 0.5;
  for (auto& q : points) q.stage = Stage::Stick;
  points.push_back(sliding);
  const detail::DepthSampler at_depth = [](double d, Stage) {
    return std::optional<detail::DepthSample>(events_cubic_sample(d));
  };
  EXPECT_TRUE(detail::located_curve_events(points, at_depth).empty());
}

// The locator on real states: the Part III stretch of a frictionless flat punch pushed into the
// inflated dome falls first and rises after (§17: 1.1177 to ~1.110 at ~1.3 mm), a true minimum
// of a solved quantity.  Handed to the locator as a "force" (its negative, so that the minimum
// is a maximum), it is located where an independent central difference of the solved stretch,
// with another spacing, vanishes, and below the stretch of dense states around it.
TEST(CurveEvents, LocatesAMinimumOfSolvedStatesAgainstIndependentDifferences) {
  const Problem p = flat();
  SolverOptions quiet;
  quiet.record_fields = false;
  auto stretch_at = [&](double d) {
    const Equilibrium e = solve_at_depth(p, d, Stage::Slip, quiet);
    EXPECT_TRUE(e.ok()) << e.message;
    return e.part_three_stretch;
  };
  std::vector<CurvePoint> points;
  for (int k = 1; k <= 12; ++k) {
    CurvePoint q;
    q.depth_mm = 0.25 * k;
    q.force_n = -stretch_at(q.depth_mm);
    q.contact_edge_radius_mm = q.depth_mm;  // rising: no contact event
    q.stage = Stage::Slip;
    q.configuration = Configuration::SlipWithoutPartTwo;
    points.push_back(q);
  }
  const detail::DepthSampler at_depth = [&](double d, Stage) {
    return std::optional<detail::DepthSample>(detail::DepthSample{-stretch_at(d), d});
  };
  const auto events = detail::located_curve_events(points, at_depth);
  ASSERT_EQ(events.size(), 1u);
  const CurveEvent& e = events.front();
  EXPECT_EQ(e.kind, CurveEventKind::ForceMaximum);
  EXPECT_GT(e.depth_mm, 0.5);
  EXPECT_LT(e.depth_mm, 2.5);
  EXPECT_LT(e.depth_uncertainty_mm, 1e-3);
  // Independent: a plain central difference of spacing 1e-3 mm at the located depth is zero to
  // its own truncation and noise, against the slope 0.1 mm away.
  const double h = 1e-3, d0 = e.depth_mm;
  const double at_root = (stretch_at(d0 + h) - stretch_at(d0 - h)) / (2.0 * h);
  const double nearby = (stretch_at(d0 + 0.1 + h) - stretch_at(d0 + 0.1 - h)) / (2.0 * h);
  EXPECT_LT(std::abs(at_root), 2e-3 * std::abs(nearby)) << at_root << " vs " << nearby;
  // No state of a dense sampling around it is lower (to the states' 1e-10).
  for (int k = -10; k <= 10; ++k) EXPECT_GE(stretch_at(d0 + 0.01 * k), -e.force_n - 1e-10) << k;
}

// The contact edge of the sphere's cap is where Part I leaves tangentially at the polar angle
// theta_c = the corner slope: radius a sin(theta_c), height a (1 - cos(theta_c)); on the
// cylinder side the radius is a.  The paper's membrane has no event, and its contact grows.
TEST(CurveEvents, SphereTippedContactEdgeIsOnTheSphereAndGrowsWithoutEvents) {
  for (const double friction : {0.0, 0.18}) {
    Problem p = paper_problem(Gent{125.0}, friction);
    const double a = 2.0;
    p.indenter = SphereTipped{a};
    CurveOptions c;
    c.points = 80;
    if (friction > 0.0) c.max_depth_mm = 17.5;  // the contact reaches the side at ~18 mm
    const LoadingCurve curve = loading_curve(p, c);
    ASSERT_TRUE(curve.ok()) << curve.message;
    EXPECT_TRUE(curve.events.empty()) << curve.events.front().description;
    EXPECT_FALSE(curve.failure_verdict.has_value());  // mounted stress-free
    double last_reach = 0.0;
    int on_cap = 0;
    for (const CurvePoint& q : curve.points) {
      if (q.configuration == Configuration::Unloaded) continue;
      if (q.configuration == Configuration::SlipWithoutPartTwo) {
        ++on_cap;
        EXPECT_NEAR(q.contact_edge_radius_mm, a * std::sin(q.corner_slope_rad), 1e-9 * a);
        EXPECT_NEAR(q.contact_edge_height_mm, a * (1.0 - std::cos(q.corner_slope_rad)), 1e-9 * a);
      } else {
        EXPECT_NEAR(q.contact_edge_radius_mm, a, 1e-9 * a);
        EXPECT_NEAR(q.contact_edge_height_mm, a + q.part_two_length_mm, 1e-9 * a);
      }
      const double reach = detail::contact_reach_mm(q);
      EXPECT_GT(reach, last_reach) << "at " << q.depth_mm << " mm";
      last_reach = reach;
    }
    EXPECT_GT(on_cap, 20);
  }
}

// On the flat punch's face under a held pressure the force is the pressure times the contact
// disc, F = p pi c^2 (§17): the contact edge's radius is c.
TEST(CurveEvents, FlatFaceContactEdgeUnderPressureIsTheContactDisc) {
  const Problem p = flat();
  CurveOptions c;
  c.points = 12;
  c.max_depth_mm = 0.25;  // on the face (to 0.27 mm)
  const LoadingCurve curve = loading_curve(p, c);
  ASSERT_TRUE(curve.ok()) << curve.message;
  for (const CurvePoint& q : curve.points) {
    if (q.depth_mm == 0.0) continue;
    const double disc = std::sqrt(q.force_n / (kPressureMpa * kPi));
    EXPECT_NEAR(q.contact_edge_radius_mm, disc, 1e-9 * disc) << q.depth_mm;
    EXPECT_LT(q.contact_edge_radius_mm, 2.0);
    EXPECT_EQ(q.contact_edge_height_mm, 0.0);
  }
  EXPECT_TRUE(curve.events.empty());
}

// Deris & Nadler's question on one inflated membrane (3e-4 MPa, the paper's Gent membrane): a
// small and a large probe.  Both puncture locally; checked independently on the puncture state:
// in the free membrane the largest I1 is at the contact's edge, and it falls all the way to the
// clamp (no interior maximum where the dome could burst), and the force rose to the puncture.
TEST(CurveEvents, SmallAndLargeProbeOnAnInflatedMembranePunctureLocally) {
  for (const double radius : {0.5, 8.0}) {
    const Problem p = pressurised(kPressureMpa, 0.0, SphereTipped{radius});
    CurveOptions c;
    c.points = 60;
    const LoadingCurve curve = loading_curve(p, c);
    ASSERT_TRUE(curve.ok()) << curve.message;
    ASSERT_TRUE(curve.failure_verdict.has_value());
    const FailureVerdict& v = *curve.failure_verdict;
    EXPECT_EQ(v.mode, FailureMode::LocalPuncture) << v.reason;
    EXPECT_EQ(v.depth_mm, curve.puncture.depth_mm);
    EXPECT_EQ(v.force_n, curve.puncture.force_n);
    EXPECT_TRUE(curve.events.empty());
    for (std::size_t k = 1; k < curve.points.size(); ++k)
      EXPECT_GT(curve.points[k].force_n, curve.points[k - 1].force_n);
    const Equilibrium s = solve_at_depth(p, curve.puncture.depth_mm, Stage::Slip);
    ASSERT_TRUE(s.ok()) << s.message;
    const MembraneFields& f = s.fields;
    double previous = std::numeric_limits<double>::infinity();
    int free_samples = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (f.part[i] != MembranePart::Free) continue;
      ++free_samples;
      EXPECT_LE(f.first_invariant[i], previous * (1.0 + 1e-9))
          << "R = " << f.reference_radius_mm[i];
      previous = f.first_invariant[i];
    }
    EXPECT_GT(free_samples, 50);
    EXPECT_GT(s.max_first_invariant, previous);  // the crack is at the probe, not at the clamp
  }
}

// The verdict's other two answers, from a curve that has them.
TEST(CurveEvents, VerdictIsGlobalForALimitPointOrACrackInTheFreeDome) {
  const Problem p = flat();
  LoadingCurve curve;
  curve.status = Status::Converged;
  curve.puncture.status = Status::Converged;
  curve.puncture.depth_mm = 30.0;
  curve.puncture.force_n = 0.5;
  curve.puncture.crack_location = "Part I, off the indenter";
  curve.puncture.crack_reference_radius_mm = 12.0;
  curve.puncture.state.max_first_invariant_part = MembranePart::Free;
  curve.puncture.state.part_two_top_reference_radius_mm = 3.0;
  auto v = detail::failure_verdict(p, curve);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->mode, FailureMode::GlobalBurst);
  EXPECT_EQ(v->depth_mm, 30.0);

  curve.puncture.crack_reference_radius_mm = 3.0;  // at the contact's edge: local
  v = detail::failure_verdict(p, curve);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->mode, FailureMode::LocalPuncture);

  CurveEvent peak;
  peak.kind = CurveEventKind::ForceMaximum;
  peak.depth_mm = 20.0;
  peak.force_n = 0.6;
  curve.events.push_back(peak);
  v = detail::failure_verdict(p, curve);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->mode, FailureMode::GlobalLimitPoint);
  EXPECT_EQ(v->depth_mm, 20.0);
  EXPECT_EQ(v->force_n, 0.6);

  curve.events.front().depth_mm = 40.0;  // past the puncture: the puncture comes first
  v = detail::failure_verdict(p, curve);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->mode, FailureMode::LocalPuncture);

  EXPECT_FALSE(detail::failure_verdict(paper_problem(), curve).has_value());  // stress-free
}

// The puncture prediction's verdict is the loading curve's (one rule: the prediction follows the
// curve for it), asked by SolverOptions::failure_verdict: the inflated membrane and a 2 mm sphere
// (3e-4 MPa, frictionless) puncture locally at the prediction's own depth; a membrane mounted
// stress-free has none.
TEST(CurveEvents, PredictionGivesTheCurvesVerdictWhenAsked) {
  const Problem p = pressurised(kPressureMpa, 0.0, SphereTipped{2.0});
  EXPECT_FALSE(predict_puncture(p).failure_verdict.has_value());  // off unless asked
  SolverOptions asked;
  asked.failure_verdict = true;
  const PuncturePrediction prediction = predict_puncture(p, asked);
  ASSERT_TRUE(prediction.ok()) << prediction.message;
  ASSERT_TRUE(prediction.failure_verdict.has_value());
  const FailureVerdict& v = *prediction.failure_verdict;
  EXPECT_EQ(v.mode, FailureMode::LocalPuncture) << v.reason;
  const LoadingCurve curve = loading_curve(p);
  ASSERT_TRUE(curve.ok()) << curve.message;
  ASSERT_TRUE(curve.failure_verdict.has_value());
  EXPECT_EQ(v.mode, curve.failure_verdict->mode);
  EXPECT_EQ(v.depth_mm, curve.failure_verdict->depth_mm);
  EXPECT_EQ(v.force_n, curve.failure_verdict->force_n);
  EXPECT_EQ(v.reason, curve.failure_verdict->reason);
  EXPECT_FALSE(curve.puncture.failure_verdict.has_value());  // the curve's is LoadingCurve's
  // The curve's puncture is the prediction's own search: the same depth and force.
  EXPECT_EQ(v.depth_mm, prediction.depth_mm);
  EXPECT_EQ(v.force_n, prediction.force_n);
  EXPECT_NEAR(prediction.depth_mm, 36.551, 5e-4);  // docs/model.md §8.1's table

  const PuncturePrediction stress_free = predict_puncture(paper_problem(), asked);
  ASSERT_TRUE(stress_free.ok()) << stress_free.message;
  EXPECT_FALSE(stress_free.failure_verdict.has_value());
  EXPECT_FALSE(detail::pretensioned(paper_problem()));
  Problem stretched = paper_problem();
  stretched.preload.prestretch = 1.2;
  EXPECT_TRUE(detail::pretensioned(stretched));
}

}  // namespace
}  // namespace puncture::test
