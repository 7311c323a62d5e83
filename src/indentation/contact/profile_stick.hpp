#pragma once
// The stick stage on the curved probes (docs/model.md §15.4, §15.5): the sphere-tipped probe (a
// hemisphere, then the cylinder), the filleted flat punch (a flat face, then a toroidal arc), the
// ball (its lower hemisphere) and the cone (a tip sphere, then the straight cone up to the kink
// onto the shank).  Each is a profile parametrised by psi = (length along it from the face's edge
// or the pole) / rho, rho the arc's (tip sphere's) radius; a material point R held at psi(R) has
//   lambda1 = rho dpsi/dR,  lambda2 = r(psi) / R,  slope phi(psi),
// and the contact map is built along the loading history, parametrised by the contact edge's
// reference radius R_c: the point R_c joins at the edge with the free membrane's meridional
// stretch there,
//   dpsi_c/dR_c = lambda1_edge(R_c, psi_c) / rho,
// lambda1_edge the stretch with which Part I, leaving the profile tangentially at (R_c, psi_c)
// with lambda2 = r(psi_c) / R_c, meets the clamp.  Classical Runge-Kutta (fourth order) on a
// uniform grid in R_c; each stage solves the edge's lambda1 (TOMS 748 on Part I's clamp
// residual); near the first touch, where the march is stiff, in sub-steps of a quarter of R.
// Stuck points keep their stretches, so their tractions are frozen too: the traction demand of a
// point is the one it had when it joined.
// The flat face touches the flat membrane at once and holds it at the pre-stretch L0 (the sharp
// punch's held Part III, §9); the map starts at the face's edge R_b = b / L0 with psi = 0.  The
// march stops where the tip sphere meets the cone (its meridional curvature jumps there) and
// restarts on the cone, so that no Runge-Kutta step spans the jump.
// Under a held gas pressure P (§17.3) the probe first touches the inflated dome's pole, which
// holds the dome's pole stretch; the gas presses the held membrane onto the probe (its contact
// pressure gains P) and carries P r^2 / 2 of the force inside the edge's current radius r.  The
// filleted punch's face then holds a disc that grows with the force (flat_punch_held_face.hpp,
// the sharp punch's held face) until it reaches the face's edge; the arc's map starts there,
// from the face's material and stretch at its edge.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "indentation/contact/contact_model.hpp"
#include "indentation/contact/flat_punch_held_face.hpp"
#include "indentation/contact/stuck_traction.hpp"
#include "indentation/free_part.hpp"
#include "mechanics/inverse_stretch.hpp"
#include "numerics/root_from_guess.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

// What ends the curved profile a held membrane may lie on.
enum class HeldProfileEnd {
  CylinderSide,  // the equator, then the cylinder (the filleted punch, the sphere-tipped probe)
  Neck,          // the ball's equator: past it the membrane would neck above the ball
  Kink,          // the cone's kink onto the shank (then the pivot over it, held_kink_pivot.hpp)
};

// The probe's profile in the held membrane's coordinate psi (lengths / (A / L0)).
struct HeldProfile {
  double arc = 1.0;   // the arc's (tip sphere's) radius rho
  double face = 0.0;  // the flat face's radius b (0: the profile starts at the pole)
  double tangency = std::numeric_limits<double>::infinity();      // psi where the cone starts
  double end_psi = 0.5 * 3.141592653589793238462643383279502884;  // where the profile ends
  HeldProfileEnd end = HeldProfileEnd::CylinderSide;

  // On the cone (past the tangency); `cone` picks the formula for the march's steps.
  bool on_cone(double psi) const { return psi > tangency; }
  double radius(double psi, bool cone) const {
    return cone ? arc * (std::sin(tangency) + (psi - tangency) * std::cos(tangency))
                : face + arc * std::sin(psi);
  }
  double slope(double psi, bool cone) const { return cone ? tangency : psi; }
  // The meridian's curvature (the hoop one is sin(slope) / r).
  double curvature(bool cone) const { return cone ? 0.0 : 1.0 / arc; }
  // Height above the tip (the pole, or the flat face).
  double height(double psi, bool cone) const {
    return cone ? arc * (1.0 - std::cos(tangency)) + arc * (psi - tangency) * std::sin(tangency)
                : arc * (1.0 - std::cos(psi));
  }
  double radius(double psi) const { return radius(psi, on_cone(psi)); }
  double slope(double psi) const { return slope(psi, on_cone(psi)); }
  double height(double psi) const { return height(psi, on_cone(psi)); }
};

// Why the held profile's history ends before the grid does.
enum class ProfileHistoryEnd {
  ProfileEnd,  // the edge reaches the profile's end (HeldProfile::end)
  Locking,     // no Part I from the edge meets the clamp (the material locks)
  GridEnd,     // the grid ended first (an edge stretch below L0 somewhere: not met so far)
};

template <class Law>
class ProfileStickHistory {
 public:
  // Grid steps over R_c in [b / L0, (b + rho end_psi) / L0]: the edge reaches the profile's end
  // before the grid's end while lambda1 >= L0 along the history.
  static constexpr int kDefaultSteps = 400;

  ProfileStickHistory(const FreePart<Law>& part_one, const HeldProfile& profile,
                      int steps = kDefaultSteps)
      : part_one_(part_one), q_(profile), steps_(steps) {
    if (q_.face > 0.0 && part_one.pressure() > 0.0)
      face_.emplace(part_one, q_.face, first_touch_stretch());
  }

  const HeldProfile& profile() const { return q_; }
  const std::vector<StuckPoint>& points() const {
    if (!built_) build();
    return points_;
  }
  ProfileHistoryEnd end() const {
    if (!built_) build();
    return end_;
  }
  // The held face under a gas pressure (none without a face or a pressure).
  const HeldFaceHistory<Law>* face_map() const { return face_ ? &*face_ : nullptr; }
  // The face's edge, where the map starts (0 without a face; under a gas pressure the material
  // the held face's disc reached it with, infinite if it locked before).
  double start() const {
    if (!face_) return q_.face / part_one_.prestretch();
    return face_->complete() ? face_->points().back().r : std::numeric_limits<double>::infinity();
  }
  // The stretch of the first material touched: the inflated dome's pole's under a gas pressure
  // (docs/model.md §17.3), else the pre-stretch L0.
  double first_touch_stretch() const {
    const double pole = part_one_.settings().dome_pole_stretch;
    return pole > 0.0 ? pole : part_one_.prestretch();
  }
  // The gas pressure's resultant on the held membrane inside psi, P r(psi)^2 / 2 (0 without).
  double gas_load(double psi, bool cone) const {
    const double radius = q_.radius(psi, cone);
    return 0.5 * part_one_.pressure() * radius * radius;
  }
  double step() const { return q_.arc * q_.end_psi / part_one_.prestretch() / steps_; }

  // psi at reference radius r in [start, last grid point]: the cubic Hermite interpolant of
  // (psi_k, lambda1_k / rho), O(h^4) as the march.
  std::optional<double> psi_at(double r) const {
    const auto k = interval(r);
    if (!k) return std::nullopt;
    const auto& p = points_;
    const double h = p[*k + 1].r - p[*k].r, s = (r - p[*k].r) / h;
    const double h00 = (1.0 + 2.0 * s) * (1.0 - s) * (1.0 - s), h10 = s * (1.0 - s) * (1.0 - s);
    const double h01 = s * s * (3.0 - 2.0 * s), h11 = s * s * (s - 1.0);
    return h00 * p[*k].theta + h10 * h * p[*k].l1 / q_.arc + h01 * p[*k + 1].theta +
           h11 * h * p[*k + 1].l1 / q_.arc;
  }
  // lambda1 = rho dpsi/dR of the same interpolant (O(h^3)); L0 on the face.
  std::optional<double> stretch_at(double r) const {
    if (r >= 0.0 && r < start()) return part_one_.prestretch();
    const auto k = interval(r);
    if (!k) return std::nullopt;
    const auto& p = points_;
    const double h = p[*k + 1].r - p[*k].r, s = (r - p[*k].r) / h;
    const double d00 = 6.0 * s * (s - 1.0) / h, d10 = (1.0 - s) * (1.0 - 3.0 * s);
    const double d01 = -d00, d11 = s * (3.0 * s - 2.0);
    return q_.arc * (d00 * p[*k].theta + d10 * p[*k].l1 / q_.arc + d01 * p[*k + 1].theta +
                     d11 * p[*k + 1].l1 / q_.arc);
  }

  // Part I leaving the profile tangentially at the edge R_c at force f (t = R s1 cos(phi), R s1
  // sin(phi) = f less the gas's resultant inside the edge); empty beyond the history or outside
  // the material's domain.
  std::optional<FreeStart> edge_start(double r, double f) const {
    const auto psi = psi_at(r);
    if (!psi || !(*psi > 0.0) || !(f > 0.0)) return std::nullopt;
    const bool cone = q_.on_cone(*psi);
    const double pull = f - gas_load(*psi, cone);
    if (!(pull > 0.0)) return std::nullopt;
    const double phi = q_.slope(*psi, cone), l2 = q_.radius(*psi, cone) / r;
    const auto l1 = invert_radial_stress(part_one_.law(), pull / (r * std::sin(phi)), l2);
    if (!l1) return std::nullopt;
    return FreeStart{{pull / std::tan(phi), *l1, l2, 0.0}, r, phi, 1.0};
  }

  // The tractions at grid point k (lambda1' by central differences of fourth order, one-sided
  // of second order at the ends; across the cone's tangency lambda1' jumps and the neighbouring
  // points' tau is first order).
  StuckTraction traction(std::size_t k) const {
    const auto& p = points();
    const std::size_t n = p.size();
    const double h = step();
    if (n < 3) return {};
    // The last interval may be shorter (close_at): three-point formulas with the true spacing
    // where the stencil reaches it.
    const bool short_end = std::abs(p[n - 1].r - p[n - 2].r - h) > 1e-9 * h;
    double dl1 = 0.0;
    if (k >= 2 && k + 2 < n && !(short_end && k + 2 == n - 1)) {
      dl1 = (p[k - 2].l1 - 8.0 * p[k - 1].l1 + 8.0 * p[k + 1].l1 - p[k + 2].l1) / (12.0 * h);
    } else if (k == 0 || k == 1) {
      dl1 = (-3.0 * p[k].l1 + 4.0 * p[k + 1].l1 - p[k + 2].l1) / (2.0 * h);
    } else if (k + 1 < n) {
      const double ha = p[k].r - p[k - 1].r, hb = p[k + 1].r - p[k].r;
      dl1 = (-hb * hb * p[k - 1].l1 + (hb * hb - ha * ha) * p[k].l1 + ha * ha * p[k + 1].l1) /
            (ha * hb * (ha + hb));
    } else {
      const double h1 = p[k].r - p[k - 1].r, h2 = p[k - 1].r - p[k - 2].r;
      dl1 = p[k].l1 * (2.0 * h1 + h2) / (h1 * (h1 + h2)) - p[k - 1].l1 * (h1 + h2) / (h1 * h2) +
            p[k - 2].l1 * h1 / (h2 * (h1 + h2));
    }
    return traction_at(p[k].r, p[k].theta, p[k].l1, dl1);
  }

  // Normal balance p = s1 kappa1 / lambda2 + s2 sin(phi) / (lambda1 r) + P (the gas presses the
  // membrane onto the probe); tangential (towards the tip) tau r lambda1 = d(R s1)/dR - s2
  // cos(phi), d(R s1)/dR = s1 + R (ds1/dl1 lambda1' + ds1/dl2 lambda2'), lambda2' = (lambda1
  // cos(phi) - lambda2) / R.  At the pole both limits.
  StuckTraction traction_at(double r, double psi, double l1, double dl1) const {
    const auto& law = part_one_.law();
    const double gas = part_one_.pressure();
    if (r == 0.0) {
      const auto st = membrane_stress(law, l1, l1);
      return {(st.s1 + st.s2) / (l1 * q_.arc) + gas, 0.0};
    }
    const bool cone = q_.on_cone(psi);
    const double radius = q_.radius(psi, cone), phi = q_.slope(psi, cone);
    const double l2 = radius / r;
    const auto st = membrane_stress(law, l1, l2);
    const double dl2 = (l1 * std::cos(phi) - l2) / r;
    const double d_rs1 = st.s1 + r * (st.ds1_dl1 * dl1 + st.ds1_dl2 * dl2);
    return {st.s1 * q_.curvature(cone) / l2 + st.s2 * std::sin(phi) / (l1 * radius) + gas,
            (d_rs1 - st.s2 * std::cos(phi)) / (radius * l1)};
  }

  // Tractions at r: none on the flat face (flat, uniform: p = tau = 0), linear between the grid
  // points on the profile.
  StuckTraction traction_near(double r) const {
    const auto& p = points();
    if (p.size() < 3 || r < start()) return {};
    const std::size_t k = index(r);
    const double s = (r - p[k].r) / (p[k + 1].r - p[k].r);
    const auto lo = traction(k), hi = traction(k + 1);
    return {lo.pressure + s * (hi.pressure - lo.pressure),
            lo.tangential + s * (hi.tangential - lo.tangential)};
  }

  // The largest |tau| / p of the held points inside r: each keeps the tractions it joined with
  // (under a gas pressure the held face's first; inside it, HeldFaceHistory::held_ratio).
  double held_ratio(double r) const {
    const auto& p = points();
    const double face = face_ ? face_->held_ratio(q_.face) : 0.0;
    if (p.size() < 3 || r < start()) return face;
    if (ratio_max_.size() != p.size()) {
      ratio_max_.assign(p.size(), 0.0);
      for (std::size_t k = 1; k < p.size(); ++k)
        ratio_max_[k] = std::max(ratio_max_[k - 1], held_traction_ratio_of(traction(k)));
    }
    const double x = (r - start()) / step();
    const std::size_t below =
        std::min(p.size() - 1, static_cast<std::size_t>(std::ceil(x)) - (x > 0.0 ? 1 : 0));
    return std::max({face, ratio_max_[below], held_traction_ratio_of(traction_near(r))});
  }

  // lambda1 of the edge's Part I at (r, psi) (the profile's formulas by `cone`), the force (the
  // membrane's pull and the gas's resultant inside the edge) and Part I's height; empty when no
  // stretch meets the clamp.
  struct EdgeSolve {
    double l1, f, height;
  };
  std::optional<EdgeSolve> solve_edge(double r, double psi, bool cone, double guess) const {
    const auto& law = part_one_.law();
    const double l2 = q_.radius(psi, cone) / r, phi = q_.slope(psi, cone);
    const double floor = 1.0 / std::sqrt(l2);  // s1 = 0
    auto start_of = [&](double l1) {
      const double s1 = membrane_stress(law, l1, l2).s1;
      return FreeStart{{r * s1 * std::cos(phi), l1, l2, 0.0}, r, phi, 1.0};
    };
    const double gas = gas_load(psi, cone);
    auto force = [&](double l1) {
      return r * membrane_stress(law, l1, l2).s1 * std::sin(phi) + gas;
    };
    auto g = [&](double l1) -> std::optional<double> {
      if (!(l1 > floor)) return std::nullopt;
      const auto st = membrane_stress(law, l1, l2);
      if (!(st.i1 < part_one_.locking_i1()) || !std::isfinite(st.s1)) return std::nullopt;
      return part_one_.residual(force(l1), start_of(l1));
    };
    const auto l1_root = root_from_guess(g, guess, floor);
    if (!l1_root) return std::nullopt;
    const double l1 = *l1_root;
    const auto run = part_one_.run(force(l1), start_of(l1), nullptr, false);
    if (!run.ok) return std::nullopt;
    return EdgeSolve{l1, force(l1), run.height};
  }

 private:
  // The grid interval holding r (from the face's edge); empty outside the history.
  std::optional<std::size_t> interval(double r) const {
    const auto& p = points();
    if (p.size() < 2 || !(r >= start()) || r > p.back().r) return std::nullopt;
    return index(r);
  }
  std::size_t index(double r) const {
    return std::min(points_.size() - 2,
                    static_cast<std::size_t>(std::floor(std::max(0.0, r - start()) / step())));
  }

  void build() const {
    built_ = true;
    end_ = ProfileHistoryEnd::GridEnd;
    const double h = step(), r0 = start();
    double l0 = first_touch_stretch(), f0 = 0.0, depth0 = 0.0;
    if (face_) {
      // From the held face's edge: its material, stretch and force P b^2 / 2.
      if (!face_->complete()) {
        end_ = ProfileHistoryEnd::Locking;
        points_.clear();
        return;
      }
      l0 = face_->points().back().l1;
      f0 = gas_load(0.0, false);
      if (const auto e = solve_edge(r0, 0.0, false, l0)) depth0 = e->height;
    }
    points_.assign(1, StuckPoint{r0, 0.0, l0, f0, depth0});
    guess_ = l0;
    // The first material the arc holds is the flat membrane's at L0 (the dome's pole's under a
    // gas pressure): the march starts a little past the face's edge (or the pole) from psi = L0
    // (R - R_b) / rho, strains ~1e-6 there, in
    // sub-steps of a quarter of R where those are shorter than the grid's (near the pole the
    // march is stiff, ~ -3 / R, as on the sphere).
    const double dr0 = std::min(kFirstTouch * q_.arc, 0.25 * h);
    double r = r0 + dr0, psi = l0 * dr0 / q_.arc;
    for (int k = 0; k < steps_; ++k) {
      const double r_next = r0 + (k + 1) * h;
      double cap = std::numeric_limits<double>::infinity();  // halved where a stage overshoots
      while (r < r_next) {
        const double dr = std::min({kStableStepFraction * r, r_next - r, cap});
        const bool last = dr == r_next - r;
        const bool cone = q_.on_cone(psi) || psi == q_.tangency;
        auto next = rk4_step(r, psi, dr, cone);
        if (next && !(*next < q_.end_psi)) {  // the step passes the profile's end
          next.reset();
          past_end_ = true;
        }
        if (!next && past_end_) {
          // A stage passed the profile's end: shorter steps up to it, so that an edge reaching
          // the end is told from a material that locks before it (no edge solve then).
          past_end_ = false;
          if (q_.end_psi - psi < kEndReached || dr < kShortestStep * h) {
            end_ = ProfileHistoryEnd::ProfileEnd;
            return close_at(r, psi);
          }
          cap = 0.5 * dr;
          continue;
        }
        if (next && !cone && *next > q_.tangency) {
          // Shorten the step to end on the tangency (secant on the step's length).
          const auto to_junction = step_to_tangency(r, psi, dr, *next);
          if (!to_junction) return end_at(r, psi);
          r += *to_junction;
          psi = q_.tangency;
          continue;
        }
        if (!next) return end_at(r, psi);
        r = last ? r_next : r + dr;
        psi = *next;
      }
      const auto e = solve_edge(r_next, psi, q_.on_cone(psi) || psi == q_.tangency, guess_);
      if (!e) return end_at(r, psi);
      guess_ = e->l1;
      points_.push_back({r_next, psi, e->l1, e->f, e->height + q_.height(psi)});
    }
  }

  // One classical Runge-Kutta step of dpsi/dR = lambda1_edge / rho with one formula (sphere or
  // cone) throughout; empty when a stage finds no edge or passes the profile's end (noted).
  std::optional<double> rk4_step(double r, double psi, double dr, bool cone) const {
    auto slope = [&](double at, double x) -> std::optional<double> {
      if (!(x < q_.end_psi)) {
        past_end_ = true;
        return std::nullopt;
      }
      const auto e = solve_edge(at, x, cone, guess_);
      if (!e) return std::nullopt;
      guess_ = e->l1;
      return e->l1 / q_.arc;
    };
    const auto k1 = slope(r, psi);
    const auto k2 = k1 ? slope(r + 0.5 * dr, psi + 0.5 * dr * *k1) : std::nullopt;
    const auto k3 = k2 ? slope(r + 0.5 * dr, psi + 0.5 * dr * *k2) : std::nullopt;
    const auto k4 = k3 ? slope(r + dr, psi + dr * *k3) : std::nullopt;
    if (!k4) return std::nullopt;
    return psi + dr * (*k1 + 2.0 * *k2 + 2.0 * *k3 + *k4) / 6.0;
  }
  // The length of the sphere's step from (r, psi) that ends on the tangency, given that dr
  // passes it (to psi_end): secant iterations, each a Runge-Kutta step, to 1e-14 of rho.
  std::optional<double> step_to_tangency(double r, double psi, double dr, double psi_end) const {
    double x0 = 0.0, g0 = psi - q_.tangency, x1 = dr, g1 = psi_end - q_.tangency;
    for (int k = 0; k < 30; ++k) {
      const double x = x1 - g1 * (x1 - x0) / (g1 - g0);
      const auto y = rk4_step(r, psi, x, false);
      if (!y) return std::nullopt;
      x0 = x1;
      g0 = g1;
      x1 = x;
      g1 = *y - q_.tangency;
      if (std::abs(g1) <= 1e-14 || g1 == g0) return x1;
    }
    return std::abs(g1) <= 1e-10 ? std::optional<double>(x1) : std::nullopt;
  }

  void end_at(double r, double psi) const {
    end_ = past_end_ ? ProfileHistoryEnd::ProfileEnd : ProfileHistoryEnd::Locking;
    close_at(r, psi);
  }
  // The last state the march reached inside the grid's last interval, as a last (shorter)
  // interval: near the profile's end the force grows steeply (the edge's lambda1 does), and the
  // states between the last grid point and the end would be lost otherwise.
  void close_at(double r, double psi) const {
    if (!(r > points_.back().r + kShortestStep * step())) return;
    const auto e = solve_edge(r, psi, q_.on_cone(psi) || psi == q_.tangency, guess_);
    if (e) points_.push_back({r, psi, e->l1, e->f, e->height + q_.height(psi)});
  }

  static constexpr double kFirstTouch = 1e-3;  // the march's start past the face's edge, / rho
  static constexpr double kStableStepFraction = 0.25;
  static constexpr double kEndReached = 1e-6;    // psi this close to the end: reached
  static constexpr double kShortestStep = 1e-9;  // / the grid's step, near the end

  const FreePart<Law>& part_one_;
  HeldProfile q_;
  int steps_;
  mutable bool built_ = false;
  mutable bool past_end_ = false;  // a Runge-Kutta stage passed the profile's end
  mutable ProfileHistoryEnd end_ = ProfileHistoryEnd::GridEnd;
  mutable std::vector<StuckPoint> points_;    // theta holds psi
  mutable std::vector<double> ratio_max_;     // running largest |tau| / p over the grid
  mutable double guess_ = 1.0;                // the last edge stretch solved: the next's start
  std::optional<HeldFaceHistory<Law>> face_;  // the held face under a gas pressure
};

// Why the held states end at the history's last point: the profile's end (a status naming what
// the held membrane would do past it), locking, or the grid's end.
template <class Law>
ShootingPlan held_profile_end_plan(const ProfileStickHistory<Law>& history) {
  ShootingPlan plan;
  plan.configuration = Configuration::Stick;
  switch (history.end()) {
    case ProfileHistoryEnd::ProfileEnd:
      switch (history.profile().end) {
        case HeldProfileEnd::CylinderSide:
          plan.status = Status::StickWrapsSide;
          plan.message = history.profile().face > 0.0
                             ? "at this force the membrane held where it touched the fillet "
                               "reaches its equator: it would wrap the punch's cylinder side, "
                               "outside the stick model"
                             : "at this force the membrane held where it touched the sphere "
                               "reaches the sphere's equator: it would wrap the cylinder side, "
                               "outside the stick model";
          break;
        case HeldProfileEnd::Neck:
          plan.status = Status::OutsideModel;
          plan.message =
              "outside the ball model: at this force the membrane held where it touched the "
              "ball reaches its equator (it would wrap the upper hemisphere and neck above "
              "the ball, not solved; docs/model.md, section 15.5)";
          break;
        case HeldProfileEnd::Kink:
          plan.status = Status::OutsideModel;
          plan.message =
              "outside the cone model: at this force the membrane held where it touched the "
              "cone reaches the kink onto the shank (held there it would pivot over the kink, "
              "not solved; docs/model.md, section 15.5)";
          break;
      }
      break;
    case ProfileHistoryEnd::Locking:
      plan.status = Status::BeyondLocking;
      plan.message =
          "the force exceeds what the membrane held on the probe carries before it locks";
      break;
    case ProfileHistoryEnd::GridEnd:
      plan.status = Status::NoConvergence;
      plan.message = "the stick history ended before the probe's profile did";
      break;
  }
  return plan;
}

// Under a gas pressure a force far below the history's first grid point's (depths ~1e-5 mm past
// the touch) has its edge well inside the grid point's edge r_grid, where the gas's resultant
// P r^2 / 2 alone exceeds f: the membrane would pull with f - P r^2 / 2 <= 0 there and no Part I
// leaves it (no residual at all, so the grid point bounds no bracket).  Near the touch the gas
// carries a small fixed share of the edge's force (a pre-tension T at the inflated pole: the pull
// 2 pi T c^2 (1 / rho - 1 / R_dome) against P c^2 / 2 = T c^2 / R_dome, ~1% on a 2 mm sphere),
// so the edge lies where P r^2 / 2 is a small part of f.  Edges halved from r_grid, the first with
// a positive pull and a negative clamp residual, bound the bracket: within a factor 2 of the
// edge while the gas's share there is below 1/4.  {R, residual}; empty if an edge with a positive
// residual comes first.
template <class Law, class Residual>
std::optional<std::pair<double, double>> held_edge_inside_gas_load(
    const ProfileStickHistory<Law>& history, double f, double r_grid, Residual& counted) {
  constexpr int kHalvings = 60;
  for (int j = 1; j <= kHalvings; ++j) {
    const double r = std::ldexp(r_grid, -j);
    const auto psi = history.psi_at(r);
    if (!psi || !(history.gas_load(*psi, history.profile().on_cone(*psi)) < f)) continue;
    const auto g = counted(Configuration::Stick, 1.0 / r);
    if (g && *g < 0.0) return std::pair{r, *g};
    if (g) return std::nullopt;  // past the edge without a negative residual
  }
  return std::nullopt;
}

// The stick stage's plan at force f (as stuck_plan on the sphere): the parameter is 1 / R_c,
// bracketed by the grid points around f; past the history's end a status.
template <class Law, class Residual>
ShootingPlan held_profile_plan(const ProfileStickHistory<Law>& history, double f,
                               Residual& counted) {
  ShootingPlan plan;
  plan.configuration = Configuration::Stick;
  const auto& p = history.points();
  if (p.size() < 4 && history.end() == ProfileHistoryEnd::Locking)
    return held_profile_end_plan(history);
  if (p.size() < 4) {
    plan.status = Status::NoConvergence;
    plan.message = "the stick history on the probe could not be started from the first touch";
    return plan;
  }
  if (!(f < p.back().f)) return held_profile_end_plan(history);
  std::size_t k = 1;
  while (k + 1 < p.size() && !(p[k].f > f)) ++k;
  const char* no_root =
      "the stick stage on the probe found no contact edge meeting the clamp condition";
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
      plan.no_root_message = no_root;
      return plan;
    }
  }
  // The gas alone carries f inside the grid point's edge: the edge lies further in.
  const StuckPoint& grid = p[std::min(k + 1, p.size() - 1)];
  if (!(history.gas_load(grid.theta, history.profile().on_cone(grid.theta)) < f)) {
    if (const auto inside = held_edge_inside_gas_load(history, f, grid.r, counted)) {
      plan.lo = 1.0 / inside->first;
      plan.g_lo = inside->second;
      plan.initial_step = 0.5 * plan.lo;
      plan.no_root_message = no_root;
      return plan;
    }
  }
  // In the history's last interval the clamp residual at its last point is ~0 for a force within
  // rounding of that point's: the end of the history, not a solver failure.
  if (k + 1 >= p.size()) return held_profile_end_plan(history);
  plan.status = Status::NoConvergence;
  plan.message = "the stick stage on the probe: no contact edge with a negative clamp residual";
  return plan;
}

// The held face's grid points under a gas pressure with current radius c < c_end: their largest
// I1 and hoop compression and, with `record`, their samples (R, lambda1, psi = (c - b) / rho < 0,
// so that the fields know each point's current radius).
template <class Law>
void track_held_face(const HeldFaceHistory<Law>& face, const HeldProfile& q, const Law& law,
                     double c_end, bool record, ScaledSolution& sol) {
  for (const HeldFacePoint& p : face.points()) {
    if (!(p.c < c_end)) break;
    const double l2 = p.r > 0.0 ? p.c / p.r : p.l1;
    const double i1 = membrane_stress(law, p.l1, l2).i1;
    if (i1 > sol.max_i1) {
      sol.max_i1 = i1;
      sol.max_i1_r = p.r;
      sol.max_i1_radius = p.c;
    }
    if (sol.wrinkle_r < 0.0 && p.r > 0.0 && hoop_compressive(p.l1, l2)) {
      sol.wrinkle_r = p.r;
      sol.wrinkle_radius = p.c;
    }
    if (record) sol.part_two.push_back({p.r, p.l1, (p.c - q.face) / q.arc});
  }
}

// Held on the filleted punch's face only (under a gas pressure, f < P b^2 / 2): the held disc up
// to its edge `st` (Part I leaving it horizontally), the Coulomb ratio its points need.
template <class Law>
void attach_held_fillet_face(const ProfileStickHistory<Law>& history, const Law& law,
                             const FreeStart& st, bool record, ScaledSolution& sol) {
  const HeldProfile& q = history.profile();
  const auto& face = *history.face_map();
  const double r_edge = st.r0, c_edge = st.state[2] * r_edge;
  if (record) sol.part_two.clear();
  track_held_face(face, q, law, c_edge * (1.0 - 1e-12), record, sol);
  const double i1 = membrane_stress(law, st.state[1], st.state[2]).i1;
  if (i1 > sol.max_i1) {
    sol.max_i1 = i1;
    sol.max_i1_r = r_edge;
    sol.max_i1_radius = c_edge;
  }
  if (record) sol.part_two.push_back({r_edge, st.state[1], (c_edge - q.face) / q.arc});
  sol.held_traction_ratio = face.held_ratio(c_edge);
  sol.r_corner = r_edge;
  sol.tension_ratio = 1.0;
  sol.part_two_length = 0.0;
}

// The held profile once Part I is integrated from the edge `st`: the face (uniform at L0, or
// under a gas pressure the held face's map), the grid points inside the edge, then the edge; the
// largest I1 and the hoop compression on the profile; the height of the edge above the tip.
template <class Law>
void attach_held_profile(const ProfileStickHistory<Law>& history, const Law& law,
                         const FreeStart& st, bool record, ScaledSolution& sol) {
  const HeldProfile& q = history.profile();
  const double r_edge = st.r0, psi_edge = history.psi_at(r_edge).value_or(0.0);
  if (record) sol.part_two.clear();
  if (const auto* face = history.face_map()) {
    track_held_face(*face, q, law, q.face, record, sol);
  } else if (record) {
    constexpr int kFaceSamples = 4;  // the flat face, uniform at L0: 0 .. R_b
    const double l0 = history.points().front().l1;
    if (history.start() > 0.0)
      for (int k = 0; k < kFaceSamples; ++k)
        sol.part_two.push_back({history.start() * k / kFaceSamples, l0, 0.0});
  }
  for (const StuckPoint& p : history.points()) {
    if (!(p.r < r_edge)) break;
    const double radius = q.radius(p.theta);
    const double l2 = p.r > 0.0 ? radius / p.r : p.l1;
    const double i1 = membrane_stress(law, p.l1, l2).i1;
    if (i1 > sol.max_i1) {
      sol.max_i1 = i1;
      sol.max_i1_r = p.r;
      sol.max_i1_radius = radius;
    }
    if (sol.wrinkle_r < 0.0 && p.r > 0.0 && hoop_compressive(p.l1, l2)) {
      sol.wrinkle_r = p.r;
      sol.wrinkle_radius = radius;
    }
    if (record) sol.part_two.push_back({p.r, p.l1, p.theta});
  }
  if (record) sol.part_two.push_back({r_edge, st.state[1], psi_edge});
  sol.held_traction_ratio = history.held_ratio(r_edge);
  sol.r_corner = r_edge;
  sol.tension_ratio = 1.0;
  // On the cone: the membrane's length on it (reported as Part II's, as sliding).
  sol.part_two_length = q.on_cone(psi_edge) ? q.arc * (psi_edge - q.tangency) : 0.0;
  sol.depth += q.height(psi_edge);
}

}  // namespace puncture::detail
