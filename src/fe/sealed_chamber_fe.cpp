// The finite elements over a sealed chamber: the gas law's root in the pressure around the
// elements' constant-pressure states.
#include "fe/sealed_chamber_fe.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "fe/inflated_dome_fe.hpp"
#include "fe/probe_profiles.hpp"
#include "fe/smooth_probe.hpp"
#include "numerics/root_in_bracket.hpp"

namespace puncture::fe {
namespace {

Problem held_at(const Problem& p, double pressure_mpa) {
  Problem held = p;
  held.preload.pressure_mpa = pressure_mpa;
  held.preload.gas_volume_mm3.reset();
  return held;
}

// A trial pressure's state, or why it has none.
struct GasTrialFailed {
  FeState state;
};

class SealedGasFe {
 public:
  SealedGasFe(const Problem& p, const FeOptions& options)
      : problem_(p), options_(options), clamp_mm_(reference_clamp_radius_mm(p)) {
    profile_ = sharp_flat_punch(p.indenter)
                   ? sharp_punch_profile(std::get<FlatPunch>(p.indenter), clamp_mm_)
                   : smooth_profile(p.indenter, clamp_mm_);
  }

  // The sealed dome: the elements' dome at the sealing pressure, its volume and height.
  FeState seal() {
    const FeDome dome = solve_dome(held_at(problem_, problem_.preload.pressure_mpa), options_);
    if (dome.state.ok()) {
      sealed_height_mm_ = dome.height * clamp_mm_;
      sealed_volume_mm3_ = dome.state.volume_mm3;
    }
    return dome.state;
  }

  // (P + p_atm)(V0 + V_s) [N mm].
  double content() const {
    return (problem_.preload.pressure_mpa + problem_.preload.atmospheric_pressure_mpa) *
           (*problem_.preload.gas_volume_mm3 + sealed_volume_mm3_);
  }

  // The constant-pressure state at `pressure_mpa` whose probe stands `depth_mm` below the sealed
  // dome's pole: the elements' own dome at that pressure stands higher by its lift.
  FeState at_pressure(double depth_mm, double pressure_mpa) const {
    const Problem held = held_at(problem_, pressure_mpa);
    const FeDome dome = solve_dome(held, options_);
    if (!dome.state.ok()) throw GasTrialFailed{dome.state};
    const double lift = dome.height * clamp_mm_ - sealed_height_mm_;
    FeState s = solve_smooth_probe(held, *profile_, {depth_mm + lift}, options_).front();
    if (!s.ok()) throw GasTrialFailed{s};
    s.depth_mm = depth_mm;
    s.gas_pressure_mpa = pressure_mpa;
    return s;
  }

  // The state at `depth_mm` where the gas law holds, searched from `start_mpa` (>= P): the
  // residual (p + p_atm)(V0 + V(p)) - C grows with p (a higher pressure lifts the membrane), so
  // the law's fixed point p' = C / (V0 + V(p)) - p_atm lies across the root from p; TOMS 748
  // refines the bracket to 1e-12 of the absolute pressure.
  FeState at_depth(double depth_mm, double start_mpa) const {
    const double p_atm = problem_.preload.atmospheric_pressure_mpa;
    const double v0 = *problem_.preload.gas_volume_mm3, c = content();
    const double floor = problem_.preload.pressure_mpa;
    std::optional<FeState> best;
    double best_residual = std::numeric_limits<double>::infinity();
    double last_volume = 0.0;  // the last trial's
    auto residual = [&](double pressure) {
      FeState s = at_pressure(depth_mm, pressure);
      last_volume = s.volume_mm3;
      const double g = (pressure + p_atm) * (v0 + s.volume_mm3) - c;
      if (std::abs(g) < best_residual) {
        best_residual = std::abs(g);
        best = std::move(s);
      }
      return g;
    };
    // The next trial from p: the law's fixed point, or where the membrane displaces more than
    // the whole chamber (V0 + V <= 0) the absolute pressure doubled.
    auto step = [&](double pressure, double g) {
      const double gas = v0 + last_volume;
      if (g < 0.0 && !(gas > 0.0)) return 2.0 * (pressure + p_atm) - p_atm;
      return std::max(c / gas - p_atm, floor);
    };
    try {
      double lo = std::max(start_mpa, floor), g_lo = residual(lo);
      double hi = lo, g_hi = g_lo;
      bool done = g_lo == 0.0 || (g_lo > 0.0 && lo == floor);
      for (int k = 0; k < 30 && !done && (g_hi < 0.0) == (g_lo < 0.0); ++k) {
        lo = hi;
        g_lo = g_hi;
        hi = step(lo, g_lo);
        if (hi == lo) {
          done = true;
          break;
        }
        // A step up may overshoot to a pressure whose state the elements do not reach (the
        // probe deeper under a higher dome, past the material's locking): halved back towards
        // lo, up to 40 times, as the shooting's search does.
        for (int halving = 0;; ++halving) {
          try {
            g_hi = residual(hi);
            break;
          } catch (const GasTrialFailed&) {
            if (!(hi > lo) || halving == 40) throw;
            hi = lo + 0.5 * (hi - lo);
          }
        }
        done = g_hi == 0.0 || (g_hi > 0.0 && hi == floor);
      }
      if (!done && (g_hi < 0.0) != (g_lo < 0.0)) {
        detail::close_gas_pressure_bracket(residual, lo, hi, g_lo, g_hi, p_atm);
      }
    } catch (const GasTrialFailed& f) {
      FeState failed = f.state;
      failed.depth_mm = depth_mm;
      failed.message = "over the sealed chamber: " + failed.message;
      return failed;
    }
    // The law's residual relative to C: the elements' volume resolves it to ~1e-12.
    if (!(best_residual <= 1e-9 * c)) {
      FeState failed = *best;
      failed.status = Status::NoConvergence;
      failed.message = fmt::format(
          "over the sealed chamber the gas law is not met at {:.6g} mm (residual {:.3g} of "
          "its content)",
          depth_mm,
          best_residual / c);
      return failed;
    }
    return *best;
  }

 private:
  const Problem& problem_;
  const FeOptions& options_;
  double clamp_mm_;
  std::unique_ptr<RigidProfile> profile_;
  double sealed_height_mm_ = 0.0;
  double sealed_volume_mm3_ = 0.0;
};

}  // namespace

std::vector<FeState> solve_sealed_chamber(const Problem& problem,
                                          const std::vector<double>& depths_mm,
                                          const FeOptions& options) {
  SealedGasFe gas(problem, options);
  std::vector<FeState> states;
  const FeState dome = gas.seal();
  double pressure = problem.preload.pressure_mpa;  // the gas compresses as the probe goes in
  for (double d : depths_mm) {
    if (!dome.ok()) {
      FeState failed = dome;
      failed.parts.clear();
      failed.depth_mm = d;
      states.push_back(failed);
      continue;
    }
    states.push_back(gas.at_depth(d, pressure));
    if (states.back().ok()) pressure = states.back().gas_pressure_mpa;
  }
  return states;
}

}  // namespace puncture::fe
