// The loading curve's events: force maxima and a shrinking contact, found between the curve's
// points and located by TOMS 748 on central differences of states solved at given depths; and
// which failure of a pre-tensioned membrane comes first (docs/model.md §8.1).
#include "indentation/curve_events.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>

namespace puncture {

std::string to_string(CurveEventKind kind) {
  switch (kind) {
    case CurveEventKind::ForceMaximum:
      return "force maximum";
    case CurveEventKind::ContactShrinks:
      return "contact shrinks";
    case CurveEventKind::SnapThrough:
      return "snap-through at a fold of the depth";
  }
  return "unknown";
}

std::string to_token(CurveEventKind kind) {
  switch (kind) {
    case CurveEventKind::ForceMaximum:
      return "force_maximum";
    case CurveEventKind::ContactShrinks:
      return "contact_shrinks";
    case CurveEventKind::SnapThrough:
      return "snap_through";
  }
  return "unknown";
}

std::string to_string(FailureMode mode) {
  switch (mode) {
    case FailureMode::LocalPuncture:
      return "local puncture at the probe";
    case FailureMode::GlobalBurst:
      return "global: the free membrane bursts away from the probe";
    case FailureMode::GlobalLimitPoint:
      return "global: a force limit point before puncture";
  }
  return "unknown";
}

std::string to_token(FailureMode mode) {
  switch (mode) {
    case FailureMode::LocalPuncture:
      return "local_puncture";
    case FailureMode::GlobalBurst:
      return "global_burst";
    case FailureMode::GlobalLimitPoint:
      return "global_limit_point";
  }
  return "unknown";
}

namespace detail {

namespace {

// The curve's forces are converged to ~1e-9 relative (SolverOptions::curve_tol): changes below
// this are no change.
constexpr double kCurveNoise = 1e-8;

std::string num5(double x) { return fmt::format("{:.6g}", x); }

// One quantity of the states along the depth: the force or the contact's reach.
enum class Quantity { Force, Reach };

double quantity_of(const CurvePoint& q, Quantity which) {
  return which == Quantity::Force ? q.force_n : contact_reach_mm(q);
}

// Where a quantity stops rising between depths a < b (its derivative by central differences
// of spacing h changes sign there): TOMS 748 on that derivative.  The result's uncertainty is
// the final bracket's half-width or the derivative's noise over its own slope, whichever is
// larger.
struct Stationary {
  double depth_mm = 0.0;
  double value = 0.0;
  DepthSample sample;
  double uncertainty_mm = 0.0;
};

class EventLocator {
 public:
  EventLocator(const DepthSampler& at_depth, Stage stage) : at_depth_(at_depth), stage_(stage) {}

  std::optional<double> value(double depth, Quantity which) const {
    const auto s = at_depth_(depth, stage_);
    if (!s) return std::nullopt;
    return which == Quantity::Force ? s->force_n : s->contact_reach_mm;
  }

  // The derivative d(quantity)/d(depth) at `depth`: central differences of spacings h and 2h
  // combined by Richardson's rule, (4 D(h) - D(2h)) / 3, exact for a quartic (a single central
  // difference errs by h^2 q'''/6, which moved a cubic's maximum by h^2/3).
  std::optional<double> slope(double depth, double h, Quantity which) const {
    const auto hi = value(depth + h, which), lo = value(depth - h, which);
    const auto hi2 = value(depth + 2.0 * h, which), lo2 = value(depth - 2.0 * h, which);
    if (!hi || !lo || !hi2 || !lo2) return std::nullopt;
    const double d1 = (*hi - *lo) / (2.0 * h), d2 = (*hi2 - *lo2) / (4.0 * h);
    return (4.0 * d1 - d2) / 3.0;
  }

  // A rising-then-falling (maximum) or falling-then-rising quantity's turning depth between a
  // and b.
  std::optional<Stationary> turning(double a, double b, Quantity which, bool maximum,
                                    double noise) const {
    const double h = 0.01 * (b - a);
    const double lo_end = a + 2.0 * h, hi_end = b - 2.0 * h;
    const auto sa = slope(lo_end, h, which), sb = slope(hi_end, h, which);
    if (!sa || !sb) return std::nullopt;
    const double sign = maximum ? 1.0 : -1.0;
    if (!(sign * *sa > 0.0 && sign * *sb < 0.0)) return std::nullopt;
    bool failed = false;
    auto g = [&](double d) {
      const auto s = slope(d, h, which);
      if (!s) failed = true;
      return s ? *s : 0.0;
    };
    std::uintmax_t iterations = 40;
    const auto bracket = boost::math::tools::toms748_solve(
        g, lo_end, hi_end, *sa, *sb, boost::math::tools::eps_tolerance<double>(34), iterations);
    if (failed) return std::nullopt;
    Stationary out;
    out.depth_mm = 0.5 * (bracket.first + bracket.second);
    const auto s = at_depth_(out.depth_mm, stage_);
    if (!s) return std::nullopt;
    out.sample = *s;
    out.value = which == Quantity::Force ? s->force_n : s->contact_reach_mm;
    // The derivative's noise (values each `noise` off: at most (4/3 + 1/6) noise |q| / h, twice
    // that for a margin) over its slope (the curvature, from the slopes at the bracket's ends).
    const double curvature = std::abs(*sb - *sa) / (hi_end - lo_end);
    const double from_noise =
        curvature > 0.0 ? 3.0 * noise * std::abs(out.value) / h / curvature : b - a;
    out.uncertainty_mm =
        std::max(0.5 * (bracket.second - bracket.first), std::min(from_noise, b - a));
    return out;
  }

  // The depth in (a, b) where the force comes back to `force` (rising through it).
  std::optional<double> regained(double a, double b, double force) const {
    const auto fa = value(a, Quantity::Force), fb = value(b, Quantity::Force);
    if (!fa || !fb || !(*fa <= force && *fb >= force)) return std::nullopt;
    bool failed = false;
    auto g = [&](double d) {
      const auto f = value(d, Quantity::Force);
      if (!f) failed = true;
      return f ? *f - force : 0.0;
    };
    std::uintmax_t iterations = 40;
    const auto bracket =
        boost::math::tools::toms748_solve(g,
                                          a,
                                          b,
                                          *fa - force,
                                          *fb - force,
                                          boost::math::tools::eps_tolerance<double>(34),
                                          iterations);
    if (failed) return std::nullopt;
    return 0.5 * (bracket.first + bracket.second);
  }

 private:
  const DepthSampler& at_depth_;
  Stage stage_;
};

// Neighbours on one smooth branch: the same stage at increasing depths (the stick -> slip
// switch repeats its depth).
bool same_branch(const CurvePoint& a, const CurvePoint& b) {
  // (The partial slip after a coulomb release is a branch of its own, up to full sliding.)
  return a.stage == b.stage && b.depth_mm > a.depth_mm &&
         a.configuration != Configuration::Unloaded &&
         (a.configuration == Configuration::PartialSlip) ==
             (b.configuration == Configuration::PartialSlip);
}

std::string configuration_words(const CurvePoint& q) {
  switch (q.configuration) {
    case Configuration::SlipWithPartTwo:
      return "the membrane sliding, wrapped down the probe's side";
    case Configuration::SlipWithoutPartTwo:
      return "the membrane sliding on the probe's tip";
    case Configuration::Stick:
      return "the membrane held at the probe's edge";
    case Configuration::PartialSlip:
      return "the membrane held inside the slip front, sliding outside it";
    case Configuration::Unloaded:
      return "unloaded";
  }
  return "";
}

// Index i of interior local maxima (rising = true) or minima of `which` on one branch, beyond
// the noise.
std::vector<std::size_t> turning_points(const std::vector<CurvePoint>& q, Quantity which,
                                        bool maximum, std::size_t from) {
  std::vector<std::size_t> out;
  for (std::size_t i = std::max<std::size_t>(from, 1); i + 1 < q.size(); ++i) {
    if (!same_branch(q[i - 1], q[i]) || !same_branch(q[i], q[i + 1])) continue;
    const double prev = quantity_of(q[i - 1], which), x = quantity_of(q[i], which),
                 next = quantity_of(q[i + 1], which);
    const double tol = kCurveNoise * std::max(std::abs(x), 1e-12);
    const double s = maximum ? 1.0 : -1.0;
    if (s * (x - prev) >= 0.0 && s * (x - next) > tol) out.push_back(i);
  }
  return out;
}

CurveEvent force_maximum(const std::vector<CurvePoint>& q, std::size_t i,
                         const DepthSampler& at_depth) {
  CurveEvent e;
  e.kind = CurveEventKind::ForceMaximum;
  const EventLocator locate(at_depth, q[i].stage);
  const auto found =
      locate.turning(q[i - 1].depth_mm, q[i + 1].depth_mm, Quantity::Force, true, 1e-9);
  if (found) {
    e.depth_mm = found->depth_mm;
    e.force_n = found->sample.force_n;
    e.contact_reach_mm = found->sample.contact_reach_mm;
    e.depth_uncertainty_mm = found->uncertainty_mm;
  } else {  // not located more finely than the curve's points
    e.depth_mm = q[i].depth_mm;
    e.force_n = q[i].force_n;
    e.contact_reach_mm = contact_reach_mm(q[i]);
    e.depth_uncertainty_mm = q[i + 1].depth_mm - q[i - 1].depth_mm;
  }
  // The first deeper point of the branch that carries the force again.
  for (std::size_t j = i + 1; j < q.size() && same_branch(q[j - 1], q[j]); ++j)
    if (q[j].force_n >= e.force_n) {
      e.end_depth_mm = locate.regained(q[j - 1].depth_mm, q[j].depth_mm, e.force_n);
      if (!e.end_depth_mm) e.end_depth_mm = q[j].depth_mm;
      break;
    }
  e.description = fmt::format(
      "the force peaks at {} N at depth {} mm ({}) and falls past it: the membrane softens "
      "faster than the deeper contact stiffens it, dF/d(depth) = 0 (located to {} mm); under "
      "force control the probe snaps through {}",
      num5(e.force_n),
      num5(e.depth_mm),
      configuration_words(q[i]),
      num5(e.depth_uncertainty_mm),
      e.end_depth_mm ? fmt::format("to depth {} mm at the same force", num5(*e.end_depth_mm))
                     : std::string("beyond the end of the curve (no deeper point carries it)"));
  return e;
}

CurveEvent contact_shrinks(const std::vector<CurvePoint>& q, std::size_t i,
                           const DepthSampler& at_depth) {
  CurveEvent e;
  e.kind = CurveEventKind::ContactShrinks;
  const EventLocator locate(at_depth, q[i].stage);
  const auto found =
      locate.turning(q[i - 1].depth_mm, q[i + 1].depth_mm, Quantity::Reach, true, 1e-9);
  if (found) {
    e.depth_mm = found->depth_mm;
    e.force_n = found->sample.force_n;
    e.contact_reach_mm = found->sample.contact_reach_mm;
    e.depth_uncertainty_mm = found->uncertainty_mm;
  } else {
    e.depth_mm = q[i].depth_mm;
    e.force_n = q[i].force_n;
    e.contact_reach_mm = contact_reach_mm(q[i]);
    e.depth_uncertainty_mm = q[i + 1].depth_mm - q[i - 1].depth_mm;
  }
  // Where it grows again: the next minimum of the reach on the branch.
  for (const std::size_t j : turning_points(q, Quantity::Reach, false, i + 1)) {
    bool one_branch = true;
    for (std::size_t k = i + 1; k <= j + 1 && k < q.size(); ++k)
      one_branch = one_branch && same_branch(q[k - 1], q[k]);
    if (!one_branch) break;
    const auto lowest =
        locate.turning(q[j - 1].depth_mm, q[j + 1].depth_mm, Quantity::Reach, false, 1e-9);
    e.end_depth_mm = lowest ? lowest->depth_mm : q[j].depth_mm;
    break;
  }
  e.description = fmt::format(
      "the contact stops growing at depth {} mm ({} N; its edge {} mm out and up the probe, "
      "{}) and shrinks as the probe goes deeper: the free membrane pulls its edge back towards "
      "the tip{}",
      num5(e.depth_mm),
      num5(e.force_n),
      num5(e.contact_reach_mm),
      configuration_words(q[i]),
      e.end_depth_mm ? fmt::format("; it grows again from {} mm", num5(*e.end_depth_mm))
                     : std::string(" to the end of the curve"));
  return e;
}

}  // namespace

std::vector<CurveEvent> located_curve_events(const std::vector<CurvePoint>& points,
                                             const DepthSampler& at_depth) {
  std::vector<CurveEvent> out;
  for (const std::size_t i : turning_points(points, Quantity::Force, true, 1))
    out.push_back(force_maximum(points, i, at_depth));
  for (const std::size_t i : turning_points(points, Quantity::Reach, true, 1))
    out.push_back(contact_shrinks(points, i, at_depth));
  std::stable_sort(out.begin(), out.end(), [](const CurveEvent& a, const CurveEvent& b) {
    return a.depth_mm < b.depth_mm;
  });
  return out;
}

bool pretensioned(const Problem& p) {
  return p.preload.pressure_mpa > 0.0 || p.preload.gas_volume_mm3 || p.preload.prestretch != 1.0;
}

std::optional<FailureVerdict> failure_verdict(const Problem& p, const LoadingCurve& curve) {
  if (!pretensioned(p)) return std::nullopt;
  const PuncturePrediction& puncture = curve.puncture;
  const auto limit =
      std::find_if(curve.events.begin(), curve.events.end(), [&](const CurveEvent& e) {
        return e.kind == CurveEventKind::ForceMaximum &&
               (!puncture.ok() || e.depth_mm < puncture.depth_mm);
      });
  FailureVerdict v;
  if (limit != curve.events.end()) {
    v.mode = FailureMode::GlobalLimitPoint;
    v.depth_mm = limit->depth_mm;
    v.force_n = limit->force_n;
    v.where = "the whole membrane (a limit point of the force)";
    v.reason = fmt::format(
        "the force reaches a maximum, {} N at {} mm, {}: held at that force{} the membrane "
        "snaps through (or bursts) there",
        num5(limit->force_n),
        num5(limit->depth_mm),
        puncture.ok() ? fmt::format("before the puncture ({} N at {} mm)",
                                    num5(puncture.force_n),
                                    num5(puncture.depth_mm))
                      : std::string("and no puncture is found"),
        p.preload.pressure_mpa > 0.0 && !p.preload.gas_volume_mm3 ? " and pressure" : "");
    return v;
  }
  if (!puncture.ok()) return std::nullopt;
  const Equilibrium& s = puncture.state;
  v.depth_mm = puncture.depth_mm;
  v.force_n = puncture.force_n;
  v.where = puncture.crack_location;
  // The contact's edge is where Part I starts (reference radius): a largest measure in the free
  // membrane beyond it (an interior maximum of Part I, not its value at the edge) is the dome's
  // own, away from the probe.
  const double edge_r = s.part_two_top_reference_radius_mm;
  const double crack_r = puncture.crack_reference_radius_mm;
  const bool in_free_dome =
      s.max_first_invariant_part == MembranePart::Free && crack_r > edge_r * (1.0 + 1e-6) + 1e-9;
  if (in_free_dome) {
    v.mode = FailureMode::GlobalBurst;
    v.reason = fmt::format(
        "the criterion is reached first in the free membrane at reference radius {} mm, "
        "{} mm beyond the contact's edge ({} mm; current radius {} mm), before any point at the "
        "probe: the dome bursts away from the probe, at {} N and {} mm",
        num5(crack_r),
        num5(crack_r - edge_r),
        num5(edge_r),
        num5(puncture.crack_radius_mm),
        num5(puncture.force_n),
        num5(puncture.depth_mm));
  } else {
    v.mode = FailureMode::LocalPuncture;
    v.reason = fmt::format(
        "the criterion is reached first at the probe ({}), at {} N and {} mm, and the force "
        "rises all the way to it (no limit point): the probe punctures the membrane locally",
        puncture.crack_location,
        num5(puncture.force_n),
        num5(puncture.depth_mm));
  }
  return v;
}

}  // namespace detail

}  // namespace puncture
