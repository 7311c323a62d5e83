#pragma once
// The indenter's work on a later inflated state from its dome to the fold of its path in depth
// (docs/model.md §8.1, "The energy across the snap-through"): the energy to puncture under depth
// control adds it to the landed state's own.
#include <optional>

#include "indentation/curve_following.hpp"
#include "indentation/depth_arclength.hpp"
#include "numerics/gauss_legendre.hpp"

namespace puncture::detail {

// int_0^fold F d(depth) [mJ], in two pieces: to the deepest state depth control reached
// (branch.states.front()), graded Gauss-Legendre as the energy to puncture's (kEnergyPanels,
// the forces at its nodes from the curve driver); from there to the fold, over the continued
// states, the area under their polyline in (depth, F), but for the last interval, which ends at
// the fold, where depth(F) has its vertex (dDepth/dF = 0): the parabola's, (2 F_a + F_fold) / 3
// times its depth interval (the chord's would miss (F_fold - F_a) / 6 of it there, F(depth)
// having a square-root end).  Empty where the curve driver fails.
template <class Shooting>
std::optional<double> work_to_fold_mj(const Problem& p, const Shooting& shooting, double curve_tol,
                                      const FoldBranch& branch) {
  const SolverScales units = solver_scales(p);
  const double deepest_mm = branch.states.front().depth * units.length_mm;
  QuadratureNodes q;
  append_graded_gauss_legendre(0.0, deepest_mm, kEnergyPanels, kEnergyGradedPanels, q);
  CurveOptions at_nodes;
  at_nodes.depths_mm = q.nodes;
  LoadingCurve path;
  StageBoundary slip;  // under a held pressure the membrane slides from the first touch
  slip.status = Status::Converged;
  slip.first_stage = Stage::Slip;
  if (!follow_curve(
          p, shooting, curve_tol, slip, deepest_mm, false, std::nullopt, at_nodes, path) ||
      path.points.size() != q.nodes.size())
    return std::nullopt;
  double work = 0.0;
  for (std::size_t j = 0; j < q.nodes.size(); ++j) work += q.weights[j] * path.points[j].force_n;
  for (std::size_t i = 0; i < branch.fold_index; ++i) {
    const double d_a = branch.states[i].depth * units.length_mm;
    const double d_b = branch.states[i + 1].depth * units.length_mm;
    const double f_a = branch.states[i].f * units.force_n,
                 f_b = branch.states[i + 1].f * units.force_n;
    work += i + 1 == branch.fold_index ? (d_b - d_a) * (2.0 * f_a + f_b) / 3.0
                                       : (d_b - d_a) * (f_a + f_b) / 2.0;
  }
  return work;
}

}  // namespace puncture::detail
