// The finite elements on a smooth probe: the mesh for a contact edge at a given place on the
// profile, the search for the edge at each depth, and the continuation in depth.
#include "fe/smooth_probe.hpp"

#include <fmt/format.h>

#include <algorithm>
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
#include "indentation/solver_scales.hpp"

namespace puncture::fe {
namespace {

// Normalised by the stress-free clamp radius A / L0, like the profile.
struct Scaled {
  double depth = 0.0;     // indentation depth of the pole
  double clamp = 1.0;     // current clamp radius: the pre-stretch L0
  double lift = 0.0;      // under a gas pressure, the inflated dome's height: depths count from it
  double pressure = 0.0;  // P = p (A / L0) / (G H)
  // The probe's pole as a deflection below the clamp plane.
  double tip() const { return depth - lift; }
};

// A contact segment shorter than this fraction of the edge's arclength is merged into the one
// before: a curvature jump that close to an element's end changes the energy by far less than
// the elements' error.
constexpr double kShortestSegment = 1e-6;

// A node of the free part may lie inside the probe by this much (/ A) at a requested depth
// before the state is refused.  The edge is placed where the free part leaves the profile
// tangentially, to the root's tolerance (a departure angle ~1e-13): nodes measured at most
// 1e-15 mm inside on the paper's membrane, 16 to 128 elements.  A continuation step on the way
// is not checked: it is only the next step's start.
constexpr double kPenetrationTolerance = 1e-10;

// The arclengths where the contact's segments end for an edge at arclength `edge`: the profile's
// curvature breaks before it, then the edge.
std::vector<double> segment_ends(const RigidProfile& profile, double edge) {
  std::vector<double> ends;
  for (double b : profile.curvature_breaks())
    if (b < edge * (1.0 - kShortestSegment)) ends.push_back(b);
  ends.push_back(edge);
  return ends;
}

// The mesh with the membrane on the profile from the pole to the arclength `edge`, then free to
// the clamp.  Unknowns: the arclength at the inner nodes of each contact segment, the reference
// radius at each segment's end (which material sits at a break or at the edge: frictionless),
// and r, z at the inner nodes of the free part, whose first node is the edge's point, at the
// depth less the profile's height there (its reaction is the force).
Mesh build_mesh(const RigidProfile& profile, const Scaled& s, double edge,
                const FeOptions& options) {
  Mesh mesh;
  mesh.order = options.order;
  mesh.pressure = s.pressure;
  const int p = options.order;
  const int n_free = options.elements, n_contact = std::max(2, options.elements / 4);
  int next = 0;
  Slot start_radius = fixed_slot(0.0);
  double start_arclength = 0.0;
  const std::vector<double> ends = segment_ends(profile, edge);
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const Slot end_radius = unknown_slot(next++);
    MeshPart part{profile.segment_part(int(k)), false, n_contact, start_radius, end_radius, {}, {}};
    part.profile = &profile;
    for (int i = 0; i <= n_contact * p; ++i) {
      part.r.push_back(i == 0               ? fixed_slot(start_arclength)
                       : i == n_contact * p ? fixed_slot(ends[k])
                                            : unknown_slot(next++));
      part.z.push_back(fixed_slot(0.0));  // unused on the profile
    }
    mesh.parts.push_back(part);
    start_radius = end_radius;
    start_arclength = ends[k];
  }
  MeshPart free_part{MembranePart::Free, true, n_free, start_radius, fixed_slot(1.0), {}, {}};
  for (int i = 0; i <= n_free * p; ++i) {
    const bool first = i == 0, last = i == n_free * p;
    free_part.r.push_back(first  ? fixed_slot(profile.radius(edge))
                          : last ? fixed_slot(s.clamp)
                                 : unknown_slot(next++));
    free_part.z.push_back(first  ? fixed_slot(s.tip() - profile.height(edge), true)
                          : last ? fixed_slot(0.0)
                                 : unknown_slot(next++));
  }
  mesh.parts.push_back(free_part);
  mesh.unknowns = next;
  return mesh;
}

double node_radius(bool logarithmic, int intervals, int i, double start, double end) {
  const double xi = double(i) / intervals;
  return logarithmic ? start * std::pow(end / start, xi) : start + xi * (end - start);
}

// The fields of a previous state at reference radius R (normalised), in whichever part holds it.
std::optional<PointFields> point_of(const FeState& state, double R, double A) {
  for (const FePart& part : state.parts)
    if (auto f = evaluate_part(part, state.order, R * A)) return f;
  return std::nullopt;
}

// The arclength along the profile of a previous state's point: its own on the contact, else the
// closest profile point's.
double arclength_of(const PointFields& f, const RigidProfile& profile, double depth, double A) {
  return f.arclength >= 0.0 ? f.arclength / A
                            : profile.closest_arclength(f.radius / A, depth - f.deflection / A);
}

// The reference radius (normalised) of the material a previous state carries to arclength
// `target` on the profile: interpolated between its nodes, contact and free; empty when its
// membrane does not reach it.
std::optional<double> radius_at_arclength(const FeState& state, const RigidProfile& profile,
                                          double target, double A, double lift) {
  const double depth = state.depth_mm / A - lift;  // the probe's pole below the clamp plane
  double r_prev = 0.0, s_prev = 0.0;
  for (const FePart& part : state.parts)
    for (std::size_t i = 0; i < part.radius_mm.size(); ++i) {
      const double R = node_radius(part.logarithmic,
                                   part.elements * state.order,
                                   int(i),
                                   part.start_radius_mm / A,
                                   part.end_radius_mm / A);
      const double s =
          part.arclength_mm.empty()
              ? profile.closest_arclength(part.radius_mm[i] / A, depth - part.deflection_mm[i] / A)
              : part.arclength_mm[i] / A;
      if (s >= target && R > r_prev)
        return s > s_prev ? r_prev + (R - r_prev) * (target - s_prev) / (s - s_prev) : R;
      r_prev = R;
      s_prev = s;
    }
  return std::nullopt;
}

// The arclength of a state's contact edge [mm]: the end of its last part on the profile.
double edge_arclength_mm(const FeState& state) {
  double edge = 0.0;
  for (const FePart& part : state.parts)
    if (!part.arclength_mm.empty()) edge = part.arclength_mm.back();
  return edge;
}

// Starting values for `mesh` (edge at `edge`): from a previous state, material point by material
// point (on the contact its arclength if they keep their order, else evenly spaced; off it its
// position plus the move that puts the free part's first node on the new edge, fading as ln R
// to the clamp), else the flat membrane with a cone in ln R off an unstretched cap.
Eigen::VectorXd starting_guess(const Mesh& mesh, const RigidProfile& profile, const Scaled& s,
                               double edge, const FeState* previous, double A) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(mesh.unknowns);
  const double old_depth = previous ? previous->depth_mm / A - s.lift : 0.0;  // the old tip
  const double edge_r = profile.radius(edge), edge_z = s.tip() - profile.height(edge);
  // The segments' end radii first: the parts' maps depend on them.
  double last_end = 0.0;
  for (const MeshPart& part : mesh.parts) {
    if (!part.profile) break;
    const double target = part.r.back().value;
    std::optional<double> R =
        previous ? radius_at_arclength(*previous, profile, target, A, s.lift) : std::nullopt;
    double guess = R ? *R : target / s.clamp;
    if (!R && previous)  // beyond the previous membrane's reach: stretch its material map
      guess = previous->part_two_top_reference_radius_mm * target / edge_arclength_mm(*previous);
    guess = std::clamp(guess, last_end + 1e-9, 0.999);
    x[part.end.index] = guess;
    last_end = guess;
  }
  double shift_r = 0.0, shift_z = 0.0;  // the previous state's point at the edge to the edge
  for (const MeshPart& part : mesh.parts) {
    const double start = value_of(part.start, x), end = value_of(part.end, x);
    const int intervals = part.elements * mesh.order;
    double s_prev = part.r.front().value;
    bool monotone = true;  // the previous arclengths keep the order of the nodes
    if (!part.profile && previous)
      if (const auto old = point_of(*previous, start, A)) {
        shift_r = edge_r - old->radius / A;
        shift_z = edge_z - old->deflection / A;
      }
    for (int i = 0; i <= intervals; ++i) {
      const double R = node_radius(part.logarithmic, intervals, i, start, end);
      const std::optional<PointFields> old = previous ? point_of(*previous, R, A) : std::nullopt;
      if (part.profile) {
        if (part.r[i].index < 0) continue;
        const double arclength = old ? arclength_of(*old, profile, old_depth, A) : -1.0;
        x[part.r[i].index] = arclength;
        monotone = monotone && arclength > s_prev && arclength < part.r.back().value;
        s_prev = arclength;
        continue;
      }
      const double fade = std::log(R) / std::log(start);  // 1 at the edge, 0 at the clamp
      double r = R * s.clamp, z = edge_z * fade;
      if (old) {
        r = old->radius / A + shift_r * fade;
        z = old->deflection / A + shift_z * fade;
      }
      if (part.r[i].index >= 0) x[part.r[i].index] = r;
      // (Without pressure the free part stays above the probe's edge; an inflated one may lie
      // on either side of it.)
      if (part.z[i].index >= 0) x[part.z[i].index] = s.pressure > 0.0 ? z : std::min(z, edge_z);
    }
    if (part.profile && !monotone)  // else evenly spaced in arclength
      for (int i = 1; i < intervals; ++i)
        x[part.r[i].index] = part.r.front().value +
                             (part.r.back().value - part.r.front().value) * double(i) / intervals;
  }
  return x;
}

// The integral of z r dr over the membrane on the profile (lengths / A), z = tip - height(s) and
// r = rho(s) along each element's interpolated arclength: the elements' Gauss rule, accurate to
// the smooth integrand's order h^10.
double contact_volume_integral(const Mesh& mesh, const Eigen::VectorXd& x,
                               const RigidProfile& profile, double tip) {
  double sum = 0.0;
  std::array<double, kMaxOrder + 1> n{}, dn{};
  for (const MeshPart& part : mesh.parts) {
    if (!part.profile) continue;
    for (int e = 0; e < part.elements; ++e)
      for (const auto& [eta, w_gauss] : gauss_points()) {
        shape_functions(mesh.order, eta, n, dn);
        double arclength = 0.0, d_arclength = 0.0;
        for (int i = 0; i <= mesh.order; ++i) {
          const double node = value_of(part.r[e * mesh.order + i], x);
          arclength += n[i] * node;
          d_arclength += dn[i] * node;
        }
        sum += (tip - profile.height(arclength)) * profile.radius(arclength) *
               profile.radius_slope(arclength) * d_arclength * w_gauss;
      }
  }
  return sum;
}

// The converged state in physical units.
FeState make_state(const Problem& problem, const RigidProfile& profile, const Mesh& mesh,
                   const Eigen::VectorXd& x, const Assembly& assembly, const Scaled& s) {
  const double A = reference_clamp_radius_mm(problem);
  FeState state;
  state.contact = FeContact::Frictionless;
  state.order = mesh.order;
  state.depth_mm = s.depth * A;
  double reaction = assembly.reaction, energy = assembly.energy;
  if (s.pressure != 0.0) {
    // The gas on the contact, whose volume moves with the probe: d(P int z r dr)/d(depth) is
    // P rho(edge)^2 / 2 (on a flat face alone the whole force, p pi c^2).  U is the energy less
    // the free part's P int z r dr.
    const double edge_radius = value_of(mesh.parts.back().r.front(), x);
    reaction += 0.5 * s.pressure * edge_radius * edge_radius;
    const double free_volume = free_volume_integral(mesh, x);
    energy -= s.pressure * free_volume;
    state.gas_pressure_mpa = problem.preload.pressure_mpa;
    state.volume_mm3 = -2.0 * std::numbers::pi *
                       (free_volume + contact_volume_integral(mesh, x, profile, s.tip())) * A * A *
                       A;
  }
  state.normalized_force = reaction / s.clamp;
  state.force_n = reaction * (force_scale_n(problem) / s.clamp);
  state.stored_energy_nmm = energy * 2.0 * std::numbers::pi * problem.material.shear_modulus_mpa *
                            problem.geometry.thickness_mm * A * A;
  state.unknowns = mesh.unknowns;
  int segments = 0;
  for (const MeshPart& part : mesh.parts) {
    FePart out;
    out.part = part.part;
    out.logarithmic = part.logarithmic;
    out.elements = part.elements;
    out.start_radius_mm = value_of(part.start, x) * A;
    out.end_radius_mm = value_of(part.end, x) * A;
    for (std::size_t i = 0; i < part.r.size(); ++i) {
      const double r = value_of(part.r[i], x), z = value_of(part.z[i], x);
      if (part.profile) {
        out.arclength_mm.push_back(r * A);
        out.radius_mm.push_back(profile.radius(r) * A);
        out.deflection_mm.push_back((s.tip() - profile.height(r)) * A);
      } else {
        out.radius_mm.push_back(r * A);
        out.deflection_mm.push_back(z * A);
        const double inside = -profile.gap(r, s.tip() - z) * A;
        state.largest_penetration_mm = std::max(state.largest_penetration_mm, inside);
      }
    }
    if (part.profile) {
      if (segments == 0) state.corner_reference_radius_mm = out.end_radius_mm;
      ++segments;
    } else {
      state.part_two_top_reference_radius_mm = out.start_radius_mm;
      state.contact_edge_radius_mm = out.radius_mm.front();
    }
    // Largest I1 at the quadrature points and at both ends of every element (the pole, R = 0,
    // below).
    raise_largest_first_invariant(
        mesh, part, x, A, state.max_first_invariant, state.max_first_invariant_reference_radius_mm);
    state.parts.push_back(std::move(out));
  }
  state.part_two = std::any_of(mesh.parts.begin(), mesh.parts.end(), [](const MeshPart& p) {
    return p.profile && p.part == MembranePart::Side;
  });
  // The pole's equibiaxial stretch, ds/dR at R = 0.
  const FePart& cap = state.parts.front();
  const auto pole = evaluate_part(cap, mesh.order, 0.0);
  state.part_three_stretch = pole ? pole->l1 : 1.0;
  const double pole_i1 = first_invariant(state.part_three_stretch, state.part_three_stretch);
  if (pole_i1 >= state.max_first_invariant) {
    state.max_first_invariant = pole_i1;
    state.max_first_invariant_reference_radius_mm = 0.0;
  }
  return state;
}

struct StepResult : Outcome {
  FeState state;
  double edge = 0.0;  // arclength of the contact edge (normalised)
};

// The direction in which the free part leaves the edge against the profile's outward normal
// there (the sine of the angle between the free part and the profile's tangent): < 0 when it
// enters the probe (the edge is too close to the pole), > 0 when it kinks outward (too far).
double departure_angle(const FeState& state, const RigidProfile& profile, double edge) {
  // (`edge` picks the profile's normal: just before a kink for the piece that ends there.)
  const FePart& free_part = state.parts.back();
  std::array<double, kMaxOrder + 1> n{}, dn{};
  shape_functions(state.order, -1.0, n, dn);
  double dr = 0.0, dz = 0.0;
  for (int i = 0; i <= state.order; ++i) {
    dr += dn[i] * free_part.radius_mm[i];
    dz += dn[i] * free_part.deflection_mm[i];
  }
  double nr, ny;
  outward_normal(profile, edge, nr, ny);
  return (nr * dr - ny * dz) / std::hypot(dr, dz);  // the height rises as z falls
}

// Minimises the energy with the contact edge at arclength `edge`, from `start` (or the flat
// membrane).
StepResult solve_at_edge(const Problem& problem, const RigidProfile& profile, const Scaled& s,
                         double edge, const FeState* start, const FeOptions& options) {
  const Mesh mesh = build_mesh(profile, s, edge, options);
  Eigen::VectorXd x =
      starting_guess(mesh, profile, s, edge, start, reference_clamp_radius_mm(problem));
  // Under pressure a contact segment that the previous state did not reach (the side, as the
  // flat punch's membrane starts to wrap it) may get arclengths bunched where its material
  // arrives: an element folds.  Evenly spaced arclengths start it instead.
  if (s.pressure > 0.0 && !std::isfinite(total_energy(problem.material.law, mesh, x)))
    for (const MeshPart& part : mesh.parts) {
      if (!part.profile) continue;
      const int intervals = part.elements * mesh.order;
      for (int i = 1; i < intervals; ++i)
        x[part.r[i].index] = part.r.front().value +
                             (part.r.back().value - part.r.front().value) * double(i) / intervals;
    }
  const NewtonResult newton =
      minimise_energy(problem.material.law, mesh, x, options.max_newton_iterations);
  StepResult step;
  step.status = newton.status;
  step.message = newton.message;
  step.edge = edge;
  if (newton.ok()) {
    step.state = make_state(problem, profile, mesh, x, newton.assembly, s);
    step.state.newton_iterations = newton.iterations;
    step.state.status = Status::Converged;
  }
  return step;
}

// Thrown when a contact edge past the profile's contact_end() would be needed.
struct BeyondContactEnd {};

// The state at depth s.depth, its contact edge found by the method.  With the edge prescribed,
// the energy's minimum over everything else, E(edge), is not minimal at the true edge: the free
// part may enter the probe, so E falls as the edge moves towards the pole, and dE/d(edge)
// vanishes there without changing sign (as for the flat punch's wrapped side,
// docs/verification.md).  The free part leaves the profile tangentially there instead: it enters
// the probe (departure_angle < 0) for an edge closer to the pole and kinks outward (> 0) beyond,
// which brackets the edge, and TOMS 748 finds the tangency.  Since dE/d(edge) = d2E/d(edge)2 = 0
// there at every depth, the force dE/d(depth) is stationary in the edge's place, so the
// tangency's own discretisation error enters the force only squared: it converges at the
// elements' full order (h^4, docs/model.md).
StepResult solve_step(const Problem& problem, const RigidProfile& profile, const Scaled& s,
                      const FeState* previous, double previous_edge, const FeOptions& options,
                      bool precise) {
  std::optional<FeState> latest;  // the latest state at this depth starts the next
  StepResult last;
  const double end = profile.contact_end(), before_end = std::nextafter(end, 0.0);
  // The edge moves in steps relative to where the profile starts to rise (past a flat face: its
  // steps from the pole would cross a small fillet at once).
  // On an inflated dome the contact grows from the pole, on a flat face too.
  const double base = s.pressure > 0.0 ? 0.0 : profile.rise_start();
  auto angle_at = [&](double edge) {
    // (Under pressure the edge may lie above the clamp plane: then it must stay inside the clamp.)
    if (!(edge > 0.0) ||
        !(s.pressure > 0.0 ? profile.radius(edge) < s.clamp : profile.height(edge) < s.depth))
      throw std::runtime_error("the contact edge would reach the clamp plane");
    if (edge > end) throw BeyondContactEnd{};
    last = solve_at_edge(problem, profile, s, edge, latest ? &*latest : previous, options);
    if (!last.ok()) throw std::runtime_error(last.message);
    latest = last.state;
    // At the contact's end, against the profile before it (the cone, not its shank).
    return departure_angle(last.state, profile, std::min(edge, before_end));
  };
  // The free part would enter the profile before its end even with the edge there: at a convex
  // kink (the cone's shank) the membrane leaves the kink at an angle between the two pieces, the
  // edge pinned there, while it stays out of the piece after it; else the contact passes the end.
  auto pinned_at_end = [&] {
    if (last.edge != end) angle_at(end);
    if (departure_angle(last.state, profile, end) < 0.0) throw BeyondContactEnd{};
    return last;
  };
  try {
    const double angle = angle_at(std::min(previous_edge, end));
    if (!precise) {
      // A continuation step on the way: one secant step towards the tangency starts the next
      // step well; the requested depths are solved precisely.
      const double other = angle < 0.0 ? std::min(base + 1.05 * (previous_edge - base), end)
                                       : base + (previous_edge - base) / 1.05;
      const double angle_other = angle_at(other);
      if (angle_other != angle) {
        const double secant = other - angle_other * (other - previous_edge) / (angle_other - angle);
        if (secant - base > 0.5 * (std::min(previous_edge, other) - base) &&
            secant - base < 2.0 * (std::max(previous_edge, other) - base) && secant <= end) {
          angle_at(secant);
          return last;
        }
      }
    }
    // Bracket the tangency by steps small enough for each solution to start the next.
    double lo = previous_edge, hi = previous_edge, angle_lo = angle, angle_hi = angle;
    constexpr double factor = 1.25;
    for (int k = 0; k < 200 && (angle_lo >= 0.0 || angle_hi <= 0.0); ++k) {
      if (angle_hi <= 0.0) {
        if (hi >= end) return pinned_at_end();
        lo = hi, angle_lo = angle_hi;
        hi = std::min(base + (hi - base) * factor, end);
        angle_hi = angle_at(hi);
      } else {
        hi = lo, angle_hi = angle_lo;
        lo = base + (lo - base) / factor;
        angle_lo = angle_at(lo);
      }
    }
    if (!(angle_lo < 0.0 && angle_hi > 0.0)) {
      StepResult none;
      none.message = "no contact edge where the membrane leaves the probe tangentially";
      return none;
    }
    // The tangency, to a few ulps of the edge's arclength.
    boost::uintmax_t root_iterations = 100;
    const auto tangency =
        boost::math::tools::toms748_solve(angle_at,
                                          lo,
                                          hi,
                                          angle_lo,
                                          angle_hi,
                                          boost::math::tools::eps_tolerance<double>(40),
                                          root_iterations);
    angle_at(0.5 * (tangency.first + tangency.second));
  } catch (const std::runtime_error& e) {
    StepResult failed;
    failed.message = e.what();
    return failed;
  } catch (const BeyondContactEnd&) {
    StepResult outside;
    outside.status = Status::OutsideModel;
    outside.message = profile.beyond_contact_end();
    return outside;
  }
  return last;
}

// A first guess of the contact edge on the flat membrane's first step: where the profile rises
// a quarter of the depth above the pole.
double first_edge_guess(const RigidProfile& profile, double depth) {
  double lo = 0.0, hi = 1e-3;
  for (int k = 0; k < 200 && profile.height(hi) < 0.25 * depth; ++k) lo = hi, hi *= 2.0;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (profile.height(mid) < 0.25 * depth ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// A first guess of the contact edge on the inflated dome's first step: the profile at the depth
// meets the undeformed dome (its drop below the pole at the profile's radius plus the profile's
// height reaches the depth) at an arclength s; a contact spreads over about s / sqrt(2) (Hertz:
// a^2 = R delta against the overlap's 2 R delta).
double dome_edge_guess(const RigidProfile& profile, const FeState& dome, const Scaled& s,
                       double A) {
  const FePart& part = dome.parts.front();
  auto drop = [&](double r) {  // below the pole, linear between the dome's nodes
    const auto& rs = part.radius_mm;
    const std::size_t k = std::min<std::size_t>(
        std::upper_bound(rs.begin(), rs.end(), r * A) - rs.begin(), rs.size() - 1);
    const std::size_t j = k == 0 ? 0 : k - 1;
    const double w = rs[k] > rs[j] ? (r * A - rs[j]) / (rs[k] - rs[j]) : 0.0;
    return (part.deflection_mm[j] + w * (part.deflection_mm[k] - part.deflection_mm[j]) -
            part.deflection_mm.front()) /
           A;
  };
  auto overlap = [&](double arclength) {
    return profile.height(arclength) + drop(profile.radius(arclength)) - s.depth;
  };
  double lo = 0.0, hi = 1e-3;
  for (int k = 0; k < 200 && overlap(hi) < 0.0 && profile.radius(2.0 * hi) < 0.9 * s.clamp; ++k)
    lo = hi, hi *= 2.0;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (overlap(mid) < 0.0 ? lo : hi) = mid;
  }
  return std::min(0.5 * (lo + hi) / std::sqrt(2.0), profile.contact_end());
}

}  // namespace

std::vector<FeState> solve_smooth_probe(const Problem& problem, const RigidProfile& profile,
                                        const std::vector<double>& depths_mm,
                                        const FeOptions& options) {
  const double A = reference_clamp_radius_mm(problem);
  Scaled s;
  s.clamp = problem.preload.prestretch;
  std::vector<FeState> states;
  std::optional<FeState> previous;
  std::optional<FeState> dome;  // under a gas pressure, the start: depths count from its pole
  if (problem.preload.pressure_mpa > 0.0) {
    FeDome inflated = solve_dome(problem, options);
    if (!inflated.state.ok()) {
      for (double d : depths_mm) {
        FeState failed = inflated.state;
        failed.parts.clear();
        failed.depth_mm = d;
        states.push_back(failed);
      }
      return states;
    }
    s.lift = inflated.height;
    s.pressure = detail::dome_pressure(problem);
    dome = inflated.state;
    previous = inflated.state;
  }
  double depth = 0.0, step = options.max_depth_step, edge = 0.0;
  for (double target_mm : depths_mm) {
    const double target = target_mm / A;
    int halvings = 0;
    std::string failure;
    Status failure_status = FeState{}.status;
    while (depth < target && failure.empty()) {
      s.depth = std::min(target, depth + step);
      if (target - s.depth < 1e-3 * step) s.depth = target;  // no sliver of a last step
      const double start_edge = previous && edge > 0.0 ? edge
                                : dome                 ? dome_edge_guess(profile, *dome, s, A)
                                                       : first_edge_guess(profile, s.depth);
      StepResult result = solve_step(problem,
                                     profile,
                                     s,
                                     previous ? &*previous : nullptr,
                                     start_edge,
                                     options,
                                     s.depth == target);
      if (result.ok() && s.depth == target &&
          result.state.largest_penetration_mm > kPenetrationTolerance * A) {
        result.status = Status::NoConvergence;
        result.message = fmt::format(
            "the free membrane enters the probe by {:.3g} mm (too few elements for this state?)",
            result.state.largest_penetration_mm);
      }
      if (result.ok()) {
        depth = s.depth;
        edge = result.edge;
        previous = std::move(result.state);
        step = std::min(2.0 * step, options.max_depth_step);
      } else if (result.status == Status::OutsideModel) {
        // Past the profile's end at this depth: no smaller step changes that.
        failure = fmt::format("beyond depth {:.6g} mm {}", depth * A, result.message);
        failure_status = Status::OutsideModel;
      } else if (++halvings > options.max_step_halvings) {
        failure = fmt::format(
            "no equilibrium found beyond depth {:.6g} mm: {}", depth * A, result.message);
        const double lock = locking_first_invariant(problem.material.law);
        if (previous && std::isfinite(lock))
          failure += fmt::format(" (largest I1 there {:.4g}; the material locks at {:.4g})",
                                 previous->max_first_invariant,
                                 lock);
      } else {
        step *= 0.5;
      }
    }
    if (!failure.empty()) {
      fill_unreached_depths(states, depths_mm, FeContact::Frictionless, failure_status, failure);
      return states;
    }
    states.push_back(*previous);
  }
  return states;
}

}  // namespace puncture::fe
