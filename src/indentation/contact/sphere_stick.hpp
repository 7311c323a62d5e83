#pragma once
// The stick stage on the sphere-tipped probe (docs/model.md §15.4): each material point of the
// cap holds the polar angle theta where it touched the sphere.  The contact map theta(R) is built
// along the loading history, parametrised by the contact edge's reference radius R_c: the point
// R_c joins at the edge with the free membrane's meridional stretch there, so
//   dtheta_c/dR_c = lambda1_edge(R_c, theta_c) / a,
// lambda1_edge the stretch with which Part I, leaving the sphere tangentially at (R_c, theta_c)
// with lambda2 = a sin(theta_c) / R_c, meets the clamp.  Classical Runge-Kutta (fourth order) on
// a uniform grid in R_c from the first touch (R_c = 0, theta = 0, lambda1 = L0); each stage solves
// the edge's lambda1 (TOMS 748 on Part I's clamp residual); near the first touch, where the
// march is stiff, in sub-steps of a quarter of R (build()).  Stuck points keep their stretches, so
// their tractions are frozen too: the traction demand of a point is the one it had when it joined.
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "indentation/contact/contact_model.hpp"
#include "indentation/free_part.hpp"
#include "mechanics/inverse_stretch.hpp"
#include "numerics/root_from_guess.hpp"
#include "numerics/shooting.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// One grid point of the history: the material point R that joined the contact at the edge.
struct StuckPoint {
  double r = 0.0;      // reference radius / (A / L0)
  double theta = 0.0;  // polar angle where it holds on the sphere
  double l1 = 1.0;     // its meridional stretch (the free membrane's at the edge when it joined)
  double f = 0.0;      // the force then, / (2 pi G H A / L0)
  double depth = 0.0;  // the depth then, / (A / L0)
};

// Why the history ends before the grid does.
enum class StickHistoryEnd {
  Equator,  // the edge reaches the sphere's equator: a held membrane would wrap the cylinder
  Locking,  // no Part I from the edge meets the clamp (the material locks)
};

// The tractions the sphere must supply to hold a stuck point (normalised by G H / A): the
// contact pressure p (normal balance, as sliding) and the tangential traction tau towards the
// pole, tau r lambda1 = d(R s1)/dR - s2 cos(theta) (tangential balance).
struct StuckTraction {
  double pressure = 0.0;
  double tangential = 0.0;
};

template <class Law>
class SphereStickHistory {
 public:
  // Grid steps over R_c in [0, pi a / (2 L0)]: the edge reaches the equator before the grid's end
  // (lambda1 >= L0 along the history).
  static constexpr int kDefaultSteps = 400;

  SphereStickHistory(const FreePart<Law>& part_one, double a, int steps = kDefaultSteps)
      : part_one_(part_one), a_(a), steps_(steps) {}

  // The history's grid points from the first touch (built on the first call).
  const std::vector<StuckPoint>& points() const {
    if (!built_) build();
    return points_;
  }
  StickHistoryEnd end() const {
    if (!built_) build();
    return end_;
  }
  double step() const { return 0.5 * kPi * a_ / part_one_.prestretch() / steps_; }
  // The stretch of the first material touched: the inflated pole's under a gas pressure (docs/
  // model.md §17.3), else the pre-stretch L0.
  double first_touch_stretch() const {
    const double pole = part_one_.settings().dome_pole_stretch;
    return pole > 0.0 ? pole : part_one_.prestretch();
  }
  // The gas pressure's resultant on the cap up to theta, P (a sin(theta))^2 / 2 (0 without).
  double gas_load(double theta) const {
    const double rho = a_ * std::sin(theta);
    return 0.5 * part_one_.pressure() * rho * rho;
  }

  // theta at reference radius r <= the last grid point's: the cubic Hermite interpolant of
  // (theta_k, lambda1_k / a), exact to O(h^4) as the Runge-Kutta history itself.
  std::optional<double> theta_at(double r) const {
    const auto& p = points();
    if (p.size() < 2 || !(r >= 0.0) || r > p.back().r) return std::nullopt;
    const std::size_t k = std::min(p.size() - 2, static_cast<std::size_t>(std::floor(r / step())));
    const double h = p[k + 1].r - p[k].r, s = (r - p[k].r) / h;
    const double h00 = (1.0 + 2.0 * s) * (1.0 - s) * (1.0 - s), h10 = s * (1.0 - s) * (1.0 - s);
    const double h01 = s * s * (3.0 - 2.0 * s), h11 = s * s * (s - 1.0);
    return h00 * p[k].theta + h10 * h * p[k].l1 / a_ + h01 * p[k + 1].theta +
           h11 * h * p[k + 1].l1 / a_;
  }

  // lambda1 = a dtheta/dR of the same interpolant (continuous, O(h^3)).
  std::optional<double> stretch_at(double r) const {
    const auto& p = points();
    if (p.size() < 2 || !(r >= 0.0) || r > p.back().r) return std::nullopt;
    const std::size_t k = std::min(p.size() - 2, static_cast<std::size_t>(std::floor(r / step())));
    const double h = p[k + 1].r - p[k].r, s = (r - p[k].r) / h;
    const double d00 = 6.0 * s * (s - 1.0) / h, d10 = (1.0 - s) * (1.0 - 3.0 * s);
    const double d01 = -d00, d11 = s * (3.0 * s - 2.0);
    return a_ *
           (d00 * p[k].theta + d10 * p[k].l1 / a_ + d01 * p[k + 1].theta + d11 * p[k + 1].l1 / a_);
  }

  // Part I leaving the sphere at the edge R_c at force f (t = R s1 cos(theta), R s1 sin(theta)
  // = f less the gas's resultant on the cap); empty beyond the history or outside the material's
  // domain.
  std::optional<FreeStart> edge_start(double r, double f) const {
    const auto theta = theta_at(r);
    if (!theta || !(*theta > 0.0) || !(f > 0.0)) return std::nullopt;
    const double pull = f - gas_load(*theta);
    if (!(pull > 0.0)) return std::nullopt;
    const double l2 = a_ * std::sin(*theta) / r;
    const auto l1 = invert_radial_stress(part_one_.law(), pull / (r * std::sin(*theta)), l2);
    if (!l1) return std::nullopt;
    return FreeStart{{pull / std::tan(*theta), *l1, l2, 0.0}, r, *theta, 1.0};
  }

  // The tractions at grid point k: lambda1' from the grid (central differences of fourth
  // order, one-sided of second order at the ends).
  StuckTraction traction(std::size_t k) const {
    const auto& p = points();
    const std::size_t n = p.size();
    const double h = step();
    double dl1 = 0.0;
    if (n < 3) return {};
    if (k >= 2 && k + 2 < n)
      dl1 = (p[k - 2].l1 - 8.0 * p[k - 1].l1 + 8.0 * p[k + 1].l1 - p[k + 2].l1) / (12.0 * h);
    else if (k == 0 || k == 1)
      dl1 = (-3.0 * p[k].l1 + 4.0 * p[k + 1].l1 - p[k + 2].l1) / (2.0 * h);
    else
      dl1 = (3.0 * p[k].l1 - 4.0 * p[k - 1].l1 + p[k - 2].l1) / (2.0 * h);
    return traction_at(p[k].r, p[k].theta, p[k].l1, dl1);
  }

  // The largest |tau| / p of the held points inside r (grid points below r and r itself): a
  // held point keeps its tractions, so this is the largest ratio met along the history.
  double held_ratio(double r) const {
    const auto& p = points();
    if (ratio_max_.size() != p.size()) {
      ratio_max_.assign(p.size(), 0.0);
      for (std::size_t k = 1; k < p.size(); ++k)
        ratio_max_[k] = std::max(ratio_max_[k - 1], ratio(traction(k)));
    }
    const std::size_t below =
        std::min(p.size() - 1, static_cast<std::size_t>(std::ceil(r / step())) - (r > 0.0 ? 1 : 0));
    return std::max(ratio_max_[below], ratio(traction_near(r)));
  }
  static double ratio(const StuckTraction& t) {
    return t.pressure > 0.0 ? std::abs(t.tangential) / t.pressure
                            : (t.tangential == 0.0 ? 0.0 : kBeyondDomain);
  }

  // The tractions at reference radius r inside the history: linear between the grid points
  // (O(h^2), for the edge's sample).
  StuckTraction traction_near(double r) const {
    const auto& p = points();
    if (p.size() < 3) return {};
    const std::size_t k = std::min(p.size() - 2, static_cast<std::size_t>(std::floor(r / step())));
    const double s = (r - p[k].r) / (p[k + 1].r - p[k].r);
    const auto lo = traction(k), hi = traction(k + 1);
    return {lo.pressure + s * (hi.pressure - lo.pressure),
            lo.tangential + s * (hi.tangential - lo.tangential)};
  }

  // Normal balance p = (s1 / lambda2 + s2 / lambda1) / a; tangential tau = (d(R s1)/dR - s2
  // cos(theta)) / (r lambda1), d(R s1)/dR = s1 + R (ds1/dl1 lambda1' + ds1/dl2 lambda2'),
  // lambda2' = (lambda1 cos(theta) - lambda2) / R.  At the pole (R = 0) the limits: tau = 0.
  StuckTraction traction_at(double r, double theta, double l1, double dl1) const {
    const auto& law = part_one_.law();
    const double gas = part_one_.pressure();  // presses the membrane onto the sphere
    if (r == 0.0) {
      const auto st = membrane_stress(law, l1, l1);
      return {(st.s1 + st.s2) / (l1 * a_) + gas, 0.0};
    }
    const double l2 = a_ * std::sin(theta) / r;
    const auto st = membrane_stress(law, l1, l2);
    const double dl2 = (l1 * std::cos(theta) - l2) / r;
    const double d_rs1 = st.s1 + r * (st.ds1_dl1 * dl1 + st.ds1_dl2 * dl2);
    return {(st.s1 / l2 + st.s2 / l1) / a_ + gas,
            (d_rs1 - st.s2 * std::cos(theta)) / (a_ * std::sin(theta) * l1)};
  }

  // lambda1 of the edge's Part I at (r, theta) and the force and height with it; empty when no
  // stretch meets the clamp.
  struct EdgeSolve {
    double l1, f, height;
  };
  std::optional<EdgeSolve> solve_edge(double r, double theta, double guess) const {
    const auto& law = part_one_.law();
    const double l2 = a_ * std::sin(theta) / r;
    const double floor = 1.0 / std::sqrt(l2);  // s1 = 0
    auto start = [&](double l1) {
      const double s1 = membrane_stress(law, l1, l2).s1;
      return FreeStart{{r * s1 * std::cos(theta), l1, l2, 0.0}, r, theta, 1.0};
    };
    auto force = [&](double l1) {
      return r * membrane_stress(law, l1, l2).s1 * std::sin(theta) + gas_load(theta);
    };
    auto g = [&](double l1) -> std::optional<double> {
      if (!(l1 > floor)) return std::nullopt;
      const auto st = membrane_stress(law, l1, l2);
      if (!(st.i1 < part_one_.locking_i1()) || !std::isfinite(st.s1)) return std::nullopt;
      return part_one_.residual(force(l1), start(l1));
    };
    const auto l1_root = root_from_guess(g, guess, floor);
    if (!l1_root) return std::nullopt;
    const double l1 = *l1_root;
    const auto run = part_one_.run(force(l1), start(l1), nullptr, false);
    if (!run.ok) return std::nullopt;
    return EdgeSolve{l1, force(l1), run.height};
  }

 private:
  static constexpr double kPi = 3.141592653589793238462643383279502884;

  void build() const {
    built_ = true;
    end_ = StickHistoryEnd::Equator;
    const double h = step(), l0 = first_touch_stretch();
    points_.assign(1, StuckPoint{0.0, 0.0, l0, 0.0, 0.0});
    guess_ = l0;
    // Near the first touch the march is stiff: a larger theta at R raises the edge's hoop
    // stretch, and the edge's lambda1 falls as -K / R times it (K ~ 3 here), so explicit
    // steps must stay below ~R: the first grid interval starts from the flat membrane's
    // theta = L0 R / a at R = 1e-3 a (or a quarter of the first step; its error ~ R^3 decays as
    // R^-K) in steps of a quarter of R, later intervals are split likewise.
    double r = std::min(kFirstTouchRadius * a_, 0.25 * h), theta = l0 * r / a_;
    for (int k = 0; k < steps_; ++k) {
      const double r_next = (k + 1) * h;
      while (r < r_next) {
        const bool last = kStableStepFraction * r >= r_next - r;
        const auto next = rk4_step(r, theta, last ? r_next - r : kStableStepFraction * r);
        if (!next) return end_at(theta);
        r = last ? r_next : r + kStableStepFraction * r;
        theta = *next;
        if (!(theta < 0.5 * kPi)) return;
      }
      const auto e = solve_edge(r_next, theta, guess_);
      if (!e) return end_at(theta);
      guess_ = e->l1;
      points_.push_back({r_next, theta, e->l1, e->f, e->height + a_ * (1.0 - std::cos(theta))});
    }
  }
  // One classical Runge-Kutta step of dtheta/dR = lambda1_edge / a.  Written out rather than
  // Odeint's runge_kutta4 because each slope is a shooting that may find no state (the material
  // locks): the step must end with "no state", which Odeint's steppers can only get through an
  // exception.  Moving it to Odeint with such an exception is a refactor to check against the
  // stick tests.
  std::optional<double> rk4_step(double r, double theta, double dr) const {
    auto slope = [&](double at, double th) -> std::optional<double> {
      if (!(th < 0.5 * kPi)) {
        past_equator_ = true;  // a stage already passes it: the edge reaches it in this step
        return std::nullopt;
      }
      const auto e = solve_edge(at, th, guess_);
      if (!e) return std::nullopt;
      guess_ = e->l1;
      return e->l1 / a_;
    };
    const auto k1 = slope(r, theta);
    const auto k2 = k1 ? slope(r + 0.5 * dr, theta + 0.5 * dr * *k1) : std::nullopt;
    const auto k3 = k2 ? slope(r + 0.5 * dr, theta + 0.5 * dr * *k2) : std::nullopt;
    const auto k4 = k3 ? slope(r + dr, theta + dr * *k3) : std::nullopt;
    if (!k4) return std::nullopt;
    return theta + dr * (*k1 + 2.0 * *k2 + 2.0 * *k3 + *k4) / 6.0;
  }
  // Where the march starts, / a: strains ~1e-6 there (~C R^2, C ~ 90 for the paper's membrane),
  // well above the clamp residual's resolution.
  static constexpr double kFirstTouchRadius = 1e-3;
  static constexpr double kStableStepFraction = 0.25;

  // The history stopped before the equator: the material locked on the way, unless a stage of
  // the last step already passed the equator.
  void end_at(double theta) const {
    end_ =
        theta < 0.5 * kPi && !past_equator_ ? StickHistoryEnd::Locking : StickHistoryEnd::Equator;
  }

  const FreePart<Law>& part_one_;
  double a_;
  int steps_;
  mutable bool built_ = false;
  mutable StickHistoryEnd end_ = StickHistoryEnd::Equator;
  mutable bool past_equator_ = false;
  mutable std::vector<StuckPoint> points_;
  mutable std::vector<double> ratio_max_;
  mutable double guess_ = 1.0;  // the last edge stretch solved: the next solve's start  // running
                                // largest |tau| / p over the grid
};

// The plan of the stick stage at force f: the parameter is 1 / R_c (growing with the clamp
// residual at a fixed force, as a smaller held cap must carry f with a more stretched Part I),
// bracketed by the grid points around the force (the history's forces grow with R_c).
template <class Law, class Residual>
ShootingPlan stuck_plan(const SphereStickHistory<Law>& history, double f, Residual& counted) {
  ShootingPlan plan;
  plan.configuration = Configuration::Stick;
  const auto& p = history.points();
  if (p.size() < 4) {
    plan.status = Status::NoConvergence;
    plan.message = "the stick history on the sphere could not be started from the first touch";
    return plan;
  }
  if (!(f < p.back().f)) {
    if (history.end() == StickHistoryEnd::Equator) {
      plan.status = Status::StickWrapsSide;
      plan.message =
          "at this force the membrane held where it touched the sphere reaches the sphere's "
          "equator: it would wrap the cylinder side, outside the stick model";
    } else {
      plan.status = Status::BeyondLocking;
      plan.message =
          "the force exceeds what the membrane held on the sphere carries before it locks";
    }
    return plan;
  }
  std::size_t k = 1;
  while (k + 1 < p.size() && !(p[k].f > f)) ++k;
  for (const std::size_t hi : {std::min(k + 1, p.size() - 1), p.size() - 1}) {
    const auto g = counted(Configuration::Stick, 1.0 / p[hi].r);
    if (g && *g < 0.0) {
      plan.lo = 1.0 / p[hi].r;
      plan.g_lo = *g;
      const double r_lo = p[k >= 2 ? k - 2 : 0].r;
      if (r_lo > 0.0)
        plan.cap = 1.0 / r_lo;
      else
        plan.initial_step = 0.5 * plan.lo;
      plan.no_root_message =
          "the stick stage on the sphere found no contact edge meeting the clamp condition";
      return plan;
    }
  }
  plan.status = Status::NoConvergence;
  plan.message = "the stick stage on the sphere: no contact edge with a negative clamp residual";
  return plan;
}

// The held cap once Part I is integrated from the edge `st`: its samples (the grid points inside
// the edge, then the edge), its largest I1 (at the grid points and the edge; the pole holds L0)
// and height.
template <class Law>
void attach_stuck_cap(const SphereStickHistory<Law>& history, const Law& law, double a,
                      const FreeStart& st, bool record, ScaledSolution& sol) {
  const double r_edge = st.r0, theta_edge = st.slope;
  if (record) sol.part_two.clear();
  for (const StuckPoint& q : history.points()) {
    if (!(q.r < r_edge)) break;
    const double l2 = q.r > 0.0 ? a * std::sin(q.theta) / q.r : q.l1;
    const double i1 = membrane_stress(law, q.l1, l2).i1;
    if (i1 > sol.max_i1) {
      sol.max_i1 = i1;
      sol.max_i1_r = q.r;
      sol.max_i1_radius = a * std::sin(q.theta);
    }
    if (sol.wrinkle_r < 0.0 && q.r > 0.0 && hoop_compressive(q.l1, l2)) {
      sol.wrinkle_r = q.r;
      sol.wrinkle_radius = a * std::sin(q.theta);
    }
    if (record) sol.part_two.push_back({q.r, q.l1, q.theta});
  }
  if (record) sol.part_two.push_back({r_edge, st.state[1], theta_edge});
  sol.held_traction_ratio = history.held_ratio(r_edge);
  sol.r_corner = r_edge;
  sol.tension_ratio = 1.0;
  sol.depth += a * (1.0 - std::cos(theta_edge));
}

}  // namespace puncture::detail
