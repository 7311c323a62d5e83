#include "indentation/sealed_global_limit.hpp"

#include <fmt/format.h>

#include "indentation/inflated_dome.hpp"
#include "indentation/reported_failure.hpp"
#include "indentation/sealed_gas.hpp"
#include "puncture/inflation.hpp"

namespace puncture::detail {

std::optional<std::string> heading_for_global_limit(const Problem& p, const SolverOptions& options,
                                                    double passed_mpa, double overhang_mpa) {
  if (!(overhang_mpa > passed_mpa)) return std::nullopt;
  SolverOptions quiet = options;
  quiet.record_fields = false;
  // The dome itself at the pressure that stopped the search: it must overhang (the only
  // outside-the-model failure of a dome), not merely fail to solve.
  try {
    const auto dome = inflated_dome(at_held_pressure(p, overhang_mpa), quiet);
    if (!dome || !overhangs_clamp(*dome)) return std::nullopt;
  } catch (const std::exception&) {
    return std::nullopt;
  }
  // The inflation's limit point (the first pressure maximum before the burst, §14).
  const InflationCurve inflation = inflation_curve(inflation_problem(p), {}, quiet);
  if (!inflation.ok()) return std::nullopt;
  const PressureExtremum* limit = nullptr;
  for (const PressureExtremum& e : inflation.extrema)
    if (e.kind == ExtremumKind::Maximum) {
      limit = &e;
      break;
    }
  if (limit == nullptr || !(overhang_mpa < limit->state.pressure_mpa)) return std::nullopt;
  const double limit_mpa = limit->state.pressure_mpa;
  return fmt::format(
      "the membrane heads for its global limit before a local puncture: the probe compresses "
      "the sealed gas (sealed at {:.6g} MPa) past {:.6g} MPa without puncturing it, and at "
      "{:.6g} MPa, just above, the inflated dome overhangs its clamp, on its way to the "
      "inflation limit point at {:.6g} MPa (the gas at {:.0f}% of it); an overhanging dome is "
      "outside the model, so whether the membrane reaches that limit or punctures first is not "
      "computed",
      p.preload.pressure_mpa,
      passed_mpa,
      overhang_mpa,
      limit_mpa,
      100.0 * passed_mpa / limit_mpa);
}

}  // namespace puncture::detail
