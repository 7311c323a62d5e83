#pragma once
// The stick stage on the flat punch under a held gas pressure (docs/model.md §17.3): the face
// first touches the inflated dome at its pole, and the contact disc grows with the force as
// c = sqrt(2 f / P) (the flat face carries exactly the gas pressure).  Material that touches the
// face is held where it touched; the held map R(c), the reference radius of the material held at
// current radius c, is built along the loading from the first touch:
//   dR_c/dc = 1 / lambda1_edge(R_c, c),  R_c(0) = 0,  lambda1_edge(0, 0) = the dome's pole stretch,
// lambda1_edge the meridional stretch with which Part I, leaving the face horizontally at R_c
// (lambda2 = c / R_c, t = R_c s1, force P c^2 / 2), meets the clamp.  Classical Runge-Kutta on a
// uniform grid in c up to the face's edge a, sub-stepped near the first touch where the march is
// stiff (as the curved probes' history, profile_stick.hpp).  A held point keeps its stretches,
// hence the tangential traction it needs: tau c lambda1 = d(R s1)/dR - s2 (the ring's radial
// balance on the flat face, whose normal load is the gas pressure P alone).
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "indentation/contact/contact_model.hpp"
#include "indentation/contact/stuck_traction.hpp"
#include "indentation/free_part.hpp"
#include "numerics/root_from_guess.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// One grid point of the held face: the material at reference radius r held at current radius c.
struct HeldFacePoint {
  double c = 0.0;   // current radius on the face / (A / L0)
  double r = 0.0;   // reference radius / (A / L0)
  double l1 = 1.0;  // meridional stretch (the free membrane's at the edge when it joined)
  double t = 0.0;   // the edge's radial line tension then, R s1 (Part I leaves horizontally)
};

template <class Law>
class HeldFaceHistory {
 public:
  static constexpr int kDefaultSteps = 200;

  HeldFaceHistory(const FreePart<Law>& part_one, double a, double pole_stretch,
                  int steps = kDefaultSteps)
      : part_one_(part_one), a_(a), pole_(pole_stretch), steps_(steps) {}

  // The grid points from the first touch (built on the first call); they reach the face's edge
  // c = a unless the material locks on the way (complete()).
  const std::vector<HeldFacePoint>& points() const {
    if (!built_) build();
    return points_;
  }
  bool complete() const { return points().size() == static_cast<std::size_t>(steps_) + 1; }
  double step() const { return a_ / steps_; }
  double pole_stretch() const { return pole_; }

  // R at current radius c: the cubic Hermite interpolant of (R_k, 1 / lambda1_k), O(h^4).
  std::optional<double> radius_at(double c) const {
    const auto& p = points();
    if (p.size() < 2 || !(c >= 0.0) || c > p.back().c) return std::nullopt;
    const std::size_t k = segment(c);
    const double h = p[k + 1].c - p[k].c, s = (c - p[k].c) / h;
    const double h00 = (1.0 + 2.0 * s) * (1.0 - s) * (1.0 - s), h10 = s * (1.0 - s) * (1.0 - s);
    const double h01 = s * s * (3.0 - 2.0 * s), h11 = s * s * (s - 1.0);
    return h00 * p[k].r + h10 * h / p[k].l1 + h01 * p[k + 1].r + h11 * h / p[k + 1].l1;
  }
  // The edge's tension t when the edge was at c (linear between the grid points): the stick
  // shooting's first guess.
  std::optional<double> tension_near(double c) const {
    const auto& p = points();
    if (p.size() < 2 || !(c >= 0.0) || c > p.back().c) return std::nullopt;
    const std::size_t k = segment(c);
    const double s = (c - p[k].c) / (p[k + 1].c - p[k].c);
    return p[k].t + s * (p[k + 1].t - p[k].t);
  }

  // The tractions at grid point k (normalised by G H / A): the gas pressure P, and tau towards
  // the axis, tau c lambda1 = lambda1 d(R s1)/dc - s2 (d/dR = lambda1 d/dc on the held face),
  // with d(R s1)/dc by central differences of fourth order (one-sided of second at the ends).
  StuckTraction traction(std::size_t k) const {
    const auto& p = points();
    const std::size_t n = p.size();
    const double pressure = part_one_.pressure();
    if (k == 0 || n < 3) return {pressure, 0.0};
    auto q = [&](std::size_t i) { return p[i].t; };  // R s1 (t = R s1 on the face)
    const double h = step();
    double dq = 0.0;
    if (k >= 2 && k + 2 < n)
      dq = (q(k - 2) - 8.0 * q(k - 1) + 8.0 * q(k + 1) - q(k + 2)) / (12.0 * h);
    else if (k + 2 < n)
      dq = (-3.0 * q(k) + 4.0 * q(k + 1) - q(k + 2)) / (2.0 * h);
    else
      dq = (3.0 * q(k) - 4.0 * q(k - 1) + q(k - 2)) / (2.0 * h);
    const double l2 = p[k].c / p[k].r;
    const double s2 = membrane_stress(part_one_.law(), p[k].l1, l2).s2;
    return {pressure, (p[k].l1 * dq - s2) / (p[k].c * p[k].l1)};
  }

  // The largest |tau| / P of the held points inside c (grid points up to c and the tractions at
  // c, linear between the grid points): a held point keeps its tractions, so this is the largest
  // ratio met along the history.
  double held_ratio(double c) const {
    const auto& p = points();
    if (p.size() < 3) return 0.0;
    double largest = 0.0;
    for (std::size_t k = 0; k < p.size() && p[k].c <= c; ++k)
      largest = std::max(largest, ratio(traction(k)));
    return std::max(largest, std::abs(tangential_near(c)) / part_one_.pressure());
  }
  static double ratio(const StuckTraction& t) { return std::abs(t.tangential) / t.pressure; }

  // The tangential traction at current radius c on the held face (linear between the grid
  // points, O(h^2): for the fields).
  double tangential_near(double c) const {
    const auto& p = points();
    if (p.size() < 3) return 0.0;
    const std::size_t k = segment(std::min(c, p.back().c));
    const double s = std::clamp((c - p[k].c) / (p[k + 1].c - p[k].c), 0.0, 1.0);
    return (1.0 - s) * traction(k).tangential + s * traction(k + 1).tangential;
  }

  // lambda1 of the edge's Part I at (R, c), with t = R s1; empty when no stretch meets the clamp.
  struct EdgeSolve {
    double l1, t;
  };
  std::optional<EdgeSolve> solve_edge(double r, double c, double guess) const {
    const auto& law = part_one_.law();
    const double l2 = c / r, f = 0.5 * part_one_.pressure() * c * c;
    const double floor = 1.0 / std::sqrt(l2);  // s1 = 0
    auto start = [&](double l1) {
      return FreeStart{{r * membrane_stress(law, l1, l2).s1, l1, l2, 0.0}, r, 0.0, 1.0};
    };
    auto g = [&](double l1) -> std::optional<double> {
      if (!(l1 > floor)) return std::nullopt;
      const auto st = membrane_stress(law, l1, l2);
      if (!(st.i1 < part_one_.locking_i1()) || !std::isfinite(st.s1)) return std::nullopt;
      return part_one_.residual(f, start(l1));
    };
    const auto l1_root = root_from_guess(g, guess, floor);
    if (!l1_root) return std::nullopt;
    const double l1 = *l1_root;
    return EdgeSolve{l1, r * membrane_stress(law, l1, l2).s1};
  }

 private:
  std::size_t segment(double c) const {
    return std::min(points_.size() - 2, static_cast<std::size_t>(std::floor(c / step())));
  }

  void build() const {
    built_ = true;
    const double h = step();
    points_.assign(1, HeldFacePoint{0.0, 0.0, pole_, 0.0});
    guess_ = pole_;
    // Near the first touch the march is stiff (a larger R at c lowers the edge's hoop stretch,
    // and its lambda1 answers as ~1 / c times it): it starts at c = 1e-3 a (or a quarter of the
    // first step) from the dome's pole, R = c / pole stretch (an error O(c^3) that decays), in
    // sub-steps of a quarter of c until they exceed the grid's.
    double c = std::min(kFirstTouchRadius * a_, 0.25 * h), r = c / pole_;
    for (int k = 0; k < steps_; ++k) {
      const double c_next = k + 1 == steps_ ? a_ : (k + 1) * h;
      while (c < c_next) {
        const bool last = kStableStepFraction * c >= c_next - c;
        const double dc = last ? c_next - c : kStableStepFraction * c;
        const auto next = rk4_step(c, r, dc);
        if (!next) return;
        c = last ? c_next : c + dc;
        r = *next;
      }
      const auto e = solve_edge(r, c_next, guess_);
      if (!e) return;
      guess_ = e->l1;
      points_.push_back({c_next, r, e->l1, e->t});
    }
  }
  // One classical Runge-Kutta step of dR/dc = 1 / lambda1_edge (written out, as the sphere's:
  // a slope may find no state).
  std::optional<double> rk4_step(double c, double r, double dc) const {
    auto slope = [&](double at, double rr) -> std::optional<double> {
      if (!(rr > 0.0)) return std::nullopt;
      const auto e = solve_edge(rr, at, guess_);
      if (!e) return std::nullopt;
      guess_ = e->l1;
      return 1.0 / e->l1;
    };
    const auto k1 = slope(c, r);
    const auto k2 = k1 ? slope(c + 0.5 * dc, r + 0.5 * dc * *k1) : std::nullopt;
    const auto k3 = k2 ? slope(c + 0.5 * dc, r + 0.5 * dc * *k2) : std::nullopt;
    const auto k4 = k3 ? slope(c + dc, r + dc * *k3) : std::nullopt;
    if (!k4) return std::nullopt;
    return r + dc * (*k1 + 2.0 * *k2 + 2.0 * *k3 + *k4) / 6.0;
  }
  static constexpr double kFirstTouchRadius = 1e-3;
  static constexpr double kStableStepFraction = 0.25;

  const FreePart<Law>& part_one_;
  double a_;
  double pole_;
  int steps_;
  mutable bool built_ = false;
  mutable std::vector<HeldFacePoint> points_;
  mutable double guess_ = 1.0;  // the last edge stretch solved: the next solve's start
};

// Held on the face under pressure (f < P a^2 / 2): t = R s1 of the edge, bracketed around the
// held map's t at the disc's edge (the map's grid states meet the clamp there), widened by
// doubling until the residual changes sign.
template <class Law, class Residual>
ShootingPlan held_face_tension_plan(const HeldFaceHistory<Law>& map, double f, double pressure,
                                    Residual& counted) {
  ShootingPlan plan;
  plan.configuration = Configuration::Stick;
  const auto guess = map.tension_near(std::sqrt(2.0 * f / pressure));
  if (!guess) {
    plan.status = Status::BeyondLocking;
    plan.message =
        "the membrane held on the face locks before the contact disc carries this "
        "force";
    return plan;
  }
  for (double d = 1e-3; d < 1.0; d *= 2.0) {
    const double lo = *guess * (1.0 - d), hi = *guess * (1.0 + d);
    const auto g_lo = counted(Configuration::Stick, lo);
    if (!g_lo || !(*g_lo < 0.0)) continue;
    const auto g_hi = counted(Configuration::Stick, hi);
    if (!g_hi || !(*g_hi >= 0.0)) continue;
    plan.lo = lo;
    plan.g_lo = *g_lo;
    plan.cap = hi;
    plan.g_cap = *g_hi;
    plan.no_root_message =
        "stick shooting on the held face found no edge tension meeting the clamp condition";
    return plan;
  }
  plan.status = Status::NoConvergence;
  plan.message =
      "stick shooting on the held face: no bracket of the edge tension around the "
      "held map's";
  return plan;
}

}  // namespace puncture::detail
