#pragma once
// The partial slip's states as the user sees them (partial_slip_path.hpp): a state as an
// Equilibrium (state --depth), and the puncture within the partial-slip stretch, the first state
// of the family whose largest I1 reaches the critical value.  The other criteria read fields the
// family's puncture search does not evaluate on every state: not searched there.
#include <fmt/format.h>

#include <optional>
#include <variant>

#include "indentation/partial_slip_path.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/failure.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::detail {

// Whether a partial-slip state's largest I1 exceeds a critical I1 of the problem (the curve's
// margin, exceeded()'s).
inline bool partial_slip_beyond_puncture(const Problem& p, double max_first_invariant) {
  for (const auto& c : failure_criteria(p))
    if (std::holds_alternative<CriticalFirstInvariant>(c) &&
        max_first_invariant > critical_value(c) * (1.0 + 1e-8))
      return true;
  return false;
}

inline Equilibrium partial_slip_equilibrium(const Problem& p, const PartialSlipSegment& segment,
                                            PartialSlipDetail d) {
  const CurvePoint& pt = d.point;
  Equilibrium e;
  e.status = Status::Converged;
  e.stage = Stage::Slip;
  e.configuration = Configuration::PartialSlip;
  e.force_n = pt.force_n;
  e.normalized_force = pt.normalized_force;
  e.depth_mm = pt.depth_mm;
  e.part_three_stretch = pt.part_three_stretch;
  e.contact_edge_radius_mm = pt.contact_edge_radius_mm;
  e.contact_edge_height_mm = pt.contact_edge_height_mm;
  e.corner_slope_rad = pt.corner_slope_rad;
  e.slip_front_reference_radius_mm = pt.slip_front_reference_radius_mm;
  e.slip_front_radius_mm = pt.slip_front_radius_mm;
  e.max_first_invariant = pt.max_first_invariant;
  e.max_first_invariant_reference_radius_mm = d.largest_i1_reference_radius_mm;
  e.max_first_invariant_radius_mm = d.largest_i1_radius_mm;
  e.max_first_invariant_part =
      d.site == PartialSlipSite::FreePart ? MembranePart::Free : MembranePart::Tip;
  e.beyond_puncture = partial_slip_beyond_puncture(p, pt.max_first_invariant);
  e.fields = std::move(d.fields);
  e.message = fmt::format(
      "partial slip after the coulomb release (released at depth {:.6g} mm): held inside the "
      "slip front at R = {:.6g} mm (r = {:.6g} mm), sliding outside it; largest I1 at {}",
      segment.release_depth_mm,
      e.slip_front_reference_radius_mm,
      e.slip_front_radius_mm,
      to_string(d.site));
  return e;
}

// The puncture by `criterion` within the partial-slip stretch (a critical I1 only); empty when
// the family's largest I1 stays below it up to the hand-over, or for another criterion.
inline std::optional<PuncturePrediction> partial_slip_puncture(const Problem& p,
                                                               const PartialSlipSegment& segment,
                                                               const FailureCriterion& criterion,
                                                               bool fields) {
  if (!std::holds_alternative<CriticalFirstInvariant>(criterion) || !segment.reaching_i1)
    return std::nullopt;
  auto found = segment.reaching_i1(critical_value(criterion), fields);
  if (!found) return std::nullopt;
  PuncturePrediction out;
  out.status = Status::Converged;
  out.criterion = describe(criterion);
  out.force_n = found->point.force_n;
  out.normalized_force = found->point.normalized_force;
  out.depth_mm = found->point.depth_mm;
  out.stage = Stage::Slip;
  out.configuration = Configuration::PartialSlip;
  out.part_three_stretch = found->point.part_three_stretch;
  out.crack_reference_radius_mm = found->largest_i1_reference_radius_mm;
  out.crack_radius_mm = found->largest_i1_radius_mm;
  out.crack_location = to_string(found->site) + ", during the partial slip";
  out.state = partial_slip_equilibrium(p, segment, std::move(*found));
  return out;
}

}  // namespace puncture::detail
