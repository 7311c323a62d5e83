#pragma once
// Implementation of ForceSolver (included by force_solver.hpp).
#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/roots.hpp>
#include <fmt/format.h>

#include "inverse_stretch.hpp"
#include "shooting.hpp"

namespace puncture::detail {

inline constexpr double kHalfPi = boost::math::constants::half_pi<double>();
// Clamp residual given to a Part I whose meridian turns back towards the axis (t < 0, hoop
// compression) before the clamp: the hoop stretch falls short, so the residual is negative.
inline constexpr double kTurnedBack = -1.0;

template <class Law>
typename ForceSolver<Law>::PartOneRun ForceSolver<Law>::run_part_one(
    double f, double r0, PartOneState x, std::vector<PartOneSample>* samples) const {
  PartOneRun run;
  run.max_i1 = 0.0;
  if (samples) samples->clear();
  const PartOneSystem<Law> system{law_, f, max_i1_};
  double last_l2 = x[2];
  run.ok = integrate_part(system, x, r0, 1.0, s_.integration, [&](double r, const PartOneState& y) {
    const double i1 = first_invariant(y[1], y[2]);
    if (i1 > run.max_i1) {
      run.max_i1 = i1;
      run.max_i1_r = r;
    }
    if (samples) samples->push_back({r, y[0], y[1], y[2], y[3]});
    last_l2 = y[2];
    if (y[0] < 0.0) {  // meridian turned back towards the axis: hoop stretch too small
      run.turned_back = true;
      return false;
    }
    return true;
  });
  // A Part I that fails (locks) on its way with the hoop stretch already below 1 has collapsed
  // towards the axis: it belongs to the negative side of the clamp residual as well.
  if (!run.ok && last_l2 < 1.0) run.turned_back = true;
  if (run.turned_back) run.residual = kTurnedBack;
  if (!run.turned_back) run.residual = x[2] - 1.0;
  run.height = x[3];
  return run;
}

template <class Law>
std::optional<PartOneState> ForceSolver<Law>::stick_start(double f, double edge_l1) const {
  // R = a, lambda2 = 1, s1 from the edge stretch; R s1 sin(phi) = f fixes the slope.
  const double rs1 = s_.a * membrane_stress(law_, edge_l1, 1.0).s1;
  // rs1 < f by round-off only at the vertical exit, where t = 0.
  if (!(rs1 >= f * (1.0 - 1e-12)) || first_invariant(edge_l1, 1.0) >= max_i1_) return std::nullopt;
  return PartOneState{std::sqrt(std::max(0.0, (rs1 - f) * (rs1 + f))), edge_l1, 1.0, 0.0};
}

// Slope phi in [0, pi/2] with sin(phi) exp(mu phi) = kappa (vertical balance at the corner with
// the capstan ratio); pi/2 when kappa >= exp(mu pi/2).
inline double corner_slope(double kappa, double mu) {
  if (kappa >= std::exp(mu * kHalfPi)) return kHalfPi;
  std::uintmax_t iterations = 100;
  return boost::math::tools::newton_raphson_iterate(
      [&](double phi) {
        const double e = std::exp(mu * phi);
        return std::make_pair(std::sin(phi) * e - kappa, (std::cos(phi) + mu * std::sin(phi)) * e);
      },
      std::asin(std::min(kappa, 1.0)) * 0.5, 0.0, kHalfPi, 52, iterations);
}

template <class Law>
std::optional<PartOneState> ForceSolver<Law>::slip_start(double f, double l3_stretch,
                                                          double* slope, double* ratio) const {
  const double r_corner = s_.a / l3_stretch;
  const double s_eq = membrane_stress(law_, l3_stretch, l3_stretch).s1;
  if (!(s_eq > 0.0) || !std::isfinite(s_eq)) return std::nullopt;
  const double phi = corner_slope(f / (r_corner * s_eq), s_.mu);
  const double s1 = s_eq * std::exp(s_.mu * phi);  // capstan: the outer side pulls harder
  const auto l1 = invert_radial_stress(law_, s1, l3_stretch, l3_stretch);
  if (!l1) return std::nullopt;
  if (slope) *slope = phi;
  if (ratio) *ratio = std::exp(s_.mu * phi);
  return PartOneState{r_corner * s1 * std::cos(phi), *l1, l3_stretch, 0.0};
}

template <class Law>
std::optional<PartOneState> ForceSolver<Law>::side_start(double f, double top_l2) const {
  // Part I leaves the side vertically at R = a / lambda2: R s1 = f, t = 0.
  const auto l1 = invert_radial_stress(law_, f * top_l2 / s_.a, top_l2);
  if (!l1) return std::nullopt;
  return PartOneState{0.0, *l1, top_l2, 0.0};
}

template <class Law>
std::optional<double> ForceSolver<Law>::part_two_onset_stretch(double f) const {
  // s_eq(L) / L = f exp(-mu pi/2) / a, increasing in L from 0 at L = 1.
  const double target = f * std::exp(-s_.mu * kHalfPi) / s_.a;
  auto g = [&](double l) -> std::optional<double> {
    const double s = membrane_stress(law_, l, l).s1;
    if (!std::isfinite(s) || first_invariant(l, l) >= max_i1_) return std::nullopt;
    return s / l - target;
  };
  // g is undefined past the equibiaxial locking stretch; shoot_increasing treats that as beyond.
  const auto root = shoot_increasing(g, 1.0, -target, locking_radial_stretch(law_, 1.0), 200);
  if (!root || !g(*root)) return std::nullopt;
  return root;
}

template <class Law>
std::optional<double> ForceSolver<Law>::part_two_indicator(double f) const {
  const auto onset = part_two_onset_stretch(f);
  if (!onset) return std::nullopt;
  const auto x0 = slip_start(f, *onset, nullptr, nullptr);
  if (!x0) return std::nullopt;
  const auto run = run_part_one(f, s_.a / *onset, *x0, nullptr);
  return run.ok || run.turned_back ? std::optional<double>(run.residual) : std::nullopt;
}

template <class Law>
ScaledSolution ForceSolver<Law>::stick(double f) const {
  ScaledSolution sol;
  sol.f = f;
  sol.configuration = Configuration::Stick;
  int evals = 0;
  auto residual = [&](double l1) -> std::optional<double> {
    const auto x0 = stick_start(f, l1);
    if (!x0) return std::nullopt;
    ++evals;
    const auto run = run_part_one(f, s_.a, *x0, nullptr);
    return run.ok || run.turned_back ? std::optional<double>(run.residual) : std::nullopt;
  };
  // Lowest edge stretch: Part I leaves the edge vertically (R s1 = f).
  const auto l1_vertical = invert_radial_stress(law_, f / s_.a, 1.0);
  if (!l1_vertical) {
    sol.status = Status::BeyondLocking;
    sol.message = "the force exceeds what the membrane at the indenter's edge can carry";
    return sol;
  }
  const double g0 = residual(*l1_vertical).value_or(kBeyondDomain);
  if (g0 >= 0.0) {
    sol.status = Status::StickWrapsSide;
    sol.message = fmt::format(
        "at this force a membrane held at the indenter's edge would have to wrap its side "
        "(clamp residual {:.3g} with a vertical edge)",
        g0);
    return sol;
  }
  const auto root = shoot_increasing(residual, *l1_vertical, g0,
                                     locking_radial_stretch(law_, 1.0), s_.max_iterations);
  if (!root) {
    sol.message = "stick shooting found no edge stretch meeting the clamp condition";
    sol.evaluations = evals;
    return sol;
  }
  const auto x0 = stick_start(f, *root);
  const auto run = x0 ? run_part_one(f, s_.a, *x0, &sol.part_one) : PartOneRun{};
  sol.evaluations = evals + 1;
  if (!run.ok) {
    sol.message = "stick solution could not be integrated to the clamp";
    return sol;
  }
  sol.r_corner = sol.r_top = s_.a;
  sol.depth = run.height;
  sol.corner_slope = std::atan2(f, (*x0)[0]);
  sol.tension_ratio = std::numeric_limits<double>::infinity();
  sol.edge_s1 = membrane_stress(law_, *root, 1.0).s1;
  sol.max_i1 = run.max_i1;
  sol.max_i1_r = run.max_i1_r;
  sol.residual = run.residual;
  sol.status = std::abs(run.residual) <= s_.shooting_tol ? Status::Converged : Status::NoConvergence;
  if (!sol.ok()) sol.message = fmt::format("stick shooting stalled at clamp residual {:.3g}", run.residual);
  return sol;
}

template <class Law>
ScaledSolution ForceSolver<Law>::slip(double f) const {
  ScaledSolution sol;
  sol.f = f;
  const auto onset = part_two_onset_stretch(f);
  if (!onset) {
    sol.status = Status::BeyondLocking;
    sol.message = "the force needs a stretch under the tip beyond the material's locking limit";
    return sol;
  }
  int evals = 0;
  auto without_two = [&](double l3) -> std::optional<double> {
    const auto x0 = slip_start(f, l3, nullptr, nullptr);
    if (!x0) return std::nullopt;
    ++evals;
    const auto run = run_part_one(f, s_.a / l3, *x0, nullptr);
    return run.ok || run.turned_back ? std::optional<double>(run.residual) : std::nullopt;
  };
  const double g_onset = without_two(*onset).value_or(kBeyondDomain);
  if (g_onset < 0.0) {
    // Part I reaches the clamp with lambda2 < 1 even when it leaves the corner vertically, so a
    // larger Part III stretch (and a flatter exit) is needed: no Part II.
    const double cap = locking_radial_stretch(law_, 1.0);
    const auto root = shoot_increasing(without_two, *onset, g_onset, cap, s_.max_iterations);
    if (!root) {
      sol.message = "slip shooting (without Part II) found no Part III stretch meeting the clamp";
      sol.evaluations = evals;
      return sol;
    }
    double slope = 0.0, ratio = 1.0;
    const auto x0 = slip_start(f, *root, &slope, &ratio);
    const auto run = x0 ? run_part_one(f, s_.a / *root, *x0, &sol.part_one) : PartOneRun{};
    sol.evaluations = evals + 1;
    if (!run.ok) {
      sol.message = "slip solution could not be integrated to the clamp";
      return sol;
    }
    sol.configuration = Configuration::SlipWithoutPartTwo;
    sol.part_three_stretch = *root;
    sol.r_corner = sol.r_top = s_.a / *root;
    sol.depth = run.height;
    sol.corner_slope = slope;
    sol.tension_ratio = ratio;
    sol.edge_s1 = membrane_stress(law_, (*x0)[1], *root).s1;
    sol.max_i1 = run.max_i1;
    sol.max_i1_r = run.max_i1_r;
    sol.residual = run.residual;
    sol.status = std::abs(run.residual) <= s_.shooting_tol ? Status::Converged : Status::NoConvergence;
    if (!sol.ok()) sol.message = fmt::format("slip shooting stalled at clamp residual {:.3g}", run.residual);
    return sol;
  }
  // Part II exists: shoot on lambda2 where Part I leaves the side (between 1 and the onset).
  auto with_two = [&](double top_l2) -> std::optional<double> {
    const auto x0 = side_start(f, top_l2);
    if (!x0) return std::nullopt;
    ++evals;
    const auto run = run_part_one(f, s_.a / top_l2, *x0, nullptr);
    return run.ok || run.turned_back ? std::optional<double>(run.residual) : std::nullopt;
  };
  const double g_one = with_two(1.0).value_or(kBeyondDomain);
  if (g_one >= 0.0) {
    sol.status = Status::BeyondLocking;
    sol.message = "the force is beyond what the membrane on the indenter's side can carry";
    return sol;
  }
  const auto root = shoot_increasing(with_two, 1.0, g_one, *onset, s_.max_iterations);
  sol.evaluations = evals;
  if (!root) {
    sol.message = "slip shooting (with Part II) found no boundary stretch meeting the clamp";
    return sol;
  }
  return finish_part_two(f, *root, std::move(sol));
}

template <class Law>
ScaledSolution ForceSolver<Law>::finish_part_two(double f, double top_l2,
                                                 ScaledSolution sol) const {
  const auto x0 = side_start(f, top_l2);
  const double r_top = s_.a / top_l2;
  const auto run = x0 ? run_part_one(f, r_top, *x0, &sol.part_one) : PartOneRun{};
  ++sol.evaluations;
  if (!run.ok) {
    sol.message = "slip solution with Part II could not be integrated to the clamp";
    return sol;
  }
  // March down the side until the capstan condition with Part III holds (Eq. 22 with Eq. 20):
  // s1(lambda1, a/R) = exp(mu pi/2) s_eq(a/R).
  const double capstan = std::exp(s_.mu * kHalfPi);
  auto corner_gap = [&](double r, const PartTwoState& y) {
    const double l2 = s_.a / r;
    return membrane_stress(law_, y[0], l2).s1 - capstan * membrane_stress(law_, l2, l2).s1;
  };
  const PartTwoSystem<Law> side{law_, s_.a, s_.mu, s_.equation, max_i1_};
  PartTwoState y{(*x0)[1], 0.0};
  double r_prev = r_top, r_hit = -1.0;
  PartTwoState y_prev = y;
  double max_i1 = run.max_i1, max_i1_r = run.max_i1_r;
  sol.part_two.clear();
  const double r_floor = s_.a / locking_radial_stretch(law_, 1.0);
  const bool ok = integrate_part(side, y, r_top, std::isfinite(r_floor) ? r_floor : 1e-6 * s_.a,
                                 s_.integration, [&](double r, const PartTwoState& state) {
                                   if (corner_gap(r, state) <= 0.0) {
                                     r_hit = r;
                                     return false;
                                   }
                                   r_prev = r;
                                   y_prev = state;
                                   sol.part_two.push_back({r, state[0], state[1]});
                                   return true;
                                 });
  if (!ok || r_hit < 0.0) {
    sol.status = Status::BeyondLocking;
    sol.message = "Part II reaches the locking stretch before meeting the capstan condition";
    return sol;
  }
  // Locate the corner inside the last step with single Dormand-Prince steps from the last state.
  boost::numeric::odeint::runge_kutta_dopri5<PartTwoState> rk;
  auto state_at = [&](double r) {
    PartTwoState out;
    rk.reset();
    rk.do_step(side, y_prev, r_prev, out, r - r_prev);
    return out;
  };
  std::uintmax_t iterations = 100;
  const auto bracket = boost::math::tools::toms748_solve(
      [&](double r) { return corner_gap(r, state_at(r)); }, r_hit, r_prev,
      boost::math::tools::eps_tolerance<double>(50), iterations);
  const double r_corner = 0.5 * (bracket.first + bracket.second);
  const PartTwoState corner = state_at(r_corner);
  sol.part_two.push_back({r_corner, corner[0], corner[1]});
  for (const auto& p : sol.part_two) {
    const double i1 = first_invariant(p[1], s_.a / p[0]);
    if (i1 > max_i1) {
      max_i1 = i1;
      max_i1_r = p[0];
    }
  }
  const double l3_stretch = s_.a / r_corner;
  sol.configuration = Configuration::SlipWithPartTwo;
  sol.part_three_stretch = l3_stretch;
  sol.r_corner = r_corner;
  sol.r_top = r_top;
  sol.part_two_length = corner[1];
  sol.depth = run.height + corner[1];
  sol.corner_slope = kHalfPi;
  sol.tension_ratio = membrane_stress(law_, corner[0], l3_stretch).s1 /
                      membrane_stress(law_, l3_stretch, l3_stretch).s1;
  sol.edge_s1 = membrane_stress(law_, corner[0], l3_stretch).s1;
  sol.max_i1 = max_i1;
  sol.max_i1_r = max_i1_r;
  sol.residual = run.residual;
  sol.status = std::abs(run.residual) <= s_.shooting_tol ? Status::Converged : Status::NoConvergence;
  if (!sol.ok()) sol.message = fmt::format("slip shooting stalled at clamp residual {:.3g}", run.residual);
  return sol;
}

}  // namespace puncture::detail
