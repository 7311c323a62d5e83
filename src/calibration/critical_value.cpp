// Critical values of every failure criterion from the marks of inflation tests at burst.
#include "puncture/critical_value.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "calibration/sample_statistics.hpp"
#include "puncture/inflation.hpp"

namespace puncture {

namespace {

void summarise(CriticalValueEstimate& out) {
  detail::summarise_sample(out.values, out);
  out.criterion = criterion_from_name(criterion_name(out.criterion), out.mean);
}

}  // namespace

CriticalValueEstimate critical_value_from_inflation(const std::vector<BurstTest>& tests,
                                                    const FailureCriterion& criterion,
                                                    const Material& material, bool pole_only) {
  // The stretches and their checks are the critical I1's (same tests, same messages).
  const CriticalI1Estimate poles = critical_i1_from_inflation(tests);
  CriticalValueEstimate out;
  out.criterion = criterion;
  out.stretches = poles.stretches;
  InflationProblem membrane;
  membrane.material = material;
  // Not used by the states; only kept valid (below a Gent locking).
  const double locking = locking_first_invariant(material.law);
  if (std::isfinite(locking)) membrane.critical_i1 = std::min(95.2, 0.5 * (3.0 + locking));
  validate(membrane);
  for (std::size_t i = 0; i < out.stretches.size(); ++i) {
    const double stretch = out.stretches[i];
    if (first_invariant(stretch, stretch) >= locking)
      throw std::invalid_argument(
          fmt::format("test {}: the mark's stretch {:.6g} gives I1 = {:.6g} at the pole, at or "
                      "beyond the material's locking value {:.6g}: this law cannot describe "
                      "the test",
                      i + 1,
                      stretch,
                      first_invariant(stretch, stretch),
                      locking));
    const double pole = measure_at(criterion, material, stretch, stretch);
    out.pole_values.push_back(pole);
    if (pole_only) {
      out.values.push_back(pole);
      out.radius_fractions.push_back(0.0);
      continue;
    }
    out.from_membrane = true;
    const InflationState state = inflate_at_pole_stretch(membrane, stretch);
    if (!state.ok()) {
      out.status = state.status;
      out.message = fmt::format(
          "test {}: no inflated state at pole stretch {:.6g}: {}", i + 1, stretch, state.message);
      return out;
    }
    // The pole's closed form is exact there; a sampled value elsewhere counts only above it.
    const FailureAssessment a = assess_fields(criterion, state.fields, material);
    const bool at_pole = !(a.value > pole);
    out.values.push_back(at_pole ? pole : a.value);
    out.radius_fractions.push_back(at_pole ? 0.0
                                           : a.reference_radius_mm / membrane.clamp_radius_mm);
  }
  out.status = Status::Converged;
  summarise(out);
  return out;
}

}  // namespace puncture
