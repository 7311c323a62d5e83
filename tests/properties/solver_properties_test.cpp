// Property tests (rapidcheck) over the valid parameter space: indenter / clamp radius ratio,
// thickness, G, the material law and its parameter, friction 0..10, the stick rule, and a
// critical I1 within the law's range.  Every converged equilibrium satisfies its identities
// (vertical force balance of Part I, the clamp, continuity across the parts) with finite fields;
// the depth grows with the force within each stage; a loading curve is finite and its force
// grows with depth within each stage; and invalid input is reported through validation_errors
// and the result's status, never by a crash or an unexpected exception.
//
// Speed: ctest runs each property on a fixed seed and a limited number of cases (RC_PARAMS in
// tests/properties/CMakeLists.txt), well under a minute in Release on one core.  More cases, or
// another seed, by running the binary directly, e.g.
//   RC_PARAMS="max_success=1000 seed=7" build/tests/properties/solver_properties_test
// (rapidcheck prints the seed it used; `reproduce=...` from a failure's report replays it).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "puncture/problem.hpp"
#include "puncture/puncture_band.hpp"

namespace puncture {
namespace {

constexpr double kPi = boost::math::constants::pi<double>();
constexpr double kHalfPi = boost::math::constants::half_pi<double>();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// ----- generators -----------------------------------------------------------------------------

// Uniform in [lo, hi] on a grid of 10^6 steps (rapidcheck's inRange is for integers; this
// shrinks towards lo).  At rapidcheck's nominal size 100 whatever the case number: its early,
// small cases would otherwise all sit near lo.
double uniform(double lo, double hi) {
  const int k = *rc::gen::resize(100, rc::gen::inRange(0, 1000001));
  return lo + (hi - lo) * k / 1e6;
}

// One of 0 .. n - 1, uniformly (also at nominal size).
int pick(int n) { return *rc::gen::resize(100, rc::gen::inRange(0, n)); }

// Log-uniform in [lo, hi]: moduli and thicknesses span decades.
double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }

// A valid problem anywhere in the model's range.  The clamp radius is kept at the paper's 25 mm:
// only the ratio a/A matters to the normalised problem, and it is varied from 0.01 to 0.3.
Problem valid_problem() {
  Problem p;
  p.geometry.clamp_radius_mm = 25.0;
  p.indenter = FlatPunch{25.0 * uniform(0.01, 0.3)};
  p.geometry.thickness_mm = log_uniform(0.02, 2.0);
  p.material.shear_modulus_mpa = log_uniform(0.005, 5.0);
  double i1_room = 200.0;  // how far above 3 the critical I1 may go
  switch (pick(3)) {
    case 0: {
      const double j_lim = log_uniform(20.0, 1000.0);
      p.material.law = Gent{j_lim};
      i1_room = std::min(i1_room, j_lim);
      break;
    }
    case 1:
      p.material.law = NeoHookean{};
      break;
    default:
      p.material.law = MooneyRivlin{uniform(0.0, 0.5)};
      break;
  }
  p.friction = pick(5) == 0 ? 0.0 : uniform(0.0, 10.0);
  // Strictly inside (3, 3 + J_lim): 5 % to 95 % of the room.
  p.critical_i1 = 3.0 + i1_room * uniform(0.05, 0.95);
  switch (pick(5)) {
    case 0:
      p.stick = {StickRule::None, 0.0};
      break;
    case 1:
      p.stick = {StickRule::Force, force_scale_n(p) * uniform(0.01, 1.0)};
      break;
    case 2:
      p.stick = {StickRule::Depth, p.geometry.clamp_radius_mm * uniform(0.05, 1.0)};
      break;
    case 3:
      p.stick = {StickRule::EdgeTension,
                 p.material.shear_modulus_mpa * p.geometry.thickness_mm * uniform(0.05, 2.0)};
      break;
    default:
      p.stick = {StickRule::Always, 0.0};
      break;
  }
  if (pick(4) == 0) p.part_two_equation = PartTwoEquation::PaperEq18;
  return p;
}

std::string describe(const Problem& p) {
  return fmt::format(
      "a = {:.10g} mm, A = {:.10g} mm, H = {:.10g} mm, {}, friction {:.10g}, critical I1 {:.10g}, "
      "stick {} {:.10g}, {}",
      radius_mm(p.indenter),
      p.geometry.clamp_radius_mm,
      p.geometry.thickness_mm,
      describe(p.material),
      p.friction,
      p.critical_i1,
      to_string(p.stick.rule),
      p.stick.threshold,
      to_string(p.part_two_equation));
}

SolverOptions with_fields() { return SolverOptions{}; }
SolverOptions without_fields() {
  SolverOptions o;
  o.record_fields = false;
  return o;
}

bool all_finite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

bool fields_finite(const MembraneFields& m) {
  return all_finite(m.reference_radius_mm) && all_finite(m.radius_mm) &&
         all_finite(m.deflection_mm) && all_finite(m.slope_rad) && all_finite(m.radial_stretch) &&
         all_finite(m.hoop_stretch) && all_finite(m.thickness_stretch) &&
         all_finite(m.radial_stress_mpa) && all_finite(m.hoop_stress_mpa) &&
         all_finite(m.first_invariant) && all_finite(m.contact_pressure_mpa) &&
         all_finite(m.friction_traction_mpa);
}

// A solve that is not converged must say why.
void require_explained(const Equilibrium& e, const std::string& what) {
  if (e.message.empty()) RC_FAIL(what + ": " + to_string(e.status) + " without a message");
}

// Calls f; any exception is a failure of the property (the library reports, it does not throw).
template <class F>
auto no_throw(const std::string& what, F&& f) {
  try {
    return f();
  } catch (const std::exception& e) {
    RC_FAIL(what + " threw: " + e.what());
  }
  return decltype(f())();
}

// The parameters an InvalidInput from f names; fails the property when f accepts the input or
// throws anything else.
template <class F>
std::vector<std::string> rejected(const std::string& what, F&& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    std::vector<std::string> names;
    for (const auto& error : e.errors()) names.push_back(error.parameter);
    return names;
  } catch (const std::exception& e) {
    RC_FAIL(what + " threw other than InvalidInput: " + e.what());
  }
  RC_FAIL(what + " accepted");
  return {};
}

std::vector<std::string> parameters_of(const std::vector<ValidationError>& errors) {
  std::vector<std::string> names;
  for (const auto& error : errors) names.push_back(error.parameter);
  return names;
}

// ----- the identities of one equilibrium ------------------------------------------------------

void check_identities(const Problem& p, const Equilibrium& e) {
  const auto& m = e.fields;
  RC_ASSERT(m.size() > 0u);
  RC_ASSERT(fields_finite(m));
  RC_ASSERT(std::isfinite(e.force_n) && std::isfinite(e.depth_mm) &&
            std::isfinite(e.part_three_stretch) && std::isfinite(e.max_first_invariant));
  if (e.stage == Stage::Slip) RC_ASSERT(std::isfinite(e.corner_tension_ratio));
  std::vector<std::size_t> one, two, three;
  for (std::size_t i = 0; i < m.size(); ++i)
    (m.part[i] == MembranePart::Free   ? one
     : m.part[i] == MembranePart::Side ? two
                                       : three)
        .push_back(i);
  RC_ASSERT(!one.empty());
  RC_ASSERT(!three.empty());
  RC_ASSERT(two.empty() == (e.configuration != Configuration::SlipWithPartTwo));

  // Eq. (12): 2 pi R H s1 sin(phi) = F along Part I.  The solver integrates t = R s1 cos(phi)
  // and lambda1, not this product, so it holds to the accumulated integration error: local
  // relative tolerance 1e-10 per step; tests/solver/equilibrium_identities_test.cpp sees < 1e-9
  // on the paper's cases.  Over the whole parameter space (stiff Gent near locking, friction up
  // to 10) 1e-7 relative: still far below any modelling error (a missing term is O(1)).
  const double h = p.geometry.thickness_mm;
  for (const std::size_t i : one) {
    const double vertical = 2.0 * kPi * m.reference_radius_mm[i] * h * m.radial_stress_mpa[i] *
                            std::sin(m.slope_rad[i]);
    RC_ASSERT(std::abs(vertical / e.force_n - 1.0) <= 1e-7);
  }

  // Eq. (24): the clamp, R = r = A with lambda2 = 1.  The shooting accepts |lambda2(A) - 1| at
  // 1e-10, up to 100 x that when its bracket collapses: 1e-8.
  const std::size_t last = m.size() - 1;
  const double big_a = p.geometry.clamp_radius_mm;
  RC_ASSERT(m.part[last] == MembranePart::Free);
  RC_ASSERT(std::abs(m.reference_radius_mm[last] - big_a) <= 1e-12 * big_a);
  RC_ASSERT(std::abs(m.hoop_stretch[last] - 1.0) <= 1e-8);
  RC_ASSERT(std::abs(m.deflection_mm[last]) <= 1e-10 * std::max(1.0, e.depth_mm));

  // Continuity (the parts are assembled from the same numbers: round-off, 1e-10 relative).
  constexpr double kRel = 1e-10;
  const double a = radius_mm(p.indenter);
  const std::size_t edge = three.back(), out = two.empty() ? one.front() : two.front();
  for (const std::size_t i : three) {
    RC_ASSERT(std::abs(m.deflection_mm[i] - e.depth_mm) <= kRel * std::max(1.0, e.depth_mm));
    RC_ASSERT(m.radial_stretch[i] == e.part_three_stretch);
  }
  RC_ASSERT(std::abs(m.radius_mm[edge] - a) <= kRel * a);
  RC_ASSERT(std::abs(m.radius_mm[out] - a) <= kRel * a);
  RC_ASSERT(std::abs(m.reference_radius_mm[out] - m.reference_radius_mm[edge]) <= kRel * a);
  RC_ASSERT(std::abs(m.hoop_stretch[out] - m.hoop_stretch[edge]) <= kRel * e.part_three_stretch);
  if (!two.empty()) {
    for (const std::size_t i : two) {
      RC_ASSERT(std::abs(m.radius_mm[i] - a) <= kRel * a);
      RC_ASSERT(std::abs(m.slope_rad[i] - kHalfPi) <= 1e-12);
    }
    const std::size_t top = two.back(), start = one.front();
    RC_ASSERT(std::abs(m.reference_radius_mm[start] - m.reference_radius_mm[top]) <=
              kRel * m.reference_radius_mm[top]);
    RC_ASSERT(std::abs(m.radial_stretch[start] - m.radial_stretch[top]) <=
              kRel * m.radial_stretch[top]);
    RC_ASSERT(std::abs(m.deflection_mm[start] - m.deflection_mm[top]) <=
              kRel * std::max(1.0, e.depth_mm));
  }
}

// ----- properties -----------------------------------------------------------------------------

RC_GTEST_PROP(SolverProperties, ConvergedEquilibriaSatisfyTheirIdentities, ()) {
  const Problem p = valid_problem();
  RC_ASSERT(validation_errors(p).empty());
  const Stage stage = *rc::gen::element(Stage::Stick, Stage::Slip);
  // f = F / (2 pi G H A) from the first touch to well past the paper's puncture (0.37).
  const double f = log_uniform(1e-3, 2.0);
  const std::string what = fmt::format("{}, f = {:.6g}, {}", describe(p), f, to_string(stage));
  const auto e = no_throw(what, [&] { return solve_at_force(p, f * force_scale_n(p), stage); });
  RC_TAG(e.ok() ? to_string(e.configuration) : "not converged: " + to_string(e.status));
  if (!e.ok()) return require_explained(e, what);
  RC_ASSERT(std::abs(e.force_n / (f * force_scale_n(p)) - 1.0) <= 1e-12);
  check_identities(p, e);
}

RC_GTEST_PROP(SolverProperties, DepthGrowsWithForceWithinAStage, ()) {
  const Problem p = valid_problem();
  const Stage stage = *rc::gen::element(Stage::Stick, Stage::Slip);
  std::vector<double> forces{
      log_uniform(1e-3, 1.0), log_uniform(1e-3, 1.0), log_uniform(1e-3, 1.0)};
  std::sort(forces.begin(), forces.end());
  RC_PRE(forces[0] < forces[1] && forces[1] < forces[2]);
  const std::string what = fmt::format("{}, {}", describe(p), to_string(stage));
  std::vector<double> depths;
  for (const double f : forces) {
    const auto e = no_throw(
        what, [&] { return solve_at_force(p, f * force_scale_n(p), stage, without_fields()); });
    if (!e.ok()) {
      require_explained(e, what);
      RC_TAG("some force not converged");
      return;
    }
    RC_ASSERT(std::isfinite(e.depth_mm) && e.depth_mm > 0.0);
    depths.push_back(e.depth_mm);
  }
  RC_TAG("all converged");
  // Strictly: a stiffer membrane still deflects more under more load.
  RC_ASSERT(depths[0] < depths[1]);
  RC_ASSERT(depths[1] < depths[2]);
}

RC_GTEST_PROP(SolverProperties, LoadingCurveIsFiniteAndRisesWithinEachStage, ()) {
  const Problem p = valid_problem();
  const std::string what = describe(p);
  RC_LOG() << what << "\n";
  CurveOptions curve;
  curve.points = 12;
  const auto c = no_throw(what, [&] { return loading_curve(p, curve, without_fields()); });
  RC_TAG(c.ok() ? "converged" : "not converged: " + to_string(c.status));
  if (!c.ok()) {
    RC_ASSERT(!c.message.empty());
    return;
  }
  RC_ASSERT(c.points.size() >= 12u);
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const auto& q = c.points[i];
    RC_ASSERT(std::isfinite(q.depth_mm) && std::isfinite(q.force_n) &&
              std::isfinite(q.part_three_stretch) && std::isfinite(q.max_first_invariant));
    if (i == 0) continue;
    const auto& prev = c.points[i - 1];
    RC_ASSERT(q.depth_mm >= prev.depth_mm);
    // Within a stage the force rises with depth (the stick -> slip switch may drop it, at one
    // depth).  Each point is converged to 1e-8 relative: a fall within that is not a fall.
    if (q.stage == prev.stage) RC_ASSERT(q.force_n >= prev.force_n * (1.0 - 1e-8));
  }
  if (c.puncture.ok()) {
    // The puncture point is where the largest I1 reaches the critical I1 (converged to ~1e-8
    // relative in force; I1 then to well within 1e-6), or, when the sliding state at the stick
    // -> slip switch is already beyond it, at the switch, with the largest I1 above it.
    const double i1 = c.puncture.state.max_first_invariant;
    // The curve then ends with the switch: LoadingCurve::stick_slip reports it at the last
    // depth, unless the puncture state is the held one (the sliding membrane would pass the
    // criterion before reaching the switch depth).
    const bool held_at_switch = c.puncture.at_switch && c.puncture.stage == Stage::Stick;
    const bool at_switch = c.stick_slip.occurs && c.stick_slip.depth_mm == c.points.back().depth_mm;
    RC_ASSERT(c.puncture.at_switch == (at_switch || held_at_switch));
    RC_LOG() << fmt::format("puncture at {:.10g} mm, {}; switch: {} at {:.10g} mm\n",
                            c.puncture.depth_mm,
                            c.puncture.crack_location,
                            c.stick_slip.occurs,
                            c.stick_slip.depth_mm);
    RC_TAG(at_switch ? "punctures at the switch" : "punctures on the way");
    if (held_at_switch)
      RC_ASSERT(i1 <= p.critical_i1 * (1.0 + 1e-6));
    else if (at_switch)
      RC_ASSERT(i1 >= p.critical_i1 * (1.0 - 1e-6));
    else
      RC_ASSERT(std::abs(i1 - p.critical_i1) <= 1e-6 * p.critical_i1);
    // Both are converged to 1e-9 relative in depth (SolverOptions::curve_tol), the curve's
    // point to its grid depth, the puncture state at the switch to the switch depth.
    RC_ASSERT(std::abs(c.points.back().depth_mm - c.puncture.depth_mm) <=
              2e-9 * c.puncture.depth_mm);
  }
}

// One parameter (or several) made invalid: the error is reported by validation_errors and by
// every entry point's status or message; only validate() and the calibrations throw, and only
// std::invalid_argument.
RC_GTEST_PROP(SolverProperties, InvalidInputIsReportedNeverThrown, ()) {
  Problem p = valid_problem();
  const auto bad = [] { return *rc::gen::element(-1.0, 0.0, kNaN, kInf, -kInf, -1e-300); };
  const int what_bad = pick(9);
  switch (what_bad) {
    case 0:
      p.geometry.clamp_radius_mm = bad();
      break;
    case 1:
      p.indenter = FlatPunch{*rc::gen::element(
          -1.0, 0.0, kNaN, p.geometry.clamp_radius_mm, 2.0 * p.geometry.clamp_radius_mm)};
      break;
    case 2:
      p.geometry.thickness_mm = bad();
      break;
    case 3:
      p.material.shear_modulus_mpa = bad();
      break;
    case 4:
      p.friction = *rc::gen::element(-0.1, 10.0 + 1e-9, 1e6, kNaN, kInf);
      break;
    case 5:
      // At or beyond the law's range: 3 + J_lim for Gent, <= 3 for every law.
      if (const auto* gent = std::get_if<Gent>(&p.material.law))
        p.critical_i1 = 3.0 + gent->j_lim * uniform(1.0, 2.0);
      else
        p.critical_i1 = *rc::gen::element(3.0, 1.0, kNaN);
      break;
    case 6:
      p.material.law = *rc::gen::element<MaterialLaw>(Gent{-5.0},
                                                      Gent{0.0},
                                                      Gent{kNaN},
                                                      MooneyRivlin{1.0},
                                                      MooneyRivlin{-0.1},
                                                      MooneyRivlin{kNaN});
      break;
    case 7:
      p.stick = {*rc::gen::element(StickRule::Force, StickRule::Depth, StickRule::EdgeTension),
                 bad()};
      break;
    default:
      p.geometry.thickness_mm = bad();
      p.friction = -1.0;
      break;
  }
  RC_TAG(what_bad);
  const std::string what = describe(p);
  const auto errors = no_throw(what, [&] { return validation_errors(p); });
  RC_ASSERT(!errors.empty());
  for (const auto& e : errors) RC_ASSERT(!e.parameter.empty() && !e.message.empty());
  try {
    validate(p);
    RC_FAIL("validate accepted " + what);
  } catch (const std::invalid_argument&) {
  }
  const double force = 0.1, depth = 1.0;
  const auto named = parameters_of(errors);
  for (const Stage s : {Stage::Stick, Stage::Slip}) {
    RC_ASSERT(rejected(what, [&] { solve_at_force(p, force, s); }) == named);
    RC_ASSERT(rejected(what, [&] { solve_at_depth(p, depth, s); }) == named);
  }
  RC_ASSERT(rejected(what, [&] { predict_puncture(p); }) == named);
  RC_ASSERT(rejected(what, [&] { loading_curve(p); }) == named);
  RC_ASSERT(rejected(what, [&] { stick_slip_boundary(p); }) == named);
  try {
    puncture_band(p, BandRanges{});
    RC_FAIL("puncture_band accepted " + what);
  } catch (const std::invalid_argument&) {
  }
}

// A valid problem with an invalid load: rejected, naming the argument.
RC_GTEST_PROP(SolverProperties, InvalidLoadIsReported, ()) {
  const Problem p = valid_problem();
  const double load = *rc::gen::element(-1.0, -1e-12, kNaN, kInf, -kInf);
  const Stage stage = *rc::gen::element(Stage::Stick, Stage::Slip);
  const std::string what = fmt::format("{}, load {}", describe(p), load);
  const auto at_force = rejected(what, [&] { solve_at_force(p, load, stage); });
  RC_ASSERT(at_force.size() == 1u && at_force.front() == "force_n");
  const auto at_depth = rejected(what, [&] { solve_at_depth(p, load, stage); });
  RC_ASSERT(at_depth.size() == 1u && at_depth.front() == "depth_mm");
}

// ----- regressions the properties found ------------------------------------------------------

// stick_slip_boundary answered an invalid problem with "converged" (rules none and always) or
// computed with it (the others).
TEST(SolverPropertyRegressions, StickSlipBoundaryReportsInvalidInput) {
  for (const StickRule rule : {StickRule::None, StickRule::Always, StickRule::Force}) {
    Problem p;
    p.geometry.clamp_radius_mm = -1.0;
    p.stick = {rule, 0.1};
    try {
      stick_slip_boundary(p);
      ADD_FAILURE() << to_string(rule) << ": accepted";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("clamp radius"), std::string::npos) << e.what();
    }
  }
}

// A membrane held at the edge (stick always) whose held solutions end (it would wrap the
// indenter's side) before its largest I1 reaches the critical value was reported punctured at
// that end, with I1 = 18.5223 < 18.52276.  No puncture of the held membrane exists there.
TEST(SolverPropertyRegressions, HeldMembraneEndingBelowTheCriticalI1DoesNotPuncture) {
  Problem p;
  p.indenter = FlatPunch{0.25013775};
  p.geometry.thickness_mm = 0.02;
  p.material = Material{0.005, MooneyRivlin{0.161205}};
  p.friction = 0.0;
  p.critical_i1 = 18.52276;
  p.stick = {StickRule::Always, 0.0};
  const auto punct = predict_puncture(p);
  EXPECT_FALSE(punct.ok()) << "largest I1 " << punct.state.max_first_invariant;
  EXPECT_NE(punct.message.find("reaches only"), std::string::npos) << punct.message;
  // A critical I1 the held membrane does reach is still found, at that I1.
  // (The corner solve and the path search agree on I1 to ~1e-8 relative: 1e-6.)
  p.critical_i1 = 8.0;
  const auto reached = predict_puncture(p);
  ASSERT_TRUE(reached.ok()) << reached.message;
  EXPECT_NEAR(reached.state.max_first_invariant, 8.0, 1e-6 * 8.0);
}

}  // namespace
}  // namespace puncture
