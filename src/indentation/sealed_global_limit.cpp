#include "indentation/sealed_global_limit.hpp"

#include <fmt/format.h>

#include "indentation/inflated_dome.hpp"
#include "indentation/reported_failure.hpp"
#include "indentation/sealed_gas.hpp"
#include "puncture/inflation.hpp"

namespace puncture::detail {

std::optional<std::string> heading_for_global_limit(const Problem& p, const SolverOptions& options,
                                                    double passed_mpa, double failed_mpa) {
  if (!(failed_mpa > passed_mpa)) return std::nullopt;
  SolverOptions quiet = options;
  quiet.record_fields = false;
  // The inflation's limit point (the first pressure maximum before the burst, §14): the
  // pressure that stopped the search lies past it (the only outside-the-model failure of a
  // trial dome over a sealed chamber), the last one passed below it.
  const InflationCurve inflation = inflation_curve(inflation_problem(p), {}, quiet);
  if (!inflation.ok()) return std::nullopt;
  const PressureExtremum* limit = nullptr;
  for (const PressureExtremum& e : inflation.extrema)
    if (e.kind == ExtremumKind::Maximum) {
      limit = &e;
      break;
    }
  if (limit == nullptr) return std::nullopt;
  const double limit_mpa = limit->state.pressure_mpa;
  if (!(passed_mpa < limit_mpa) || failed_mpa < limit_mpa) return std::nullopt;
  return fmt::format(
      "the membrane heads for its global limit before a local puncture: the probe compresses "
      "the sealed gas (sealed at {:.6g} MPa) past {:.6g} MPa without puncturing it, up to the "
      "inflation limit point at {:.6g} MPa (the gas at {:.4g}% of it), where the inflated "
      "dome snaps through to another branch; the sealed path is not followed past it, so "
      "whether the membrane snaps through or punctures first is not computed",
      p.preload.pressure_mpa,
      passed_mpa,
      limit_mpa,
      100.0 * passed_mpa / limit_mpa);
}

}  // namespace puncture::detail
