#include "indentation/inflated_dome.hpp"

#include <fmt/format.h>

#include <boost/math/constants/constants.hpp>

#include "indentation/reported_failure.hpp"
#include "indentation/solver_scales.hpp"
#include "inflation/scaled_inflation.hpp"
#include "puncture/inflation.hpp"

namespace puncture::detail {

std::optional<InflatedDome> inflated_dome(const Problem& problem, const SolverOptions& options) {
  const double p_mpa = problem.preload.pressure_mpa;
  if (p_mpa == 0.0) return std::nullopt;
  const InflationProblem membrane = inflation_problem(problem);
  SolverOptions quiet = options;
  quiet.record_fields = false;
  const InflationAtPressure at = inflate_at_pressure(membrane, p_mpa, {}, quiet);
  if (!at.ok()) {
    if (at.status == Status::NotReached)
      throw PhysicalFailure(
          Status::LimitLoad,
          fmt::format("the membrane cannot hold the pressure {:g} MPa before the indenter touches "
                      "it: it bursts or snaps through while it is inflated ({})",
                      p_mpa,
                      at.message));
    throw PhysicalFailure(
        at.status, "the inflated membrane before contact could not be solved: " + at.message);
  }
  const InflationState& first = at.states.front();
  SolverOptions sampled = options;
  sampled.record_fields = true;
  const ScaledInflation dome = solve_inflation(
      membrane, first.pole_stretch, sampled, first.normalized_pressure / membrane.prestretch);
  if (!dome.ok())
    throw PhysicalFailure(
        dome.status, "the inflated membrane before contact could not be solved: " + dome.message);
  if (!(dome.clamp_slope < boost::math::constants::half_pi<double>()))
    throw PhysicalFailure(
        Status::OutsideModel,
        fmt::format(
            "at {:g} MPa the inflated membrane overhangs its clamp (slope {:.4g} rad at the "
            "clamp): indenting a dome beyond a hemisphere is not modelled",
            p_mpa,
            dome.clamp_slope));
  InflatedDome out;
  out.pressure = dome_pressure(problem);
  out.height = dome.pole_height;
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

}  // namespace puncture::detail
