#pragma once
// The largest I1 along an integrated part, to the integration's accuracy rather than the step
// spacing: the observer keeps the samples around the largest one, and a Brent search over the
// steps beside it (each re-taken as one Runge-Kutta step from
// its accepted start) finds the maximum between samples.
#include <boost/math/tools/minima.hpp>
#include <limits>
#include <utility>

#include "numerics/integrate.hpp"

namespace puncture::detail {

template <class State>
class InteriorMaximum {
 public:
  void observe(double r, const State& x, double value) {
    if (value > best_value_) {
      best_value_ = value;
      best_r_ = r;
      best_state_ = x;
      has_before_ = has_last_;
      before_r_ = last_r_;
      before_state_ = last_state_;
      has_after_ = false;
      just_set_ = true;
    } else if (just_set_) {
      has_after_ = true;
      after_r_ = r;
      just_set_ = false;
    }
    has_last_ = true;
    last_r_ = r;
    last_state_ = x;
  }

  struct Maximum {
    double value;
    double r;
    State state;
  };

  // step(r0, x0, r) integrates one step from (r0, x0) to r; value(r, x) is the quantity.
  template <class Step, class Value>
  Maximum refine(Step&& step, Value&& value) const {
    Maximum best{best_value_, best_r_, best_state_};
    auto search = [&](double r0, const State& x0, double r1) {
      const auto [lo, hi] = std::minmax(r0, r1);
      std::uintmax_t iterations = 60;
      const auto found = boost::math::tools::brent_find_minima(
          [&](double r) { return -value(r, step(r0, x0, r)); }, lo, hi, 40, iterations);
      if (-found.second > best.value)
        best = {-found.second, found.first, step(r0, x0, found.first)};
    };
    // The largest sample at an end of the part still leaves the step beside it to search: the
    // maximum may lie inside it, above both of its ends.
    if (has_before_) search(before_r_, before_state_, best_r_);
    if (has_after_) search(best_r_, best_state_, after_r_);
    return best;
  }

  Maximum sampled() const { return {best_value_, best_r_, best_state_}; }
  bool observed() const { return has_last_; }

 private:
  double best_value_ = -std::numeric_limits<double>::infinity();
  double best_r_ = 0.0, before_r_ = 0.0, after_r_ = 0.0, last_r_ = 0.0;
  State best_state_{}, before_state_{}, last_state_{};
  bool has_before_ = false, has_after_ = false, has_last_ = false, just_set_ = false;
};

// The largest value(r, x) along a part integrated with `system`: refined between the samples by
// re-taking each adjacent step as one Runge-Kutta step; the sampled maximum when a re-taken step
// leaves the material's domain.
template <class State, class System, class Value>
typename InteriorMaximum<State>::Maximum refined_maximum(const InteriorMaximum<State>& samples,
                                                         const System& system, Value&& value) {
  try {
    IntegrationStepper<State> rk;
    return samples.refine(
        [&](double ra, const State& xa, double rb) {
          State out;
          rk.do_step(system, xa, ra, out, rb - ra);
          if (!all_finite(out)) throw IntegrationFailure{};
          return out;
        },
        value);
  } catch (const IntegrationFailure&) {
    return samples.sampled();
  }
}

}  // namespace puncture::detail
