#pragma once
// Adaptive Runge-Kutta integration of one membrane part along the reference radius, with an
// observer at every accepted step.  A right-hand side whose state leaves the material's domain
// (locking, non-positive stretch) returns non-finite derivatives (outside_domain); a trial step
// that met one is retried smaller, and a state that cannot go on ends the integration with
// `false`.  (They used to throw: a throw and its unwinding per failed trial took 3/4 of the
// time of solves that march up to locking, e.g. a neo-Hookean Part II near its limit load.)
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <limits>
#include <optional>

namespace puncture::detail {

// Thrown by helpers that evaluate one step outside an integration (refined_maximum's re-taken
// steps, root searches inside a step) when it leaves the domain.
struct IntegrationFailure {};

// What a right-hand side returns outside the material's domain.
template <class State>
void outside_domain(State& dx) {
  dx.fill(std::numeric_limits<double>::quiet_NaN());
}

template <class State>
bool all_finite(const State& x) {
  for (const double v : x)
    if (!std::isfinite(v)) return false;
  return true;
}

struct IntegrationSettings {
  double rel_tol;
  double abs_tol;
  int max_steps;
  double max_step = 0.0;  // largest step |dR| (0: no limit); used to sample fields densely
};

// Runge-Kutta-Fehlberg 7(8): at the 1e-10 tolerance the solver needs, it takes about a fifth of
// the steps of Dormand-Prince 5(4) and halves the time of a shooting (bench/).
template <class State>
using IntegrationStepper = boost::numeric::odeint::runge_kutta_fehlberg78<State>;

template <class State, class System, class Observer>
bool integrate_part(const System& system, State& x, double r_begin, double r_end,
                    const IntegrationSettings& settings, Observer&& observe) {
  namespace odeint = boost::numeric::odeint;
  auto stepper =
      odeint::make_controlled(settings.abs_tol, settings.rel_tol, IntegrationStepper<State>());
  const double span = r_end - r_begin;
  const double direction = span > 0.0 ? 1.0 : -1.0;
  double r = r_begin;
  double dr = 1e-3 * span;
  const double min_step = 1e-14 * std::abs(span);
  if (!observe(r, x)) return true;
  int attempts = 0;
  State trial;
  while (direction * (r_end - r) > 1e-15 * std::abs(span)) {
    if (++attempts > settings.max_steps) return false;
    if (settings.max_step > 0.0 && std::abs(dr) > settings.max_step)
      dr = direction * settings.max_step;
    // Land exactly on the end, never leaving a sliver of a step behind.
    if (direction * (r + dr - r_end) > -1e-12 * std::abs(span)) dr = r_end - r;
    const double r_before = r, dr_before = dr;
    const bool accepted = stepper.try_step(system, x, r, trial, dr) == odeint::success;
    if (!all_finite(trial)) {  // a stage left the domain: whatever the error estimate said
      r = r_before;
      dr = 0.25 * dr_before;
      if constexpr (requires { stepper.reset(); }) stepper.reset();
    } else if (accepted) {
      x = trial;
      if (!observe(r, x)) return true;  // the observer found what it looked for
    }
    if (std::abs(dr) < min_step && direction * (r_end - r) > 1e-15 * std::abs(span)) return false;
  }
  return true;
}

// The state at r_end from (r_begin, x), integrated adaptively; empty if it cannot be reached.
template <class State, class System>
std::optional<State> advance(const System& system, State x, double r_begin, double r_end,
                             const IntegrationSettings& settings) {
  if (r_end == r_begin) return x;
  if (!integrate_part(
          system, x, r_begin, r_end, settings, [](double, const State&) { return true; }))
    return std::nullopt;
  return x;
}

// Within an accepted step: one Runge-Kutta step from its start (cheap, and as accurate as the
// step itself), or, if a stage of that step leaves the material's domain, an adaptive advance.
template <class State, class System>
std::optional<State> step_or_advance(const System& system, const State& x, double r_begin,
                                     double r_end, const IntegrationSettings& settings) {
  IntegrationStepper<State> rk;
  State out;
  rk.do_step(system, x, r_begin, out, r_end - r_begin);
  if (all_finite(out)) return out;
  return advance(system, x, r_begin, r_end, settings);
}

}  // namespace puncture::detail
