#include "indentation/sealed_gas.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "indentation/curve_point_from_equilibrium.hpp"
#include "indentation/enclosed_volume.hpp"
#include "indentation/inflated_dome.hpp"
#include "indentation/path_puncture.hpp"
#include "indentation/reported_failure.hpp"
#include "indentation/sealed_global_limit.hpp"
#include "indentation/sealed_path_work.hpp"
#include "indentation/solver_scales.hpp"
#include "indentation/stored_energy.hpp"
#include "numerics/root_in_bracket.hpp"

namespace puncture::detail {

namespace {

// A trial pressure's result (a state or a puncture) and the volume its state encloses.
template <class Result>
struct AtPressure {
  Result result;
  double volume_mm3 = std::numeric_limits<double>::quiet_NaN();
};

// A trial pressure whose constant-pressure solve failed: the search reports that status.
struct TrialFailed {
  Status status;
  std::string message;
  double limit_mpa = std::numeric_limits<double>::quiet_NaN();  // past the limit point: its p
};

// Where a search upward stopped: the gas law's root lies above `passed_mpa` (its residual is
// negative there), and the trial pressure just above it, `failed_mpa`, has no state.
struct GasLawStop {
  double passed_mpa = 0.0;
  double failed_mpa = 0.0;
};

SolverOptions with_fields(SolverOptions o) {
  o.record_fields = true;  // the enclosed volume is read on the fields
  return o;
}

// The inflated pole's height above the clamp plane at the problem's pressure [mm]; throws
// PhysicalFailure where that dome lies past the inflation limit point (another branch than the
// sealed one's).  A dome overhanging its clamp below it is indented as it stands (§17).
double dome_height_mm(const Problem& held, const SolverOptions& options) {
  SolverOptions quiet = options;
  quiet.record_fields = false;
  const auto dome = inflated_dome(held, quiet);
  if (!dome) return 0.0;
  refuse_dome_past_limit_point(held, *dome, quiet);
  return dome->height * solver_scales(held).length_mm;
}

// A state at a held pressure seen from the sealed dome: its pole rose by `lift` [mm] above the
// sealed dome's, so depths and deflections (measured from the pole) are `lift` less.
void measure_from_sealed_pole(Equilibrium& e, double lift, double pressure_mpa, double volume_mm3,
                              bool keep_fields) {
  e.depth_mm -= lift;
  for (double& z : e.fields.deflection_mm) z -= lift;
  e.gas = ChamberGas{pressure_mpa, volume_mm3};
  if (!keep_fields) e.fields = {};
}

// The result at the pressure where the gas law holds, searched from `start` (>= P) upward or
// downward but never below P: evaluate(p) gives the result at a held pressure p and its volume.
// The residual (p + p_atm)(V0 + V(p)) - C grows with p (a higher pressure lifts the membrane),
// so from any p the gas law's fixed point p' = C / (V0 + V(p)) - p_atm lies across the root: one
// step brackets it, TOMS 748 refines it.  The evaluated result nearest the law is returned.
// `stop`, if given, is set when the search stops on its way up (a trial halved back 40 times
// still fails).
template <class Result, class Evaluate>
Result at_gas_law(const SealedChamber& c, double start, Evaluate&& evaluate,
                  std::optional<GasLawStop>* stop = nullptr) {
  const double floor = c.sealed_pressure_mpa, p_atm = c.atmospheric_pressure_mpa;
  std::optional<AtPressure<Result>> best;
  double best_residual = std::numeric_limits<double>::infinity();
  double trial = start, trial_volume = 0.0;  // the last trial pressure and its volume
  auto residual = [&](double p) {
    trial = p;
    AtPressure<Result> a;
    try {
      a = evaluate(p);
    } catch (const PastLimitPoint& e) {
      throw TrialFailed{e.status(), e.what(), e.limit_mpa()};
    } catch (const PhysicalFailure& e) {
      throw TrialFailed{e.status(), e.what()};
    } catch (const std::exception& e) {
      throw TrialFailed{Status::NoConvergence,
                        std::string("numerical failure inside the solver: ") + e.what()};
    }
    if (!a.result.ok()) throw TrialFailed{a.result.status, a.result.message};
    trial_volume = a.volume_mm3;
    const double g = c.residual(p, a.volume_mm3);
    if (!std::isfinite(g))
      throw TrialFailed{Status::NoConvergence,
                        fmt::format("the enclosed volume is not finite at {:.6g} MPa", p)};
    if (std::abs(g) < best_residual) {
      best_residual = std::abs(g);
      best = std::move(a);
    }
    return g;
  };
  // The next trial from p with residual g: the law's fixed point, or (where the membrane
  // displaces more than the whole chamber, V0 + V <= 0) the absolute pressure doubled.
  auto step = [&](double p, double g) {
    const double gas_volume = c.gas_volume_mm3 + trial_volume;
    if (g < 0.0 && !(gas_volume > 0.0)) return 2.0 * (p + p_atm) - p_atm;
    return std::max(c.gas_content_n_mm() / gas_volume - p_atm, floor);
  };
  try {
    double lo = std::max(start, floor);
    double g_lo = residual(lo);
    if (g_lo == 0.0 || (g_lo > 0.0 && lo == floor)) return best->result;
    // Fixed-point steps until the residual changes sign (one, where V grows with p).
    double hi = lo, g_hi = g_lo;
    for (int k = 0; k < 30 && (g_hi < 0.0) == (g_lo < 0.0); ++k) {
      lo = hi;
      g_lo = g_hi;
      hi = step(lo, g_lo);
      if (hi == lo) return best->result;  // the law holds to the last bit of p
      // A step up may overshoot to a pressure no dome holds (past a limit point) while the root
      // lies below it: such a trial is moved halfway back towards lo, up to 40 times.  Past the
      // inflation limit point, whose pressure the failure knows, the first trial goes just below
      // it (1e-3 of the way from lo): a residual still negative there puts the law's root past
      // the limit point, on no state of the sealed branch.  Where that trial has no state
      // either, the halving goes on from it.
      std::optional<TrialFailed> past_limit;
      bool near_limit = false;  // hi is the trial just below the limit point
      for (int halving = 0;; ++halving) {
        try {
          g_hi = residual(hi);
          break;
        } catch (const TrialFailed& f) {
          near_limit = false;
          if (!past_limit && std::isfinite(f.limit_mpa) && f.limit_mpa > lo && hi > lo) {
            past_limit = f;
            near_limit = true;
            hi = lo + (1.0 - 1e-3) * (f.limit_mpa - lo);
            continue;
          }
          if (halving == 40 && hi > lo && g_lo < 0.0 && stop != nullptr) *stop = GasLawStop{lo, hi};
          if (hi < lo || halving == 40) throw;
          hi = lo + 0.5 * (hi - lo);
        }
      }
      if (near_limit && g_hi < 0.0) {
        if (stop != nullptr) *stop = GasLawStop{hi, past_limit->limit_mpa};
        throw *past_limit;
      }
      if (g_hi > 0.0 && hi == floor) return best->result;
    }
    if ((g_hi < 0.0) == (g_lo < 0.0))
      throw TrialFailed{Status::NoConvergence,
                        fmt::format("the chamber's pressure could not be bracketed (last tried "
                                    "{:.8g} MPa)",
                                    hi)};
    close_gas_pressure_bracket(residual, lo, hi, g_lo, g_hi, p_atm);
    // A residual left where the bracket closed on a jump of the volume (another branch's state
    // at one end), never a state off the law: ~1e-12 of C where the law holds.
    if (!(best_residual <= 1e-9 * c.gas_content_n_mm()))
      throw TrialFailed{Status::NoConvergence,
                        fmt::format("the gas law is met to {:.3g} of the gas's content only (the "
                                    "enclosed volume jumps near {:.8g} MPa)",
                                    best_residual / c.gas_content_n_mm(),
                                    trial)};
    return best->result;
  } catch (const TrialFailed& f) {
    Result r;
    r.status = f.status;
    r.message = fmt::format(
        "over the sealed chamber, at a trial gas pressure of {:.6g} MPa: {}", trial, f.message);
    return r;
  }
}

}  // namespace

namespace {

// Where Part II appears on a sealed curve: between the two points whose sliding configurations
// differ, by bisection on the depth to 1e-9 of it; the onset's force is the state's with Part II
// at the final bracket's deep end.  Right at the onset a constant-pressure solve may fail (Part
// II of zero length): a failure once the bracket is within 1e-7 of the depth ends the bisection
// there; earlier, the onset is left empty.
void locate_part_two_onset(const Problem& p, const SealedChamber& c, const SolverOptions& quiet,
                           LoadingCurve& out) {
  for (std::size_t k = 1; k < out.points.size(); ++k) {
    const CurvePoint &a = out.points[k - 1], &b = out.points[k];
    if (a.configuration != Configuration::SlipWithoutPartTwo ||
        b.configuration != Configuration::SlipWithPartTwo)
      continue;
    double lo = a.depth_mm, hi = b.depth_mm, pressure = a.gas->pressure_mpa, force = b.force_n;
    while (hi - lo > 1e-9 * hi) {
      const double mid = 0.5 * (lo + hi);
      const Equilibrium e = sealed_at_depth(p, c, mid, Stage::Slip, quiet, pressure);
      if (!e.ok()) {
        if (hi - lo > 1e-7 * hi) return;
        break;
      }
      if (e.configuration == Configuration::SlipWithPartTwo) {
        hi = mid;
        force = e.force_n;
      } else {
        lo = mid;
        pressure = e.gas->pressure_mpa;
      }
    }
    out.part_two_onset_depth_mm = hi;
    out.part_two_onset_force_n = force;
    return;
  }
}

}  // namespace

Problem at_held_pressure(const Problem& p, double pressure_mpa) {
  Problem held = p;
  held.preload.pressure_mpa = pressure_mpa;
  held.preload.gas_volume_mm3.reset();
  return held;
}

SealedChamber sealed_chamber(const Problem& p, const SolverOptions& options) {
  SealedChamber c;
  c.gas_volume_mm3 = *p.preload.gas_volume_mm3;
  c.atmospheric_pressure_mpa = p.preload.atmospheric_pressure_mpa;
  c.sealed_pressure_mpa = p.preload.pressure_mpa;
  const Problem held = at_held_pressure(p, c.sealed_pressure_mpa);
  c.sealed_height_mm = dome_height_mm(held, options);
  const Equilibrium dome = solve_at_depth(held, 0.0, Stage::Slip, with_fields(options));
  if (!dome.ok()) throw PhysicalFailure(dome.status, dome.message);
  c.sealed_volume_mm3 = enclosed_volume_mm3(dome.fields);
  return c;
}

Equilibrium sealed_at_depth(const Problem& p, const SealedChamber& c, double depth_mm, Stage stage,
                            const SolverOptions& options, double pressure_guess_mpa) {
  return at_gas_law<Equilibrium>(c, pressure_guess_mpa, [&](double pressure) {
    const Problem held = at_held_pressure(p, pressure);
    const double lift = dome_height_mm(held, options) - c.sealed_height_mm;
    // Below the sealing pressure (never searched) the lower pole could lie under the probe.
    AtPressure<Equilibrium> out{
        solve_at_depth(held, std::max(depth_mm + lift, 0.0), stage, with_fields(options))};
    if (out.result.ok()) {
      out.volume_mm3 = enclosed_volume_mm3(out.result.fields);
      measure_from_sealed_pole(out.result, lift, pressure, out.volume_mm3, options.record_fields);
    }
    return out;
  });
}

Equilibrium sealed_at_force(const Problem& p, const SealedChamber& c, double force_n, Stage stage,
                            const SolverOptions& options) {
  return at_gas_law<Equilibrium>(c, c.sealed_pressure_mpa, [&](double pressure) {
    const Problem held = at_held_pressure(p, pressure);
    const double lift = dome_height_mm(held, options) - c.sealed_height_mm;
    AtPressure<Equilibrium> out{solve_at_force(held, force_n, stage, with_fields(options))};
    if (out.result.ok()) {
      out.volume_mm3 = enclosed_volume_mm3(out.result.fields);
      measure_from_sealed_pole(out.result, lift, pressure, out.volume_mm3, options.record_fields);
    }
    return out;
  });
}

namespace {

// The state of a constant-pressure puncture with its fields: at its force, or where that search
// closes on another inflated branch's root (a dome beyond a hemisphere, §17) at its depth, which
// depth control from the dome keeps on the path.
Equilibrium puncture_state(const Problem& held, const PuncturePrediction& at,
                           const SolverOptions& options) {
  Equilibrium state = solve_at_force(held, at.force_n, at.stage, options);
  if (state.ok()) return state;
  Equilibrium by_depth = solve_at_depth(held, at.depth_mm, at.stage, options);
  return by_depth.ok() ? by_depth : state;
}

// The energy to puncture over the chamber: without friction dPi/d(depth) = F along the sealed
// path (docs/model.md §17.1), so the work is Pi at the puncture less Pi at the sealed dome, with
// Pi = U + p_atm (V - V_s) - C ln((V0 + V) / (V0 + V_s)) evaluated as U - P (V - V_s) - C (ln(1 +
// x) - x), x = (V - V_s) / (V0 + V_s) (the terms p_atm dV, each ~300 times the rest, cancel
// analytically).  U and V of both states from fields of 2000 samples (to ~1e-8 of U).  With
// friction the work exceeds the change of Pi by what the friction dissipates: the force is
// integrated along the sealed path instead (sealed_path_work.hpp).
void add_sealed_energy_to_puncture(const Problem& p, const SealedChamber& c,
                                   const SolverOptions& options, PuncturePrediction& puncture) {
  auto note = [&](const std::string& why) {
    puncture.message += (puncture.message.empty() ? "" : "; ") +
                        fmt::format("no energy to puncture over the sealed chamber: {}", why);
  };
  // With friction the work is not a change of energy (friction dissipates): the force's
  // integral along the sealed path itself.
  if (p.friction > 0.0) {
    const SealedPathWork path = sealed_path_work(p, c, puncture.depth_mm, options);
    if (path.work_mj)
      puncture.energy_to_puncture_mj = path.work_mj;
    else
      note(path.why);
    return;
  }
  if (!puncture.state.gas) {
    note("the state at puncture has no gas");
    return;
  }
  SolverOptions fine = options;
  fine.record_fields = true;
  fine.field_points = std::max(options.field_points, 2000);
  const Equilibrium dome =
      solve_at_depth(at_held_pressure(p, c.sealed_pressure_mpa), 0.0, Stage::Slip, fine);
  // The puncture's state at its own pressure, its depth counted from that pressure's dome.
  const Problem held = at_held_pressure(p, puncture.state.gas->pressure_mpa);
  PuncturePrediction at_own = puncture;
  at_own.depth_mm = puncture.depth_mm + dome_height_mm(held, options) - c.sealed_height_mm;
  const Equilibrium at = puncture_state(held, at_own, fine);
  if (!dome.ok() || !at.ok()) {
    note(dome.ok() ? at.message : dome.message);
    return;
  }
  const double v_s = enclosed_volume_mm3(dome.fields), v = enclosed_volume_mm3(at.fields);
  const double x = (v - v_s) / (c.gas_volume_mm3 + v_s);
  const double content = c.gas_content_n_mm();
  puncture.energy_to_puncture_mj =
      stored_energy_nmm(at.fields, p) - stored_energy_nmm(dome.fields, p) -
      c.sealed_pressure_mpa * (v - v_s) - content * (std::log1p(x) - x);
}

}  // namespace

PuncturePrediction sealed_puncture(const Problem& p, const SolverOptions& options) {
  const SealedChamber c = sealed_chamber(p, options);
  SolverOptions search = options;
  search.energy_to_puncture = false;
  std::optional<GasLawStop> stop;
  auto out = at_gas_law<PuncturePrediction>(
      c,
      c.sealed_pressure_mpa,
      [&](double pressure) {
        const Problem held = at_held_pressure(p, pressure);
        const double lift = dome_height_mm(held, options) - c.sealed_height_mm;
        AtPressure<PuncturePrediction> at{puncture_on_path(held, search, false)};
        if (!at.result.ok()) return at;
        // The puncture state with its fields, for its volume.
        Equilibrium state = puncture_state(held, at.result, with_fields(options));
        if (!state.ok()) {
          at.result.status = state.status;
          at.result.message = "the state at puncture: " + state.message;
          return at;
        }
        at.volume_mm3 = enclosed_volume_mm3(state.fields);
        measure_from_sealed_pole(state, lift, pressure, at.volume_mm3, options.record_fields);
        at.result.depth_mm -= lift;
        at.result.state = std::move(state);
        return at;
      },
      &stop);
  // Stopped on the way up by an overhanging dome: said as the global failure it heads for.
  if (!out.ok() && out.status == Status::OutsideModel && stop)
    if (const auto why = heading_for_global_limit(p, options, stop->passed_mpa, stop->failed_mpa))
      out.message = *why + " (" + out.message + ")";
  if (out.ok() && options.energy_to_puncture) add_sealed_energy_to_puncture(p, c, options, out);
  return out;
}

LoadingCurve sealed_loading_curve(const Problem& p, const CurveOptions& curve,
                                  const SolverOptions& options) {
  LoadingCurve out;
  const SealedChamber c = sealed_chamber(p, options);
  out.puncture = sealed_puncture(p, options);
  const bool given = !curve.depths_mm.empty();
  double end_depth = given ? curve.depths_mm.back() : curve.max_depth_mm;
  if (end_depth <= 0.0) {
    if (!out.puncture.ok()) {
      out.status = out.puncture.status;
      out.message = "cannot end the curve at puncture: " + out.puncture.message;
      return out;
    }
    end_depth = out.puncture.depth_mm;
  }
  const int n = given ? static_cast<int>(curve.depths_mm.size()) : curve.points;
  auto grid = [&](int k) {
    if (given) return curve.depths_mm[static_cast<std::size_t>(k)];
    return k == n - 1 ? end_depth : end_depth * k / (n - 1);
  };
  SolverOptions quiet = options;
  quiet.record_fields = false;
  double pressure = c.sealed_pressure_mpa;  // the gas is compressed further at each depth
  for (int k = 0; k < n; ++k) {
    const double depth = grid(k);
    const Equilibrium e = sealed_at_depth(p, c, depth, Stage::Slip, quiet, pressure);
    if (!e.ok()) {
      out.status = e.status;
      out.message = fmt::format("at depth {:.6g} mm: {}", depth, e.message);
      return out;
    }
    pressure = e.gas->pressure_mpa;
    CurvePoint pt = curve_point_from_equilibrium(e, depth);
    pt.beyond_puncture =
        e.beyond_puncture || (out.puncture.ok() && depth > out.puncture.depth_mm * (1.0 + 1e-9));
    pt.gas = e.gas;
    out.points.push_back(pt);
    if (curve.progress) curve.progress(k + 1, n);
  }
  locate_part_two_onset(p, c, quiet, out);
  out.status = Status::Converged;
  return out;
}

}  // namespace puncture::detail
