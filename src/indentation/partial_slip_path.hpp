#pragma once
// The loading path after a `coulomb` release on a curved probe (docs/model.md §15.4, "Partial
// slip after the release"): from the release to the depth where the slip front reaches the map's
// start (the pole, the fillet's face edge) the path's states are the partial-slip family's
// (contact/partial_slip.hpp); past that hand-over they are the sliding model's, which the family
// meets there.  The curve driver (curve_following.hpp) takes its points from here on that stretch.
#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>

#include "indentation/contact/partial_slip.hpp"
#include "indentation/partial_slip_fields.hpp"
#include "indentation/solver_scales.hpp"
#include "numerics/root_in_bracket.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::detail {

// A partial-slip state as a curve point (stage Slip, Configuration::PartialSlip): force and depth,
// the frozen pole's stretch, the contact's edge, the slip front and the largest I1 (the held core's
// grid points, the annulus's samples, Part I's maximum).
struct PartialSlipPoint {
  CurvePoint point;
  double edge_reference_radius_mm = 0.0;
};

// Where a partial-slip state's I1 is largest.
enum class PartialSlipSite { Pole, Face, HeldCore, SlipFront, Annulus, ContactEdge, FreePart };

inline std::string to_string(PartialSlipSite site) {
  switch (site) {
    case PartialSlipSite::Pole:
      return "the held pole, under the tip";
    case PartialSlipSite::Face:
      return "the held flat face (as stretched as where it touched)";
    case PartialSlipSite::HeldCore:
      return "the held core, between the pole and the slip front";
    case PartialSlipSite::SlipFront:
      return "the slip front, where the held core meets the slipping annulus";
    case PartialSlipSite::Annulus:
      return "the slipping annulus, between the slip front and the contact edge";
    case PartialSlipSite::ContactEdge:
      return "the contact edge, where the membrane leaves the probe";
    case PartialSlipSite::FreePart:
      return "Part I, off the indenter";
  }
  return "?";
}

// The largest I1 of a partial-slip state and where it is (radii / (A / L0)).
struct PartialSlipLargestI1 {
  double value = 3.0;
  PartialSlipSite site = PartialSlipSite::Pole;
  double reference_radius = 0.0;
  double radius = 0.0;
  MembranePart part() const {
    return site == PartialSlipSite::FreePart ? MembranePart::Free : MembranePart::Tip;
  }
};

// A partial-slip state at a depth: the curve point, where its I1 is largest (mm) and, when
// asked, its fields along the meridian.
struct PartialSlipDetail {
  CurvePoint point;
  PartialSlipSite site = PartialSlipSite::Pole;
  double largest_i1_reference_radius_mm = 0.0;
  double largest_i1_radius_mm = 0.0;
  MembraneFields fields;
};

// The stretch of the path that follows the family, in mm: from the release's depth (the held
// state's, an empty annulus) to the hand-over, with the family's state at a depth in between.
struct PartialSlipSegment {
  double release_depth_mm = 0.0;
  // The family's first depth a depth's search resolves (PartialSlip::kReleaseFront, a few um past
  // the release): between the release and it the held state stands for the family's.
  double first_depth_mm = 0.0;
  double handover_depth_mm = 0.0;  // the front at the map's start (PartialSlip::kPoleFront)
  double handover_force_n = 0.0;
  CurvePoint release;  // the family's state at the release (the held one)
  std::function<std::optional<CurvePoint>(double depth_mm)> at_depth;  // empty outside the family
  // The family's state at a depth with its fields (when `fields`); empty outside the family.
  std::function<std::optional<PartialSlipDetail>(double depth_mm, bool fields)> detail_at_depth;
  // The first state of the family (from the release inward) whose largest I1 reaches
  // `critical_i1`, the puncture within the stretch; empty when none does before the hand-over.
  std::function<std::optional<PartialSlipDetail>(double critical_i1, bool fields)> reaching_i1;
  bool covers(double depth_mm) const {
    return depth_mm > release_depth_mm && depth_mm < handover_depth_mm;
  }
};

// The family on a held-profile history with its Part I and the release edge.
template <class Law>
class PartialSlipPath {
 public:
  // Sub-intervals of the annulus sampled for its largest I1 (it grows smoothly outward, to the
  // edge's value; the edge itself is sampled as Part I's start).
  static constexpr int kAnnulusSamples = 8;

  PartialSlipPath(const ProfileStickHistory<Law>& history, const Law& law,
                  const ShootingSettings& settings, double mu, const SolverScales& units)
      : part_one_(law, settings),
        history_(history),
        slip_(part_one_, history_, mu),
        units_(units) {}

  // The release edge R_r where the held points' largest |tau| / p reaches mu (bisected between
  // the history's grid points to 1e-15); empty when the history never reaches mu.
  std::optional<double> release_edge() const {
    const auto& pts = history_.points();
    const double mu = slip_.mu();
    if (pts.size() < 3 || !(history_.held_ratio(pts.back().r) >= mu)) return std::nullopt;
    std::size_t k = 2;
    while (k + 1 < pts.size() && history_.held_ratio(pts[k].r) < mu) ++k;
    std::uintmax_t iterations = 200;
    const auto root =
        boost::math::tools::bisect([&](double r) { return history_.held_ratio(r) - mu; },
                                   pts[k - 1].r,
                                   pts[k].r,
                                   [](double a, double b) { return std::abs(b - a) <= 1e-15; },
                                   iterations);
    return 0.5 * (root.first + root.second);
  }

  const PartialSlip<Law>& family() const { return slip_; }

  // The state with its front a fraction `front` of the way from the map's start to the release.
  std::optional<PartialSlipState> at_front(double front, double release) const {
    const double start = history_.start();
    return slip_.state(start + front * (release - start), release);
  }

  // The curve point of a state of the family.
  std::optional<CurvePoint> point(const PartialSlipState& st) const {
    const HeldProfile& q = history_.profile();
    const auto front_psi = history_.psi_at(st.front);
    if (!front_psi) return std::nullopt;
    const double psi = st.at_edge.psi;
    CurvePoint pt;
    pt.depth_mm = st.at_edge.depth * units_.length_mm;
    pt.force_n = st.at_edge.f * units_.force_n;
    pt.normalized_force = units_.normalized_force(st.at_edge.f);
    pt.stage = Stage::Slip;
    pt.configuration = Configuration::PartialSlip;
    pt.part_three_stretch = history_.first_touch_stretch();  // the held pole keeps its stretch
    pt.contact_edge_radius_mm = q.radius(psi) * units_.length_mm;
    pt.contact_edge_height_mm = q.height(psi) * units_.length_mm;
    pt.corner_slope_rad = q.slope(psi);  // Part I leaves the smooth profile tangentially
    pt.slip_front_reference_radius_mm = st.front * units_.length_mm;
    pt.slip_front_radius_mm = q.radius(*front_psi) * units_.length_mm;
    const auto i1 = largest_i1(st);
    if (!i1) return std::nullopt;
    pt.max_first_invariant = *i1;
    return pt;
  }

  // The largest I1 of the state: the held core (its grid points and the pole), the annulus's
  // samples and Part I's interior maximum.
  std::optional<double> largest_i1(const PartialSlipState& st) const {
    const auto largest = largest_i1_site(st);
    if (!largest) return std::nullopt;
    return largest->value;
  }

  // The same with its place: the first sample holding the largest value (the pole or face,
  // the core's grid points, the annulus's samples from the front to the edge, Part I's maximum).
  std::optional<PartialSlipLargestI1> largest_i1_site(const PartialSlipState& st) const {
    const HeldProfile& q = history_.profile();
    const double pole = history_.first_touch_stretch();
    PartialSlipLargestI1 out;
    out.value = first_invariant(pole, pole);
    out.site = q.face > 0.0 ? PartialSlipSite::Face : PartialSlipSite::Pole;
    auto observe = [&](double i1, PartialSlipSite site, double r, double radius) {
      if (i1 > out.value) out = {i1, site, r, radius};
    };
    for (const StuckPoint& k : history_.points()) {
      if (k.r > st.front) break;
      if (k.r > 0.0)
        observe(first_invariant(k.l1, q.radius(k.theta) / k.r),
                PartialSlipSite::HeldCore,
                k.r,
                q.radius(k.theta));
    }
    for (int i = 0; i <= kAnnulusSamples; ++i) {
      const double r = st.front + (st.edge - st.front) * i / kAnnulusSamples;
      const auto at = slip_.march(st.front, r);
      if (!at) return std::nullopt;
      observe(first_invariant(at->second, q.radius(at->first) / r),
              i == 0                 ? PartialSlipSite::SlipFront
              : i == kAnnulusSamples ? PartialSlipSite::ContactEdge
                                     : PartialSlipSite::Annulus,
              r,
              q.radius(at->first));
    }
    const auto start = slip_.free_start(st.edge, st.at_edge.psi, st.at_edge.l1);
    if (!start) return std::nullopt;
    const auto run = part_one_.run(st.at_edge.f, *start, nullptr, true);
    if (!run.ok) return std::nullopt;
    // Part I's maximum at its start is the edge's own value.
    const bool at_edge = run.max_i1_r <= st.edge * (1.0 + 1e-9);
    observe(run.max_i1,
            at_edge ? PartialSlipSite::ContactEdge : PartialSlipSite::FreePart,
            run.max_i1_r,
            run.max_i1_radius);
    return out;
  }

  // The state's detail (lengths in mm); empty where its annulus or Part I cannot be re-solved.
  std::optional<PartialSlipDetail> detail(const PartialSlipState& st,
                                          const FieldScales* fields) const {
    auto pt = point(st);
    const auto largest = largest_i1_site(st);
    if (!pt || !largest) return std::nullopt;
    PartialSlipDetail out;
    out.point = *pt;
    out.site = largest->site;
    out.largest_i1_reference_radius_mm = largest->reference_radius * units_.length_mm;
    out.largest_i1_radius_mm = largest->radius * units_.length_mm;
    if (fields && !append_partial_slip_fields(slip_, st, *fields, out.fields)) return std::nullopt;
    return out;
  }

  // The first state from the release inward whose largest I1 reaches `critical`: the fronts
  // scanned from kReleaseFront in tenths of the way to kPoleFront for a change of sign, then
  // TOMS 748 to 1e-13 in the front's fraction (as state_at_depth); the state on the critical
  // side.  The family's first state when it already exceeds it (within a few um of the
  // release, where the held state stands for the family).  The largest I1 grows along the path
  // (the samples' maximum is continuous in the front); a dip between two scanned fronts would
  // go unseen.
  std::optional<PartialSlipState> first_reaching_i1(double critical, double release) const {
    auto excess = [&](double front) {
      const auto st = at_front(front, release);
      const auto i1 = st ? largest_i1(*st) : std::nullopt;
      return i1 ? *i1 - critical : std::numeric_limits<double>::quiet_NaN();
    };
    constexpr double kFirst = PartialSlip<Law>::kReleaseFront, kLast = PartialSlip<Law>::kPoleFront;
    double hi = kFirst, g_hi = excess(hi);
    if (!std::isfinite(g_hi)) return std::nullopt;
    if (g_hi >= 0.0) return at_front(hi, release);
    for (int k = 9; k >= 0; --k) {
      const double lo = k == 0 ? kLast : 0.1 * k, g_lo = excess(lo);
      if (!std::isfinite(g_lo)) return std::nullopt;
      if (g_lo >= 0.0) {
        const auto root = bracket_to_width(excess, lo, hi, g_lo, g_hi, 1e-13);
        return at_front(root.first, release);  // the inner end: past the critical value
      }
      hi = lo;
      g_hi = g_lo;
    }
    return std::nullopt;
  }

 private:
  FreePart<Law> part_one_;
  const ProfileStickHistory<Law>& history_;
  PartialSlip<Law> slip_;
  SolverScales units_;
};

// The segment of a `coulomb` problem whose membrane is released at a finite depth on a curved
// probe (a contact with a held-profile history: the sphere-tipped probe, the filleted punch, the
// cone and the ball; under a gas pressure not the filleted punch); empty otherwise, or where the
// family's ends cannot be solved (the curve then jumps to the sliding model at the release, as the
// report says).
template <class Shooting>
std::optional<PartialSlipSegment> partial_slip_segment(const Problem& p, const Shooting& shooting,
                                                       const StageBoundary& boundary) {
  const auto& contact = shooting.contact();
  if constexpr (!requires(const std::decay_t<decltype(contact)>& c) { c.held_profile_history(); }) {
    return std::nullopt;
  } else {
    if (p.stick.rule != StickRule::Coulomb || !boundary.switches) return std::nullopt;
    // Under a gas pressure the filleted punch's face carries the gas and slides with friction in
    // the sliding model (a rough face), while the family holds it: its front's end is not the
    // sliding state (0.12108 N against 0.12117 N), so the curve jumps there (docs/model.md §15.4).
    if (p.preload.pressure_mpa > 0.0 && contact.held_profile_history().profile().face > 0.0)
      return std::nullopt;
    using Law = std::decay_t<decltype(contact.law())>;
    const auto path = std::make_shared<PartialSlipPath<Law>>(contact.held_profile_history(),
                                                             contact.law(),
                                                             shooting.settings(),
                                                             p.friction,
                                                             solver_scales(p));
    const auto release = path->release_edge();
    if (!release) return std::nullopt;
    const auto& slip = path->family();
    const auto at_release = slip.edge(*release, *release);
    const auto first = path->at_front(PartialSlip<Law>::kReleaseFront, *release);
    const auto last = path->at_front(PartialSlip<Law>::kPoleFront, *release);
    if (!at_release || !first || !last) return std::nullopt;
    PartialSlipState empty_annulus{*release, *release, *at_release};
    const auto release_point = path->point(empty_annulus);
    if (!release_point) return std::nullopt;
    PartialSlipSegment out;
    out.release = *release_point;
    out.release_depth_mm = boundary.depth_mm;
    const double big_a = solver_scales(p).length_mm;
    out.first_depth_mm = first->at_edge.depth * big_a;
    out.handover_depth_mm = last->at_edge.depth * big_a;
    out.handover_force_n = last->at_edge.f * solver_scales(p).force_n;
    const double r_release = *release;
    out.at_depth = [path, r_release, big_a](double depth_mm) -> std::optional<CurvePoint> {
      const auto st = path->family().state_at_depth(depth_mm / big_a, r_release);
      if (!st) return std::nullopt;
      return path->point(*st);
    };
    const FieldScales scales{big_a, p.material.shear_modulus_mpa, p.geometry.thickness_mm};
    out.detail_at_depth = [path, r_release, big_a, scales](
                              double depth_mm, bool fields) -> std::optional<PartialSlipDetail> {
      const auto st = path->family().state_at_depth(depth_mm / big_a, r_release);
      if (!st) return std::nullopt;
      return path->detail(*st, fields ? &scales : nullptr);
    };
    out.reaching_i1 = [path, r_release, scales](double critical,
                                                bool fields) -> std::optional<PartialSlipDetail> {
      const auto st = path->first_reaching_i1(critical, r_release);
      if (!st) return std::nullopt;
      return path->detail(*st, fields ? &scales : nullptr);
    };
    return out;
  }
}

}  // namespace puncture::detail
