#pragma once
// Partial slip after a `coulomb` release on a curved probe (docs/model.md §15.4, "Partial slip
// after the release"): a held core R < R_s frozen where the history left it, a slipping annulus
// R_s < R < R_c with Coulomb slip (tau = mu p towards the tip: the membrane slides away from it)
// and the free Part I from the edge R_c.
//
// A held point keeps its stretches, so the core is the history's map and its tractions are
// frozen.  At the slip front psi, lambda2 and R s1 (no line force), hence lambda1, are
// continuous: the annulus is the initial value problem
//   dpsi/dR = lambda1 / rho,
//   dlambda1/dR = (mu p r lambda1 + s2 cos(phi) - s1 - R ds1/dl2 lambda2') / (R ds1/dl1),
// from the core's (psi, lambda1) at R_s, with p the normal balance (as sliding) and lambda2' =
// (lambda1 cos(phi) - lambda2) / R.  Only lambda1' (the traction) jumps at the front.  Part I
// leaves at R_c with the annulus's state and f = R_c s1 sin(phi) (+ the gas's share), so the
// clamp residual g(R_s, R_c) is one condition on two unknowns: the states form a one-parameter
// family, the loading path.  Besides the history's own states (R_c = R_s, an empty annulus) the
// family's branch starts at the release R_r, where the front's frozen ratio is mu, and there g =
// O((R_c - R_s)^2): with the front pinned there the release is an isolated (double) root, and
// the front must move inward for the path to go on (the edge advancing about as far, R_c - R_r ~
// R_r - R_s).  It ends where the front reaches the map's start (the pole, the face's edge): the
// state is then the sliding model's.  Lengths / (A / L0), forces / (2 pi G H A / L0), tractions
// / (G H / A), as the history.
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "indentation/contact/profile_stick.hpp"
#include "numerics/root_in_bracket.hpp"

namespace puncture::detail {

// The annulus's state at the edge and what the clamp asks of it.
struct PartialSlipEdge {
  double psi = 0.0;       // where the edge sits on the profile
  double l1 = 1.0;        // its meridional stretch
  double f = 0.0;         // the force (Part I's pull plus the gas's share inside the edge)
  double residual = 0.0;  // Part I's clamp residual (lambda2 - L0 at the clamp)
  double depth = 0.0;     // Part I's height plus the edge's height above the tip
};

// One state of the partial-slip family: the front, the edge and the edge's state.
struct PartialSlipState {
  double front = 0.0;  // R_s: held inside
  double edge = 0.0;   // R_c
  PartialSlipEdge at_edge;
};

template <class Law>
class PartialSlip {
 public:
  // Annulus steps per history grid step (classical Runge-Kutta, O(h^4)).
  static constexpr int kStepsPerGridStep = 4;
  // The fronts (fractions of the way from the map's start to the release edge) that bound a
  // depth's search: just inside the release and near the start.  Closer to the release the edge's
  // root is lost in the held map's own clamp residual (~1e-10, its interpolation), the annulus's
  // residual growing as 54 d^2 only; the depths skipped are within a few um of the release's (the
  // held state stands for them).
  static constexpr double kReleaseFront = 1.0 - 1e-3;
  static constexpr double kPoleFront = 1e-3;
  static constexpr double kStableStepFraction = 0.25;

  PartialSlip(const FreePart<Law>& part_one, const ProfileStickHistory<Law>& history, double mu)
      : part_one_(part_one), history_(history), mu_(mu) {}

  double mu() const { return mu_; }
  const FreePart<Law>& part_one() const { return part_one_; }
  const ProfileStickHistory<Law>& history() const { return history_; }

  // The annulus's (dpsi/dR, dlambda1/dR) at (r, psi, lambda1); empty past locking or where s1 no
  // longer grows with lambda1.
  std::optional<std::pair<double, double>> slope(double r, double psi, double l1) const {
    const HeldProfile& q = history_.profile();
    const bool cone = q.on_cone(psi);
    const double radius = q.radius(psi, cone), phi = q.slope(psi, cone), l2 = radius / r;
    const auto st = membrane_stress(part_one_.law(), l1, l2);
    if (!(st.i1 < part_one_.locking_i1()) || !(st.ds1_dl1 > 0.0)) return std::nullopt;
    const double p = pressure(st.s1, st.s2, l1, l2, psi, cone);
    const double dl2 = (l1 * std::cos(phi) - l2) / r;
    const double dl1 =
        (mu_ * p * radius * l1 + st.s2 * std::cos(phi) - st.s1 - r * st.ds1_dl2 * dl2) /
        (r * st.ds1_dl1);
    return std::make_pair(l1 / q.arc, dl1);
  }

  // The annulus from the front r_s to r (>= r_s): (psi, lambda1) there.
  std::optional<std::pair<double, double>> march(double r_s, double r) const {
    auto psi0 = history_.psi_at(r_s);
    auto l10 = history_.stretch_at(r_s);
    if (!psi0 || !l10 || !(r_s > 0.0) || r < r_s) return std::nullopt;
    double psi = *psi0, l1 = *l10;
    const double span = r - r_s;
    const int n =
        std::max(1, static_cast<int>(std::ceil(span / history_.step() * kStepsPerGridStep)));
    const double uniform = span / n;
    double x = r_s;
    while (x < r) {
      // Near the pole the annulus is stiff (~ -3 / R, as the history's march): steps of at most
      // a quarter of R there.
      const double h = std::min({uniform, kStableStepFraction * x, r - x});
      const auto k1 = slope(x, psi, l1);
      if (!k1) return std::nullopt;
      const auto k2 = slope(x + 0.5 * h, psi + 0.5 * h * k1->first, l1 + 0.5 * h * k1->second);
      if (!k2) return std::nullopt;
      const auto k3 = slope(x + 0.5 * h, psi + 0.5 * h * k2->first, l1 + 0.5 * h * k2->second);
      if (!k3) return std::nullopt;
      const auto k4 = slope(x + h, psi + h * k3->first, l1 + h * k3->second);
      if (!k4) return std::nullopt;
      psi += h * (k1->first + 2.0 * k2->first + 2.0 * k3->first + k4->first) / 6.0;
      l1 += h * (k1->second + 2.0 * k2->second + 2.0 * k3->second + k4->second) / 6.0;
      x = h == r - x ? r : x + h;
    }
    return std::make_pair(psi, l1);
  }

  // Part I from the annulus's edge at r_c (front r_s): the clamp residual and the depth; empty
  // where the annulus or Part I leaves the material's domain or the profile.
  std::optional<PartialSlipEdge> edge(double r_s, double r_c) const {
    const auto at = march(r_s, r_c);
    if (!at) return std::nullopt;
    const HeldProfile& q = history_.profile();
    const auto [psi, l1] = *at;
    if (!(psi > 0.0) || !(psi < q.end_psi)) return std::nullopt;
    const auto start = free_start(r_c, psi, l1);
    if (!start) return std::nullopt;
    const double pull = r_c * membrane_stress(part_one_.law(), l1, start->state[2]).s1;
    const double f = pull * std::sin(start->slope) + history_.gas_load(psi, q.on_cone(psi));
    const auto run = part_one_.run(f, *start, nullptr, false);
    if (!run.ok) return std::nullopt;
    // Depths from the inflated pole under a gas pressure (+ 0 without: bit for bit).
    return PartialSlipEdge{
        psi, l1, f, run.residual, run.height + q.height(psi) + part_one_.settings().dome_height};
  }

  // Part I leaving the profile tangentially at r_c, psi with meridional stretch l1 (t = R s1
  // cos(phi)); empty where s1 <= 0.
  std::optional<FreeStart> free_start(double r_c, double psi, double l1) const {
    const HeldProfile& q = history_.profile();
    const bool cone = q.on_cone(psi);
    const double phi = q.slope(psi, cone), l2 = q.radius(psi, cone) / r_c;
    const double s1 = membrane_stress(part_one_.law(), l1, l2).s1;
    if (!(s1 > 0.0)) return std::nullopt;
    return FreeStart{{r_c * s1 * std::cos(phi), l1, l2, 0.0}, r_c, phi, 1.0};
  }

  // The state with its front at r_s, inside the release edge r_release: the edge's root of the
  // clamp residual past the front, bracketed around 2 r_release - r_s (the leading order: the
  // frozen ratio grows linearly with R, and the annulus's lambda1 crosses the core map's again
  // where the ratio's excess mu - ratio(R_s) has been integrated away), TOMS 748 to 1e-14.
  std::optional<PartialSlipState> state(double r_s, double r_release) const {
    const double d = r_release - r_s;
    if (!(d > 0.0)) return std::nullopt;
    auto g = [&](double r_c) {
      const auto e = edge(r_s, r_c);
      return e ? e->residual : std::numeric_limits<double>::quiet_NaN();
    };
    // Scan from just past the front outward for the first change of sign, in shorter steps
    // where the longer one leaves the material's domain or the profile.
    double lo = r_s + 0.25 * d, g_lo = g(lo);
    if (!std::isfinite(g_lo)) return std::nullopt;
    for (double step = 0.25 * d; step < 64.0 * d; step *= 1.5) {
      const double hi = lo + step, g_hi = g(hi);
      if (!std::isfinite(g_hi)) {
        if (step < 1e-6 * d) return std::nullopt;
        step /= 3.0;  // half the step once the loop's factor is applied
        continue;
      }
      if ((g_lo < 0.0) != (g_hi < 0.0)) {
        std::uintmax_t iterations = 100;
        const auto root = boost::math::tools::toms748_solve(
            g,
            lo,
            hi,
            g_lo,
            g_hi,
            [&](double a, double b) { return std::abs(b - a) <= 1e-14 * std::abs(b); },
            iterations);
        const double r_c = 0.5 * (root.first + root.second);
        const auto e = edge(r_s, r_c);
        if (!e) return std::nullopt;
        return PartialSlipState{r_s, r_c, *e};
      }
      lo = hi;
      g_lo = g_hi;
    }
    return std::nullopt;
  }

  // The state at depth `depth` past the release (r_release): the front's root of the depth
  // (which grows as the front moves in), TOMS 748 to 1e-13 in the front's fraction, between
  // kReleaseFront and kPoleFront.  Empty outside their depths: beyond, the front is at the map's
  // start and the state the sliding model's.
  std::optional<PartialSlipState> state_at_depth(double depth, double r_release) const {
    const double start = history_.start();
    auto at = [&](double front) { return state(start + front * (r_release - start), r_release); };
    auto depth_gap = [&](double front) {
      const auto st = at(front);
      return st ? st->at_edge.depth - depth : std::numeric_limits<double>::quiet_NaN();
    };
    const double hi = kReleaseFront, lo = kPoleFront;
    const double g_hi = depth_gap(hi), g_lo = depth_gap(lo);
    if (!(g_hi < 0.0) || !(g_lo > 0.0)) return std::nullopt;
    const auto root = bracket_to_width(depth_gap, lo, hi, g_lo, g_hi, 1e-13);
    return at(0.5 * (root.first + root.second));
  }

  // The contact pressure on the profile (the normal balance, as sliding and held).
  double pressure(double s1, double s2, double l1, double l2, double psi, bool cone) const {
    const HeldProfile& q = history_.profile();
    return s1 * q.curvature(cone) / l2 +
           s2 * std::sin(q.slope(psi, cone)) / (l1 * q.radius(psi, cone)) + part_one_.pressure();
  }

 private:
  const FreePart<Law>& part_one_;
  const ProfileStickHistory<Law>& history_;
  double mu_;
};

}  // namespace puncture::detail
