// The finite-element dome: the start state of the finite elements under a gas pressure.
#include "fe/inflated_dome_fe.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fe/energy_newton.hpp"
#include "fe/meridian_mesh.hpp"
#include "fe/part_evaluation.hpp"
#include "indentation/inflated_dome.hpp"
#include "indentation/reported_failure.hpp"
#include "indentation/solver_scales.hpp"

namespace puncture::fe {
namespace {

// One free part from the pole (r = 0, z unknown) to the clamp, linear in R: the pole is a node,
// its height the dome's.
Mesh dome_mesh(double clamp, double pressure, const FeOptions& options) {
  Mesh mesh;
  mesh.order = options.order;
  mesh.pressure = pressure;
  int next = 0;
  const int n = options.elements * options.order;
  MeshPart part{
      MembranePart::Free, false, options.elements, fixed_slot(0.0), fixed_slot(1.0), {}, {}};
  for (int i = 0; i <= n; ++i) {
    part.r.push_back(i == 0 ? fixed_slot(0.0) : i == n ? fixed_slot(clamp) : unknown_slot(next++));
    part.z.push_back(i == n ? fixed_slot(0.0) : unknown_slot(next++));
  }
  mesh.parts.push_back(part);
  mesh.unknowns = next;
  return mesh;
}

// The shooting's dome sampled at reference radius R (linear between its samples): r and z.
void dome_guess_at(const detail::InflatedDome& dome, double R, double& r, double& z) {
  const auto& samples = dome.state.part_one;  // (R, t, lambda1, lambda2, h), h = -drop
  auto above = std::lower_bound(
      samples.begin(), samples.end(), R, [](const auto& s, double x) { return s[0] < x; });
  if (above == samples.end()) above = std::prev(samples.end());
  const auto below = above == samples.begin() ? above : std::prev(above);
  const double span = (*above)[0] - (*below)[0];
  const double w = span > 0.0 ? (R - (*below)[0]) / span : 0.0;
  const double l2 = (*below)[3] + w * ((*above)[3] - (*below)[3]);
  const double h = (*below)[4] + w * ((*above)[4] - (*below)[4]);
  r = l2 * R;
  z = -(dome.height + h);
}

}  // namespace

FeDome solve_dome(const Problem& problem, const FeOptions& options) {
  SolverOptions sampled;
  sampled.record_fields = true;
  FeDome dome;
  FeState& state = dome.state;
  state.order = options.order;
  std::optional<detail::InflatedDome> shooting;
  try {
    shooting = detail::inflated_dome(problem, sampled);
  } catch (const detail::PhysicalFailure& e) {
    state.status = e.status();
    state.message = std::string("no inflated state to indent: ") + e.what();
    return dome;
  }
  const double A = reference_clamp_radius_mm(problem), clamp = problem.preload.prestretch;
  const Mesh mesh = dome_mesh(clamp, detail::dome_pressure(problem), options);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(mesh.unknowns);
  const MeshPart& part = mesh.parts.front();
  const int n = int(part.r.size()) - 1;
  for (int i = 0; i <= n; ++i) {
    double r, z;
    dome_guess_at(*shooting, double(i) / n, r, z);
    if (part.r[i].index >= 0) x[part.r[i].index] = r;
    if (part.z[i].index >= 0) x[part.z[i].index] = z;
  }
  const NewtonResult newton =
      minimise_energy(problem.material.law, mesh, x, options.max_newton_iterations);
  state.status = newton.status;
  state.message = newton.ok() ? "" : "the inflated dome: " + newton.message;
  state.newton_iterations = newton.iterations;
  state.unknowns = mesh.unknowns;
  if (!newton.ok()) return dome;
  const double volume = free_volume_integral(mesh, x);
  const double energy_scale = 2.0 * std::numbers::pi * problem.material.shear_modulus_mpa *
                              problem.geometry.thickness_mm * A * A;
  state.stored_energy_nmm = (newton.assembly.energy - mesh.pressure * volume) * energy_scale;
  state.volume_mm3 = -2.0 * std::numbers::pi * volume * A * A * A;
  state.gas_pressure_mpa = problem.preload.pressure_mpa;
  FePart out;
  out.part = MembranePart::Free;
  out.elements = part.elements;
  out.start_radius_mm = 0.0;
  out.end_radius_mm = A;
  for (int i = 0; i <= n; ++i) {
    out.radius_mm.push_back(value_of(part.r[i], x) * A);
    out.deflection_mm.push_back(value_of(part.z[i], x) * A);
  }
  dome.height = -value_of(part.z.front(), x);
  const auto pole = evaluate_part(out, state.order, 0.0);
  state.part_three_stretch = pole ? pole->l1 : 1.0;
  state.max_first_invariant = first_invariant(state.part_three_stretch, state.part_three_stretch);
  std::array<double, kMaxLocal> values;
  std::array<const Slot*, kMaxLocal> slots;
  for (int e = 0; e < part.elements; ++e) {
    const ElementPlace place = gather(mesh, part, e, x, values, slots);
    for (const auto& [eta, w_gauss] : gauss_points()) {
      double l1, l2, radius, weight;
      if (!stretches_at(place, values, eta, l1, l2, radius, weight)) continue;
      if (const double i1 = first_invariant(l1, l2); i1 > state.max_first_invariant) {
        state.max_first_invariant = i1;
        state.max_first_invariant_reference_radius_mm = radius * A;
      }
    }
  }
  state.parts.push_back(std::move(out));
  return dome;
}

}  // namespace puncture::fe
