#include "indentation/sealed_path_work.hpp"

#include <fmt/format.h>

#include "numerics/gauss_legendre.hpp"

namespace puncture::detail {

namespace {

// Graded panels towards zero depth on a pre-tensioned membrane (as add_energy_to_puncture).
constexpr int kSealedWorkGradedPanels = 10;

// Where Part II appears on the sealed path between 0 and `end` (whose state has it): the
// configuration is the one without Part II below the onset and with it above, so bisection on
// the depth to 1e-9 of it; a failing state ends it (the onset's own neighbourhood).
double sealed_part_two_onset(const Problem& p, const SealedChamber& c, double end,
                             const SolverOptions& quiet, int& states) {
  double lo = 0.0, hi = end, pressure = c.sealed_pressure_mpa;
  while (hi - lo > 1e-9 * hi) {
    const double mid = 0.5 * (lo + hi);
    const Equilibrium e = sealed_at_depth(p, c, mid, Stage::Slip, quiet, pressure);
    ++states;
    if (!e.ok()) break;
    if (e.configuration == Configuration::SlipWithPartTwo) {
      hi = mid;
    } else {
      lo = mid;
      pressure = e.gas->pressure_mpa;
    }
  }
  return hi;
}

}  // namespace

SealedPathWork sealed_path_work(const Problem& p, const SealedChamber& c, double end_depth_mm,
                                const SolverOptions& options, int panels) {
  SealedPathWork out;
  if (!(end_depth_mm > 0.0)) {
    out.work_mj = 0.0;
    return out;
  }
  SolverOptions quiet = options;
  quiet.record_fields = false;
  const Equilibrium end =
      sealed_at_depth(p, c, end_depth_mm, Stage::Slip, quiet, c.sealed_pressure_mpa);
  ++out.states;
  if (!end.ok()) {
    out.why = fmt::format("the state at {:.6g} mm: {}", end_depth_mm, end.message);
    return out;
  }
  std::vector<double> cuts{0.0};
  if (end.configuration == Configuration::SlipWithPartTwo)
    cuts.push_back(sealed_part_two_onset(p, c, end_depth_mm, quiet, out.states));
  cuts.push_back(end_depth_mm);
  const bool pretensioned = p.preload.pressure_mpa > 0.0 || p.preload.prestretch > 1.0;
  QuadratureNodes q;
  append_graded_gauss_legendre(
      cuts[0], cuts[1], panels, pretensioned ? kSealedWorkGradedPanels : 0, q);
  for (std::size_t i = 1; i + 1 < cuts.size(); ++i)
    append_gauss_legendre(cuts[i], cuts[i + 1], panels, q);
  double work = 0.0, pressure = c.sealed_pressure_mpa;  // the gas compresses along the path
  for (std::size_t k = 0; k < q.nodes.size(); ++k) {
    const Equilibrium e = sealed_at_depth(p, c, q.nodes[k], Stage::Slip, quiet, pressure);
    ++out.states;
    if (!e.ok()) {
      out.why = fmt::format("the state at {:.6g} mm: {}", q.nodes[k], e.message);
      return out;
    }
    pressure = e.gas->pressure_mpa;
    work += q.weights[k] * e.force_n;
  }
  out.work_mj = work;
  return out;
}

}  // namespace puncture::detail
