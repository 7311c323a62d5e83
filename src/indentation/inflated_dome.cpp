#include "indentation/inflated_dome.hpp"

#include <fmt/format.h>

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/roots.hpp>
#include <cstdint>

#include "indentation/reported_failure.hpp"
#include "indentation/solver_scales.hpp"
#include "inflation/scaled_inflation.hpp"
#include "puncture/inflation.hpp"
#include "puncture/kinematics.hpp"

namespace puncture::detail {

namespace {

// The pole stretch of the first inflated state at normalised pressure `target` (the one reached
// by inflating slowly from flat): the first crossing of P(pole stretch) = target in a scan from
// the flat state to the pole's burst, refined by TOMS 748.  Empty when the scan meets a decrease
// of P below the crossing (a limit point: the crossing may lie inside one scan interval) or a
// solver failure: inflate_at_pressure, which locates the extrema, decides then.
std::optional<double> first_crossing(const InflationProblem& membrane, double target,
                                     const SolverOptions& options) {
  constexpr int kScan = 32;
  const double flat = membrane.prestretch;
  const double upper = equibiaxial_stretch_for_first_invariant(membrane.critical_i1);
  double guess = 0.0, l_prev = flat, p_prev = 0.0;
  auto pressure = [&](double l) -> std::optional<double> {
    const auto s = solve_inflation(membrane, l, options, guess);
    if (!s.ok()) return std::nullopt;
    guess = s.pressure;
    return s.pressure;
  };
  for (int k = 1; k <= kScan; ++k) {
    const double l = flat + (upper - flat) * k / kScan;
    const auto p = pressure(l);
    if (!p || *p < p_prev) return std::nullopt;
    if (*p >= target) {
      std::uintmax_t iterations = 100;
      bool failed = false;
      const auto bracket = boost::math::tools::toms748_solve(
          [&](double x) {
            const auto q = pressure(x);
            if (!q) failed = true;
            return q ? *q - target : 1.0;
          },
          l_prev,
          l,
          p_prev - target,
          *p - target,
          boost::math::tools::eps_tolerance<double>(45),
          iterations);
      if (failed) return std::nullopt;
      return 0.5 * (bracket.first + bracket.second);
    }
    l_prev = l;
    p_prev = *p;
  }
  return std::nullopt;
}

}  // namespace

std::optional<InflatedDome> inflated_dome(const Problem& problem, const SolverOptions& options) {
  const double p_mpa = problem.preload.pressure_mpa;
  if (p_mpa == 0.0) return std::nullopt;
  const InflationProblem membrane = inflation_problem(problem);
  SolverOptions quiet = options;
  quiet.record_fields = false;
  const double target = p_mpa / solver_pressure_scale_mpa(membrane);
  double pole_stretch = 0.0, pressure_guess = 0.0;
  const int chosen = problem.preload.inflated_state;
  if (chosen != 1) {  // another branch: every state at the pressure (validated: it exists)
    const InflationAtPressure at = inflate_at_pressure(membrane, p_mpa, {}, quiet);
    const std::size_t k = chosen == kLastInflatedState ? at.states.size() : std::size_t(chosen);
    if (!at.ok() || k < 1 || k > at.states.size())
      throw PhysicalFailure(at.ok() ? Status::NotReached : at.status,
                            fmt::format("inflated state {} at {:g} MPa not found ({} states{})",
                                        chosen,
                                        p_mpa,
                                        at.states.size(),
                                        at.ok() ? "" : ": " + at.message));
    pole_stretch = at.states[k - 1].pole_stretch;
    pressure_guess = at.states[k - 1].normalized_pressure / membrane.prestretch;
  } else if (const auto crossing = first_crossing(membrane, target, quiet)) {
    pole_stretch = *crossing;
    pressure_guess = target;
  } else {
    const InflationAtPressure at = inflate_at_pressure(membrane, p_mpa, {}, quiet);
    if (!at.ok()) {
      if (at.status == Status::NotReached)
        throw PhysicalFailure(
            Status::LimitLoad,
            fmt::format("the membrane cannot hold the pressure {:g} MPa before the indenter "
                        "touches it: it bursts or snaps through while it is inflated ({})",
                        p_mpa,
                        at.message));
      throw PhysicalFailure(
          at.status, "the inflated membrane before contact could not be solved: " + at.message);
    }
    pole_stretch = at.states.front().pole_stretch;
    pressure_guess = at.states.front().normalized_pressure / membrane.prestretch;
  }
  SolverOptions sampled = options;
  sampled.record_fields = true;
  const ScaledInflation dome = solve_inflation(membrane, pole_stretch, sampled, pressure_guess);
  if (!dome.ok())
    throw PhysicalFailure(
        dome.status, "the inflated membrane before contact could not be solved: " + dome.message);
  // The scan's bound is the pole's burst; elsewhere (Mooney-Rivlin near the clamp) the membrane
  // may burst earlier.
  if (!(dome.max_i1 < problem.critical_i1))
    throw PhysicalFailure(
        Status::LimitLoad,
        fmt::format("the membrane cannot hold the pressure {:g} MPa before the indenter touches "
                    "it: it bursts while it is inflated (largest I1 {:.6g} at the critical {:g})",
                    p_mpa,
                    dome.max_i1,
                    problem.critical_i1));
  InflatedDome out;
  // A later state overhanging its clamp (every later state of the membranes tried): the force
  // searches near zero force close on the first state's branch, whose states lie at positive
  // depths below that higher pole (docs/model.md §17): followed in depth control alone.
  out.later_state = chosen != 1 && !(dome.clamp_slope < boost::math::constants::half_pi<double>());
  out.pressure = dome_pressure(problem);
  out.height = dome.pole_height;
  out.clamp_slope = dome.clamp_slope;
  ScaledSolution& s = out.state;
  s.status = Status::Converged;
  s.configuration = Configuration::Unloaded;
  s.integrated = true;
  s.part_three_stretch = dome.pole_stretch;  // the pole's equibiaxial stretch
  s.max_i1 = dome.max_i1;
  s.max_i1_r = dome.max_i1_r_ref;
  s.max_i1_radius = dome.max_i1_radius;
  s.residual = dome.residual;
  s.evaluations = dome.evaluations;
  // Part I samples (R, t, lambda1, lambda2, h), h climbed from the pole (the dome descends).
  if (options.record_fields) {
    s.part_one.push_back({0.0, 0.0, dome.pole_stretch, dome.pole_stretch, 0.0});
    for (const auto& x : dome.samples) s.part_one.push_back({x.r_ref, x.t, x.l1, x.l2, -x.drop});
  }
  return out;
}

bool overhangs_clamp(const InflatedDome& dome) {
  return !(dome.clamp_slope < boost::math::constants::half_pi<double>());
}

void refuse_dome_past_limit_point(const Problem& held, const InflatedDome& dome,
                                  const SolverOptions& options) {
  // Below a hemisphere the first state lies below any limit point (the limit points of the
  // clamped membranes lie past the hemisphere, §17): only an overhanging dome is asked.
  if (!overhangs_clamp(dome)) return;
  const double p = held.preload.pressure_mpa;
  SolverOptions quiet = options;
  quiet.record_fields = false;
  const InflationAtPressure at = inflate_at_pressure(inflation_problem(held), p, {}, quiet);
  if (!at.ok() || at.states.empty())
    throw PhysicalFailure(
        Status::NoConvergence,
        fmt::format("at {:g} MPa the inflated states are not found: {}", p, at.message));
  const double first = at.states.front().pole_stretch;
  for (const PressureExtremum& e : at.extrema)
    if (e.kind == ExtremumKind::Maximum && e.state.pole_stretch < first)
      throw PastLimitPoint(
          fmt::format("at {:g} MPa the inflated membrane is past its inflation limit point "
                      "({:.6g} MPa, pole stretch {:.5g}; the first state at {:g} MPa has pole "
                      "stretch {:.5g}, another branch): over a sealed chamber the path does not "
                      "continue onto another inflated branch",
                      p,
                      e.state.pressure_mpa,
                      e.state.pole_stretch,
                      p,
                      first),
          e.state.pressure_mpa);
}

}  // namespace puncture::detail
