// The finite elements on a smooth probe, the membrane held where it touched: a fixed material
// mesh, each node free (r, z unknown) until it reaches the profile, then held at the arclength
// where it touched, moving with the probe.  The depth at which a free node reaches the profile is
// located as an event of the continuation (TOMS 748 on the smallest gap), so the discrete history
// depends on the mesh alone, not on the depth steps (docs/model.md §15.3, "Held where it
// touched").
#include "fe/held_smooth_probe.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "fe/energy_newton.hpp"
#include "fe/inflated_dome_fe.hpp"
#include "fe/meridian_mesh.hpp"
#include "fe/part_evaluation.hpp"
#include "fe/smooth_probe.hpp"
#include "indentation/solver_scales.hpp"

namespace puncture::fe {
namespace {

// One part of the fixed material mesh: nodes equally spaced in xi, mapped to R linearly or
// logarithmically; neighbouring parts share their end node.
struct HeldPartLayout {
  MembranePart part = MembranePart::Free;
  bool logarithmic = false;
  int elements = 0;
  double start = 0.0, end = 1.0;  // reference radii (/ A)
  int first = 0;                  // global index of its first node
};

// The material mesh: the flat face (held from the first touch), the reach of the profile that
// may be held, and the free membrane to the clamp, every part linear in R: the flat membrane
// (r = L0 R) is then exact, stress-free, the start of the history (a logarithmic part stores
// ~1e-9 of rounding-level energy there, whose compressed spots made Newton stall from the flat
// state on fine meshes); the edge stays inside the held reach, where the elements are finest.
struct HeldLayout {
  int order = 2;
  std::vector<HeldPartLayout> parts;
  std::vector<double> radius;  // R of every node (/ A)
  int nodes() const { return int(radius.size()); }
};

// The state of the history at one depth: every node of the layout.
struct HeldNodes {
  // The probe's pole below the clamp plane (/ A): the depth, less the inflated dome's height
  // under a gas pressure (depths count from the dome's pole).
  double tip = 0.0;
  std::vector<double> r, z;  // current radius and deflection below the clamp plane (/ A)
  std::vector<char> held;    // on the profile, at arclength `s`, moving with the probe
  std::vector<double> s;
  double energy = 0.0, reaction = 0.0;  // as Assembly
  int newton_iterations = 0, unknowns = 0;
};

// The largest arclength a node may be held at: the end of the contact model (the cone's kink, the
// ball's equator), else the last curvature break (the cylinder side of the sphere-tipped probe and
// the fillet), beyond which the shooting's held models end too.
double held_end_arclength(const RigidProfile& profile) {
  if (std::isfinite(profile.contact_end())) return profile.contact_end();
  const std::vector<double> breaks = profile.curvature_breaks();
  return breaks.empty() ? std::numeric_limits<double>::infinity() : breaks.back();
}

HeldLayout held_layout(const RigidProfile& profile, double prestretch, const FeOptions& options) {
  HeldLayout layout;
  layout.order = options.order;
  const double face = profile.rise_start() / prestretch;  // R of the face's edge
  // The material that can reach the held end: held stretches are at least the pre-stretch (kept
  // inside the clamp, for a probe nearly as wide as the opening).
  const double reach =
      std::min(face + (held_end_arclength(profile) - profile.rise_start()) / prestretch,
               face + 0.8 * (1.0 - face));
  double start = 0.0;
  if (face > 0.0) {
    layout.parts.push_back(
        {MembranePart::Tip, false, std::max(2, options.elements / 8), 0.0, face, 0});
    start = face;
  }
  layout.parts.push_back(
      {MembranePart::Tip, false, std::max(2, options.elements / 2), start, reach, 0});
  layout.parts.push_back({MembranePart::Free, false, options.elements, reach, 1.0, 0});
  const int p = options.order;
  for (HeldPartLayout& part : layout.parts) {
    part.first = layout.radius.empty() ? 0 : layout.nodes() - 1;
    const int intervals = part.elements * p;
    for (int i = layout.radius.empty() ? 0 : 1; i <= intervals; ++i) {
      const double xi = double(i) / intervals;
      layout.radius.push_back(part.logarithmic ? part.start * std::pow(part.end / part.start, xi)
                                               : part.start + xi * (part.end - part.start));
    }
  }
  return layout;
}

// The flat membrane at its pre-stretch, the pole held and, on a flat face, the material the face
// touches at once, at its flat place (s = L0 R).
HeldNodes first_touch(const HeldLayout& layout, const RigidProfile& profile, double prestretch) {
  HeldNodes nodes;
  const int n = layout.nodes();
  nodes.r.resize(n);
  nodes.z.assign(n, 0.0);
  nodes.held.assign(n, 0);
  nodes.s.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    nodes.r[i] = prestretch * layout.radius[i];
    if (i == 0 || nodes.r[i] <= profile.rise_start() * (1.0 + 1e-12)) {
      nodes.held[i] = 1;
      nodes.s[i] = nodes.r[i];
    }
  }
  return nodes;
}

// Under a gas pressure the start: the inflated dome on the held layout, the minimum of U - p V
// with no node held, started from the elements' own dome (inflated_dome_fe.cpp, interpolated),
// then its pole held at s = 0 with the probe's pole there (depth 0).  `lift` receives the pole's
// height above the clamp plane (/ A); a dome the membrane cannot hold is `failure`'s state.
std::optional<HeldNodes> inflated_touch(const Problem& problem, const HeldLayout& layout,
                                        const RigidProfile& profile, const FeOptions& options,
                                        double& lift, FeState& failure);

// The discrete problem at depth `tip` for the held set of `nodes`: a held node at its profile
// point, its deflection moving with the depth (its reaction is part of the force); the clamp
// fixed; the pole on the axis.  `unknown_r`/`unknown_z` receive each node's unknown (-1 if none).
// Under a gas pressure every element carries its P int z r dr, the held ones too: their volume
// moves with the probe, so the held nodes' reaction is dPi/d(depth) with Pi = U - p V.
Mesh held_mesh(const HeldLayout& layout, const HeldNodes& nodes, const RigidProfile& profile,
               double tip, const Problem& problem, std::vector<int>& unknown_r,
               std::vector<int>& unknown_z) {
  const double prestretch = problem.preload.prestretch;
  Mesh mesh;
  mesh.order = layout.order;
  mesh.pressure = detail::dome_pressure(problem);
  const int n = layout.nodes();
  unknown_r.assign(n, -1);
  unknown_z.assign(n, -1);
  std::vector<Slot> r(n), z(n);
  int next = 0;
  for (int i = 0; i < n; ++i) {
    if (i == n - 1) {
      r[i] = fixed_slot(prestretch);
      z[i] = fixed_slot(0.0);
    } else if (nodes.held[i]) {
      r[i] = fixed_slot(i == 0 ? 0.0 : profile.radius(nodes.s[i]));
      z[i] = fixed_slot(tip - profile.height(nodes.s[i]), true);
    } else {
      if (i == 0) {
        r[i] = fixed_slot(0.0);
      } else {
        unknown_r[i] = next;
        r[i] = unknown_slot(next++);
      }
      unknown_z[i] = next;
      z[i] = unknown_slot(next++);
    }
  }
  for (const HeldPartLayout& part : layout.parts) {
    MeshPart mp{part.part,
                part.logarithmic,
                part.elements,
                fixed_slot(part.start),
                fixed_slot(part.end),
                {},
                {}};
    for (int i = 0; i <= part.elements * layout.order; ++i) {
      mp.r.push_back(r[part.first + i]);
      mp.z.push_back(z[part.first + i]);
    }
    mesh.parts.push_back(std::move(mp));
  }
  mesh.unknowns = next;
  return mesh;
}

// The outermost held node (the contact edge).
int edge_node(const HeldNodes& nodes) {
  int edge = 0;
  for (int i = 0; i < int(nodes.held.size()); ++i)
    if (nodes.held[i]) edge = i;
  return edge;
}

// Equilibrium at depth `tip` with the held set of `from`, started from `from` with the free
// membrane moved by the depth's change, fully at the edge and fading as ln R to the clamp.
std::optional<HeldNodes> held_equilibrium(const Problem& problem, const HeldLayout& layout,
                                          const RigidProfile& profile, const HeldNodes& from,
                                          double tip, const FeOptions& options,
                                          std::string& failure) {
  const double l0 = problem.preload.prestretch;
  std::vector<int> ur, uz;
  const Mesh mesh = held_mesh(layout, from, profile, tip, problem, ur, uz);
  Eigen::VectorXd x(mesh.unknowns);
  const double edge_radius = std::max(layout.radius[std::max(edge_node(from), 1)], 1e-12);
  for (int i = 0; i < layout.nodes(); ++i) {
    const double fade = std::clamp(std::log(layout.radius[i]) / std::log(edge_radius), 0.0, 1.0);
    if (ur[i] >= 0) x[ur[i]] = from.r[i];
    if (uz[i] >= 0) x[uz[i]] = from.z[i] + (tip - from.tip) * (i == 0 ? 1.0 : fade);
  }
  const NewtonResult newton =
      minimise_energy(problem.material.law, mesh, x, options.max_newton_iterations);
  if (!newton.ok()) {
    failure = newton.message;
    return std::nullopt;
  }
  HeldNodes out = from;
  out.tip = tip;
  for (int i = 0; i < layout.nodes(); ++i) {
    out.r[i] = ur[i] >= 0 ? x[ur[i]] : (i == layout.nodes() - 1 ? l0 : from.r[i]);
    out.z[i] = uz[i] >= 0 ? x[uz[i]] : (i == layout.nodes() - 1 ? 0.0 : from.z[i]);
    if (from.held[i]) {
      out.r[i] = i == 0 ? 0.0 : profile.radius(from.s[i]);
      out.z[i] = tip - profile.height(from.s[i]);
    }
  }
  out.energy = newton.assembly.energy;
  out.reaction = newton.assembly.reaction;
  out.newton_iterations = newton.iterations;
  out.unknowns = mesh.unknowns;
  return out;
}

std::optional<HeldNodes> inflated_touch(const Problem& problem, const HeldLayout& layout,
                                        const RigidProfile& profile, const FeOptions& options,
                                        double& lift, FeState& failure) {
  const double A = reference_clamp_radius_mm(problem), l0 = problem.preload.prestretch;
  const FeDome dome = solve_dome(problem, options);
  if (!dome.state.ok()) {
    failure = dome.state;
    return std::nullopt;
  }
  const FePart& part = dome.state.parts.front();
  const int n = layout.nodes();
  HeldNodes nodes;
  nodes.r.resize(n);
  nodes.z.resize(n);
  nodes.held.assign(n, 0);
  nodes.s.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    const auto at = evaluate_part(part, dome.state.order, std::min(layout.radius[i] * A, A));
    nodes.r[i] = i == 0 ? 0.0 : i == n - 1 ? l0 : at->radius / A;
    nodes.z[i] = i == n - 1 ? 0.0 : at->deflection / A;
  }
  std::vector<int> ur, uz;
  const Mesh mesh = held_mesh(layout, nodes, profile, 0.0, problem, ur, uz);
  Eigen::VectorXd x(mesh.unknowns);
  for (int i = 0; i < n; ++i) {
    if (ur[i] >= 0) x[ur[i]] = nodes.r[i];
    if (uz[i] >= 0) x[uz[i]] = nodes.z[i];
  }
  const NewtonResult newton =
      minimise_energy(problem.material.law, mesh, x, options.max_newton_iterations);
  if (!newton.ok()) {
    failure.status = newton.status;
    failure.message = "the inflated dome on the held mesh: " + newton.message;
    return std::nullopt;
  }
  for (int i = 0; i < n; ++i) {
    if (ur[i] >= 0) nodes.r[i] = x[ur[i]];
    if (uz[i] >= 0) nodes.z[i] = x[uz[i]];
  }
  lift = -nodes.z[0];
  nodes.tip = -lift;
  nodes.held[0] = 1;
  nodes.energy = newton.assembly.energy;
  nodes.newton_iterations = newton.iterations;
  nodes.unknowns = mesh.unknowns;
  return nodes;
}

// The smallest signed gap of a free node from the profile (< 0: inside the probe) and its node.
std::pair<double, int> smallest_gap(const HeldNodes& nodes, const RigidProfile& profile) {
  std::pair<double, int> smallest{std::numeric_limits<double>::infinity(), -1};
  for (int i = 0; i + 1 < int(nodes.r.size()); ++i)
    if (!nodes.held[i]) {
      const double g = profile.gap(nodes.r[i], nodes.tip - nodes.z[i]);
      if (g < smallest.first) smallest = {g, i};
    }
  return smallest;
}

// `lift`: the inflated dome's pole height (/ A) under a gas pressure, from which depths count.
FeState held_state(const Problem& problem, const HeldLayout& layout, const RigidProfile& profile,
                   const HeldNodes& nodes, double lift) {
  const double A = reference_clamp_radius_mm(problem), l0 = problem.preload.prestretch;
  FeState state;
  state.status = Status::Converged;
  state.contact = FeContact::Held;
  state.order = layout.order;
  state.depth_mm = (nodes.tip + lift) * A;
  state.normalized_force = nodes.reaction / l0;
  state.force_n = nodes.reaction * (force_scale_n(problem) / l0);
  state.newton_iterations = nodes.newton_iterations;
  state.unknowns = nodes.unknowns;
  const int edge = edge_node(nodes);
  state.corner_reference_radius_mm = layout.radius[edge] * A;
  state.part_two_top_reference_radius_mm = state.corner_reference_radius_mm;
  state.contact_edge_radius_mm = nodes.r[edge] * A;
  state.largest_penetration_mm = std::max(0.0, -smallest_gap(nodes, profile).first * A);
  std::vector<int> ur, uz;
  const Mesh mesh = held_mesh(layout, nodes, profile, nodes.tip, problem, ur, uz);
  Eigen::VectorXd x(mesh.unknowns);
  for (int i = 0; i < layout.nodes(); ++i) {
    if (ur[i] >= 0) x[ur[i]] = nodes.r[i];
    if (uz[i] >= 0) x[uz[i]] = nodes.z[i];
  }
  // The energy minimised is U - p V: U is it less the P int z r dr of every element.
  double energy = nodes.energy;
  if (mesh.pressure != 0.0) {
    const double volume = free_volume_integral(mesh, x);
    energy -= mesh.pressure * volume;
    state.volume_mm3 = -2.0 * std::numbers::pi * volume * A * A * A;
    state.gas_pressure_mpa = problem.preload.pressure_mpa;
  }
  state.stored_energy_nmm = energy * 2.0 * std::numbers::pi * problem.material.shear_modulus_mpa *
                            problem.geometry.thickness_mm * A * A;
  for (std::size_t k = 0; k < layout.parts.size(); ++k) {
    const HeldPartLayout& part = layout.parts[k];
    FePart out;
    out.part = part.part;
    out.logarithmic = part.logarithmic;
    out.elements = part.elements;
    out.start_radius_mm = part.start * A;
    out.end_radius_mm = part.end * A;
    for (int i = 0; i <= part.elements * layout.order; ++i) {
      out.radius_mm.push_back(nodes.r[part.first + i] * A);
      out.deflection_mm.push_back(nodes.z[part.first + i] * A);
    }
    raise_largest_first_invariant(mesh,
                                  mesh.parts[k],
                                  x,
                                  A,
                                  state.max_first_invariant,
                                  state.max_first_invariant_reference_radius_mm);
    state.parts.push_back(std::move(out));
  }
  const auto pole = evaluate_part(state.parts.front(), layout.order, 0.0);
  state.part_three_stretch = pole ? pole->l1 : l0;
  const double pole_i1 = first_invariant(state.part_three_stretch, state.part_three_stretch);
  if (pole_i1 >= state.max_first_invariant) {
    state.max_first_invariant = pole_i1;
    state.max_first_invariant_reference_radius_mm = 0.0;
  }
  return state;
}

// A node reached the profile past where the held models end: the status and its words.
struct HeldEndReached {
  Status status;
  std::string message;
};

// A convex kink where the contact must end (the cone's shank).
bool kink_at_end(const RigidProfile& profile) {
  const double end = profile.contact_end();
  return std::isfinite(end) && std::abs(profile.radius_slope(std::nextafter(end, 0.0)) -
                                        profile.radius_slope(end * (1.0 + 1e-9))) > 1e-6;
}

// The held membrane pivoting over such a kink keeps its nodes outside the probe while the kink
// pokes through the element between them: the membrane then crosses the kink's radius above the
// kink (inside the probe), where before the end it leaves the cone tangentially and crosses that
// radius below it, outside.  (The nodes' polyline: linear between them.)
bool crosses_kink_at_end(const HeldNodes& nodes, const RigidProfile& profile) {
  if (!kink_at_end(profile)) return false;
  const double end = profile.contact_end();
  const double kink_r = profile.radius(std::nextafter(end, 0.0)), kink_y = profile.height(end);
  for (std::size_t i = 0; i + 1 < nodes.r.size(); ++i)
    if (nodes.r[i] < kink_r && nodes.r[i + 1] >= kink_r) {
      const double w = (kink_r - nodes.r[i]) / (nodes.r[i + 1] - nodes.r[i]);
      const double y = nodes.tip - (nodes.z[i] + w * (nodes.z[i + 1] - nodes.z[i]));
      return y > kink_y * (1.0 + 1e-9);
    }
  return false;
}

// One continuation step from `current` towards depth `tip`: either the state there, no free node
// having reached the profile, or the state at the first depth where one reaches it (the smallest
// gap's root, TOMS 748 to ~1e-13 of the depth), that node then held at its profile point and the
// equilibrium solved again with it.  Throws std::runtime_error when an equilibrium fails and
// HeldEndReached past the held models' end.
HeldNodes held_step(const Problem& problem, const HeldLayout& layout, const RigidProfile& profile,
                    const HeldNodes& current, double tip, const FeOptions& options) {
  std::string failure;
  auto solve = [&](double depth) {
    std::optional<HeldNodes> next =
        held_equilibrium(problem, layout, profile, current, depth, options, failure);
    if (!next) throw std::runtime_error(failure);
    return *next;
  };
  const double gap_before = smallest_gap(current, profile).first;
  HeldNodes touched = current;  // a node on the profile already (within rounding)
  if (gap_before > 0.0) {
    HeldNodes trial = solve(tip);
    const double gap_after = smallest_gap(trial, profile).first;
    if (gap_after >= 0.0) {
      if (crosses_kink_at_end(trial, profile))
        throw HeldEndReached{Status::OutsideModel,
                             "held where it touched, " + profile.beyond_contact_end()};
      return trial;
    }
    auto gap_at = [&](double depth) { return smallest_gap(solve(depth), profile).first; };
    boost::uintmax_t iterations = 60;
    const auto root =
        boost::math::tools::toms748_solve(gap_at,
                                          current.tip,
                                          tip,
                                          gap_before,
                                          gap_after,
                                          boost::math::tools::eps_tolerance<double>(44),
                                          iterations);
    touched = solve(root.second);  // the side where the node has just reached it
  }
  const double end = held_end_arclength(profile);
  // The node that reached the profile, and any other within rounding of it, held where it is.
  for (int pass = 0; pass < 4; ++pass) {
    const auto [gap, node] = smallest_gap(touched, profile);
    if (node < 0 || (pass > 0 && gap >= 0.0)) break;
    const double s = profile.closest_arclength(touched.r[node], touched.tip - touched.z[node]);
    // Near the held models' end the held stretch grows steeply (the last 2 % of the held material
    // covers the last third of the sphere's arc), so the node after the material that ends at
    // the end may touch just past a smooth end (an equator): one node is held there (the discrete
    // edge within a node of the end, as everywhere), the next one ends the history.  Past a kink
    // (the cone's shank) the first one does.
    const bool past_end = s > end * (1.0 + 1e-12);
    const bool one_past_already =
        std::any_of(touched.s.begin(), touched.s.end(), [&](double held_at) {
          return held_at > end * (1.0 + 1e-12);
        });
    if (past_end && (one_past_already || kink_at_end(profile))) {
      if (std::isfinite(profile.contact_end()))
        throw HeldEndReached{Status::OutsideModel,
                             "held where it touched, " + profile.beyond_contact_end()};
      throw HeldEndReached{
          Status::StickWrapsSide,
          "the held membrane would wrap the probe's cylinder side (outside the stick model)"};
    }
    touched.held[node] = 1;
    touched.s[node] = s;
    std::optional<HeldNodes> settled =
        held_equilibrium(problem, layout, profile, touched, touched.tip, options, failure);
    if (!settled) throw std::runtime_error(failure);
    touched = *settled;
  }
  if (crosses_kink_at_end(touched, profile))
    throw HeldEndReached{Status::OutsideModel,
                         "held where it touched, " + profile.beyond_contact_end()};
  return touched;
}

}  // namespace

std::vector<FeState> solve_held_smooth_probe(const Problem& problem, const RigidProfile& profile,
                                             const std::vector<double>& depths_mm,
                                             const FeOptions& options) {
  const double A = reference_clamp_radius_mm(problem), l0 = problem.preload.prestretch;
  const HeldLayout layout = held_layout(profile, l0, options);
  std::vector<FeState> states;
  double lift = 0.0;  // under a gas pressure the dome's pole height: depths count from it
  HeldNodes current;
  if (problem.preload.pressure_mpa > 0.0) {
    FeState failure;
    std::optional<HeldNodes> dome =
        inflated_touch(problem, layout, profile, options, lift, failure);
    if (!dome) {
      fill_unreached_depths(states, depths_mm, FeContact::Held, failure.status, failure.message);
      return states;
    }
    current = std::move(*dome);
  } else {
    current = first_touch(layout, profile, l0);
  }
  // The first step: a few times the depth at which the probe would reach the first free node of
  // the flat membrane or the dome (on a fine mesh a larger one has the pole alone push the flat
  // membrane into a cone steep enough to lock); the steps double from there.
  double step = options.max_depth_step;
  for (int i = 0; i < layout.nodes(); ++i)
    if (!current.held[i]) {
      const double touch = profile.height(profile.closest_arclength(current.r[i], 0.0)) -
                           (current.tip - current.z[i]);
      step = std::min(step, std::max(4.0 * touch, 1e-9));
      break;
    }
  for (double target_mm : depths_mm) {
    const double target = target_mm / A - lift;
    int halvings = 0;
    std::string failure;
    Status failure_status = FeState{}.status;
    while (current.tip < target && failure.empty()) {
      double tip = std::min(target, current.tip + step);
      if (target - tip < 1e-3 * step) tip = target;  // no sliver of a last step
      try {
        current = held_step(problem, layout, profile, current, tip, options);
        step = std::min(2.0 * step, options.max_depth_step);
        halvings = 0;
      } catch (const HeldEndReached& end) {
        failure = fmt::format("beyond depth {:.6g} mm {}", (current.tip + lift) * A, end.message);
        failure_status = end.status;
      } catch (const std::runtime_error& e) {
        if (++halvings > options.max_step_halvings) {
          failure = fmt::format("no equilibrium found beyond depth {:.6g} mm: {}",
                                (current.tip + lift) * A,
                                e.what());
        } else {
          step *= 0.5;
        }
      }
    }
    if (!failure.empty()) {
      fill_unreached_depths(states, depths_mm, FeContact::Held, failure_status, failure);
      return states;
    }
    states.push_back(held_state(problem, layout, profile, current, lift));
  }
  return states;
}

}  // namespace puncture::fe
