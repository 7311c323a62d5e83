// The finite-element solver: contact configurations, starting guesses, and the continuation in
// depth that carries the solution from the flat membrane to the requested depths.
#include "puncture/finite_element.hpp"

#include <fmt/format.h>

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fe/energy_newton.hpp"
#include "fe/held_smooth_probe.hpp"
#include "fe/inflated_dome_fe.hpp"
#include "fe/meridian_mesh.hpp"
#include "fe/part_evaluation.hpp"
#include "fe/probe_profiles.hpp"
#include "fe/rigid_profile.hpp"
#include "fe/sealed_chamber_fe.hpp"
#include "fe/smooth_probe.hpp"

namespace puncture {
namespace {

using fe::fixed_slot;
using fe::Mesh;
using fe::MeshPart;
using fe::Slot;
using fe::unknown_slot;

enum class Layout {
  Held,             // Part I from the indenter's edge, R = a
  SlipWithoutSide,  // Part III under the tip, then Part I from the corner
  SlipWithSide,     // Part III, Part II on the side, Part I
};

// Everything normalised by the stress-free clamp radius A / L0 (A without pre-stretch).
struct Scaled {
  double a = 0.08;                           // indenter radius
  double depth = 0.0;                        // indentation depth
  double clamp = 1.0;                        // current clamp radius: the pre-stretch L0
  double held() const { return a / clamp; }  // reference radius held at the indenter's edge
};

// The mesh of a layout at a depth.  The numbering of the unknowns depends only on the layout,
// the element counts and the order, so a solution at one depth starts the next.  With the side
// wrapped, the reference length of Part II, `side_length`, is prescribed: the point where the
// membrane leaves the side is found outside the energy minimisation (solve_wrapped).
Mesh build_mesh(Layout layout, const Scaled& s, const FeOptions& options,
                double side_length = 0.0) {
  Mesh mesh;
  mesh.order = options.order;
  const int p = options.order;
  const int n1 = options.elements, n23 = std::max(2, options.elements / 4);
  int next = 0;
  auto unknown = [&] { return unknown_slot(next++); };
  const Slot at_depth = fixed_slot(s.depth, true);

  Slot corner_radius = fixed_slot(s.held());  // R at the corner: unknown when it slides
  Slot side_top_radius = corner_radius;       // R where Part I begins
  Slot part_one_first_z = at_depth;
  if (layout != Layout::Held) {
    corner_radius = unknown();
    side_top_radius = corner_radius;
    MeshPart tip{MembranePart::Tip, false, n23, fixed_slot(0.0), corner_radius, {}, {}};
    for (int i = 0; i <= n23 * p; ++i) {
      tip.r.push_back(i == 0 ? fixed_slot(0.0) : i == n23 * p ? fixed_slot(s.a) : unknown());
      tip.z.push_back(at_depth);
    }
    mesh.parts.push_back(tip);
  }
  if (layout == Layout::SlipWithSide) {
    side_top_radius = unknown_slot(corner_radius.index, side_length);
    MeshPart side{MembranePart::Side, false, n23, corner_radius, side_top_radius, {}, {}};
    for (int i = 0; i <= n23 * p; ++i) {
      side.r.push_back(fixed_slot(s.a));
      side.z.push_back(i == 0 ? at_depth : unknown());
    }
    part_one_first_z = side.z.back();
    mesh.parts.push_back(side);
  }
  MeshPart free_part{MembranePart::Free, true, n1, side_top_radius, fixed_slot(1.0), {}, {}};
  for (int i = 0; i <= n1 * p; ++i) {
    const bool first = i == 0, last = i == n1 * p;
    free_part.r.push_back(first ? fixed_slot(s.a) : last ? fixed_slot(s.clamp) : unknown());
    free_part.z.push_back(first ? part_one_first_z : last ? fixed_slot(0.0) : unknown());
  }
  mesh.parts.push_back(free_part);
  mesh.unknowns = next;
  return mesh;
}

// Reference radius of node i of a part whose ends are at `start` and `end`.
double node_radius(bool logarithmic, int intervals, int i, double start, double end) {
  const double xi = double(i) / intervals;
  return logarithmic ? start * std::pow(end / start, xi) : start + xi * (end - start);
}

// The converged state in physical units.
FeState make_state(const Problem& problem, const Mesh& mesh, const Eigen::VectorXd& x,
                   const fe::Assembly& assembly, const Scaled& s, FeContact contact) {
  const double A = reference_clamp_radius_mm(problem);
  FeState state;
  state.contact = contact;
  state.order = mesh.order;
  state.depth_mm = s.depth * A;
  state.normalized_force = assembly.reaction / s.clamp;
  state.force_n = assembly.reaction * (force_scale_n(problem) / s.clamp);
  state.stored_energy_nmm = assembly.energy * 2.0 * std::numbers::pi *
                            problem.material.shear_modulus_mpa * problem.geometry.thickness_mm * A *
                            A;
  // Held, the membrane under the tip is not meshed: it keeps the pre-stretch L0 (homogeneous) and
  // stores W(L0, L0) over the disc R < a / L0 (nothing without pre-stretch).
  if (contact == FeContact::Held && s.clamp != 1.0) {
    const double w = strain_energy_density(problem.material.law, s.clamp, s.clamp);
    const double r = s.held() * A;
    state.stored_energy_nmm += std::numbers::pi * r * r * problem.geometry.thickness_mm *
                               problem.material.shear_modulus_mpa * w;
  }
  state.unknowns = mesh.unknowns;
  state.corner_reference_radius_mm = s.held() * A;
  state.part_two_top_reference_radius_mm = state.corner_reference_radius_mm;
  for (const MeshPart& part : mesh.parts) {
    FePart out;
    out.part = part.part;
    out.logarithmic = part.logarithmic;
    out.elements = part.elements;
    out.start_radius_mm = fe::value_of(part.start, x) * A;
    out.end_radius_mm = fe::value_of(part.end, x) * A;
    for (std::size_t i = 0; i < part.r.size(); ++i) {
      out.radius_mm.push_back(fe::value_of(part.r[i], x) * A);
      out.deflection_mm.push_back(fe::value_of(part.z[i], x) * A);
    }
    if (part.part == MembranePart::Tip) state.corner_reference_radius_mm = out.end_radius_mm;
    if (part.part == MembranePart::Free)
      state.part_two_top_reference_radius_mm = out.start_radius_mm;
    if (part.part == MembranePart::Side) state.part_two = true;
    // Largest I1 at the quadrature points and at both ends of every element.
    fe::raise_largest_first_invariant(
        mesh, part, x, A, state.max_first_invariant, state.max_first_invariant_reference_radius_mm);
    state.parts.push_back(std::move(out));
  }
  state.part_three_stretch = radius_mm(problem.indenter) / state.corner_reference_radius_mm;
  state.contact_edge_radius_mm = radius_mm(problem.indenter);
  return state;
}

// dr/dR where Part I leaves the indenter: negative when the free membrane would enter it.
double corner_radial_slope(const FeState& state) {
  for (const FePart& part : state.parts)
    if (part.part == MembranePart::Free) {
      const double dR = node_radius(part.logarithmic,
                                    part.elements * state.order,
                                    1,
                                    part.start_radius_mm,
                                    part.end_radius_mm) -
                        part.start_radius_mm;
      return (part.radius_mm[1] - part.radius_mm[0]) / dR;
    }
  return 1.0;
}

// Starting values of the unknowns of `mesh` at depth s.depth: from a previous state (its shape,
// the deflections scaled to the new depth), or for the first step a cone in ln R.
Eigen::VectorXd starting_guess(const Mesh& mesh, const Scaled& s, const FeState* previous,
                               double clamp_radius) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(mesh.unknowns);
  const double A = clamp_radius;
  const double corner = previous ? previous->corner_reference_radius_mm / A : s.held() * 0.999;
  const double scale = previous ? s.depth / (previous->depth_mm / A) : 1.0;
  for (const MeshPart& part : mesh.parts)  // the moving corner first
    if (part.part == MembranePart::Tip) x[part.end.index] = corner;
  for (const MeshPart& part : mesh.parts) {
    const double start = fe::value_of(part.start, x), end = fe::value_of(part.end, x);
    for (std::size_t i = 0; i < part.r.size(); ++i) {
      const double R =
          node_radius(part.logarithmic, part.elements * mesh.order, int(i), start, end);
      double r = R * s.clamp, z = s.depth;
      std::optional<fe::PointFields> old;
      if (previous)
        for (const FePart& p : previous->parts)
          if (!old) old = fe::evaluate_part(p, previous->order, R * A);
      if (old) {
        r = old->radius / A;
        z = old->deflection / A * scale;
      } else if (part.part == MembranePart::Tip) {
        r = R * s.a / corner;
      } else if (part.part == MembranePart::Free) {
        z = s.depth * std::log(R) / std::log(start);
      }
      if (part.r[i].index >= 0) x[part.r[i].index] = r;
      if (part.z[i].index >= 0) x[part.z[i].index] = std::min(z, s.depth);
    }
  }
  return x;
}

struct StepResult : Outcome {
  FeState state;
};

// Minimises the energy of one layout from `x` (updated in place).
StepResult minimise(const Problem& problem, const Mesh& mesh, const Scaled& s, Eigen::VectorXd& x,
                    FeContact contact, const FeOptions& options) {
  const fe::NewtonResult newton =
      fe::minimise_energy(problem.material.law, mesh, x, options.max_newton_iterations);
  StepResult step;
  step.status = newton.status;
  step.message = newton.message;
  if (newton.ok()) {
    step.state = make_state(problem, mesh, x, newton.assembly, s, contact);
    step.state.newton_iterations = newton.iterations;
    step.state.status = Status::Converged;
  }
  return step;
}

StepResult solve_layout(const Problem& problem, Layout layout, const Scaled& s,
                        const FeState* previous, FeContact contact, const FeOptions& options) {
  const Mesh mesh = build_mesh(layout, s, options);
  Eigen::VectorXd x = starting_guess(mesh, s, previous, reference_clamp_radius_mm(problem));
  return minimise(problem, mesh, s, x, contact, options);
}

// The membrane wrapped on the side.  Where it leaves the side is not an energy minimum over the
// layout's unknowns: with the free part allowed to cross the side, the energy E(L, depth) falls
// as the side's reference length L shortens, and dE/dL >= 0 vanishes without changing sign at
// the answer L* (a double root: Newton on it converges only linearly).  Two consequences are
// used.  The free part leaves the side tangentially at L*: dr/dR where it begins is < 0 (it
// enters the indenter) for L < L* and > 0 (a kink outward) for L > L*, which brackets L*.  And
// since dE/dL = d2E/dL2 = 0 at L* for every depth, d2E/dL d(depth) = 0 there: the force
// dE/d(depth) is stationary (a maximum) in L at L*.  Boost's Brent finds that maximum; the
// force there is insensitive to the error of L, and converges at the elements' full order
// (the discrete tangency condition alone places L* only to O(h), the force to O(h^2)).
StepResult solve_wrapped(const Problem& problem, const Scaled& s, const FeState& previous,
                         FeContact contact, const FeOptions& options, bool precise) {
  const double A = reference_clamp_radius_mm(problem);
  const double corner = previous.corner_reference_radius_mm / A;
  double length =
      previous.part_two
          ? (previous.part_two_top_reference_radius_mm - previous.corner_reference_radius_mm) / A
          : 1e-3 * corner;
  // Each side length starts from the latest state at this depth (the previous depth's at
  // first), material point by material point: a node keeps the position its reference radius
  // had.  Near locking that start can lock where the free part leaves the side (its first,
  // shortest element meets a kink); then the nodes keep the latest solution's positions
  // instead, which rescales the side's stretches by the change of its length but keeps the
  // free part smooth.  Each start alone fails somewhere near locking; together they follow
  // the paper's membrane to within 1e-2 of Gent's locking.
  std::optional<FeState> latest;
  Eigen::VectorXd latest_x;
  StepResult last;
  auto slope_at = [&](double length) {
    const Mesh mesh = build_mesh(Layout::SlipWithSide, s, options, length);
    Eigen::VectorXd x = starting_guess(mesh, s, latest ? &*latest : &previous, A);
    if (latest && !std::isfinite(fe::total_energy(problem.material.law, mesh, x))) x = latest_x;
    last = minimise(problem, mesh, s, x, contact, options);
    if (!last.ok()) throw std::runtime_error(last.message);
    latest = last.state;
    latest_x = x;
    return corner_radial_slope(last.state);
  };
  try {
    double slope = slope_at(length);
    if (!precise) {
      // A continuation step on the way: one secant step towards the tangential departure gives
      // the next step a good start; the requested depths are solved precisely.
      const double other = slope < 0.0 ? 1.05 * length : length / 1.05;
      const double slope_other = slope_at(other);
      if (slope_other != slope) {
        const double secant = other - slope_other * (other - length) / (slope_other - slope);
        if (secant > 0.5 * std::min(length, other) && secant < 2.0 * std::max(length, other)) {
          slope_at(secant);
          return last;
        }
      }
    }
    double lo = length, hi = length, slope_lo = slope, slope_hi = slope;
    // Bracket the tangential departure by growing or shrinking the side's length in steps small
    // enough for the last solution to start the next.
    constexpr double factor = 1.25;
    for (int k = 0; k < 200 && (slope_lo >= 0.0 || slope_hi <= 0.0); ++k) {
      if (slope_hi <= 0.0) {
        lo = hi, slope_lo = slope_hi;
        hi *= factor;
        slope_hi = slope_at(hi);
      } else {
        hi = lo, slope_hi = slope_lo;
        lo /= factor;
        if (lo < 1e-12 * corner) break;
        slope_lo = slope_at(lo);
      }
    }
    if (!(slope_lo < 0.0 && slope_hi > 0.0)) {
      StepResult none;
      none.message = "no side contact: the free part leaves the corner outward";
      return none;
    }
    // The force is stationary (a maximum) in the side's length at the answer (see above): Brent
    // finds it near the tangency, and the force there is insensitive to the length's error.
    // The discrete maximum and the discrete tangency differ by O(h) (0.1 % at 128 elements,
    // more on coarse meshes), so the search starts in a window of +-10 % around the tangency,
    // located by TOMS 748, and moves the window on while the maximum sits at its edge.  A
    // window as wide as the bracket is not safe near locking: there the force rises again at
    // lengths ~1.5 times the answer, where the side would pull the free part onto itself
    // (dr/dR > 0 at the top), and can exceed the maximum.
    boost::uintmax_t root_iterations = 50;
    const auto tangency =
        boost::math::tools::toms748_solve(slope_at,
                                          lo,
                                          hi,
                                          slope_lo,
                                          slope_hi,
                                          boost::math::tools::eps_tolerance<double>(10),
                                          root_iterations);
    const double around = 0.5 * (tangency.first + tangency.second);
    double from = around / 1.1, to = around * 1.1, best = around;
    for (int moves = 0; moves < 10; ++moves) {
      boost::uintmax_t iterations = 200;
      best = boost::math::tools::brent_find_minima(
                 [&](double length) {
                   slope_at(length);
                   return -last.state.normalized_force;
                 },
                 from,
                 to,
                 20,  // bits: L to ~1e-6 relative, the force (stationary) to ~1e-12
                 iterations)
                 .first;
      if (best > to / 1.001)
        from = to / 1.01, to *= 1.1;
      else if (best < from * 1.001)
        to = from * 1.01, from /= 1.1;
      else
        break;
    }
    slope_at(best);
  } catch (const std::runtime_error& e) {
    StepResult failed;
    failed.message = e.what();
    return failed;
  }
  return last;
}

// One continuation step to depth s.depth: the layout of the previous state, switched when the
// solution leaves it (the free part entering the indenter, or the side contact vanishing).
StepResult solve_step_in_layout(const Problem& problem, Layout& layout, const Scaled& s,
                                const FeState* previous, FeContact contact,
                                const FeOptions& options, bool precise) {
  if (layout == Layout::Held) {
    StepResult step = solve_layout(problem, layout, s, previous, contact, options);
    if (step.ok() && corner_radial_slope(step.state) < 0.0) {
      step.status = Status::StickWrapsSide;
      step.message = "the held membrane would wrap the indenter's side (outside the stick model)";
    }
    return step;
  }
  if (layout == Layout::SlipWithoutSide) {
    StepResult step = solve_layout(problem, layout, s, previous, contact, options);
    if (!step.ok() || corner_radial_slope(step.state) >= 0.0) return step;
    // Started from the last state outside the indenter: the one just found crosses the side.
    StepResult wrapped =
        solve_wrapped(problem, s, previous ? *previous : step.state, contact, options, precise);
    if (wrapped.ok()) layout = Layout::SlipWithSide;
    return wrapped;
  }
  StepResult wrapped = solve_wrapped(problem, s, *previous, contact, options, precise);
  if (wrapped.ok()) return wrapped;
  // The side contact may have shrunk to nothing: try without it.
  StepResult plain = solve_layout(problem, Layout::SlipWithoutSide, s, previous, contact, options);
  if (plain.ok() && corner_radial_slope(plain.state) >= 0.0) {
    layout = Layout::SlipWithoutSide;
    return plain;
  }
  return wrapped;
}

// Nodes of the free part inside the indenter (r < a) by more than the elements' own error
// where the membrane leaves the side (a dip of O(h^2) relative): the answer is not admissible.
bool crosses_side(const FeState& state, double indenter_radius_mm) {
  for (const FePart& part : state.parts)
    if (part.part == MembranePart::Free)
      for (double r : part.radius_mm)
        if (r < indenter_radius_mm * (1.0 - 1e-3)) return true;
  return false;
}

StepResult solve_step(const Problem& problem, Layout& layout, const Scaled& s,
                      const FeState* previous, FeContact contact, const FeOptions& options,
                      bool precise) {
  StepResult step = solve_step_in_layout(problem, layout, s, previous, contact, options, precise);
  if (step.ok() && crosses_side(step.state, radius_mm(problem.indenter))) {
    step.status = Status::NoConvergence;
    step.message =
        "the free membrane crosses the indenter's side (too few elements for this state?)";
  }
  return step;
}

void check_options(const FeOptions& options) {
  if (options.order != 1 && options.order != 2)
    throw std::invalid_argument(
        fmt::format("element order must be 1 or 2 (got {})", options.order));
  if (options.elements < 2 || options.elements > 100000)
    throw std::invalid_argument(
        fmt::format("elements must be between 2 and 100000 (got {})", options.elements));
  if (options.max_newton_iterations < 1 || options.max_step_halvings < 0 ||
      !(options.max_depth_step > 0.0 && options.max_depth_step <= 1.0))
    throw std::invalid_argument(
        "max Newton iterations must be >= 1, step halvings >= 0 and the depth step in (0, 1]");
}

}  // namespace

std::vector<FeState> fe_solve_at_depths(const Problem& problem,
                                        const std::vector<double>& depths_mm, FeContact contact,
                                        const FeOptions& options) {
  validate(problem);
  const bool smooth = !sharp_flat_punch(problem.indenter);
  const bool pressurised = problem.preload.pressure_mpa > 0.0;
  if (pressurised && contact == FeContact::Held && !smooth)
    throw InvalidInput("preload.pressure_mpa",
                       "under a gas pressure the finite elements on the sharp flat punch are "
                       "frictionless only (a held edge would need the stick stage's history of "
                       "the face); held where it touched they cover the smooth probes");
  if (problem.preload.gas_volume_mm3 && !pressurised)
    throw InvalidInput("preload.pressure_mpa",
                       "over a sealed gas chamber the finite elements need it closed at a gauge "
                       "pressure > 0 MPa (closed flat, the flat membrane has no volume to start "
                       "from in the elements' layouts)");
  if (problem.preload.gas_volume_mm3 && contact == FeContact::Held)
    throw InvalidInput("preload.gas_volume_mm3",
                       "over a sealed gas chamber the finite elements are frictionless only");
  check_options(options);
  const double A = reference_clamp_radius_mm(problem);
  double last = 0.0;
  for (double d : depths_mm) {
    if (!std::isfinite(d) || d <= last)
      throw std::invalid_argument(fmt::format(
          "depths must be finite, > 0 and increasing (got {} mm after {} mm)", d, last));
    last = d;
  }
  if (problem.preload.gas_volume_mm3) return fe::solve_sealed_chamber(problem, depths_mm, options);
  if (smooth && contact == FeContact::Held)  // held where it touched
    return fe::solve_held_smooth_probe(
        problem, *fe::smooth_profile(problem.indenter, A), depths_mm, options);
  if (smooth)
    return fe::solve_smooth_probe(
        problem, *fe::smooth_profile(problem.indenter, A), depths_mm, options);
  if (pressurised)  // the face's contact disc grows on the dome: its edge is searched for
    return fe::solve_smooth_probe(
        problem,
        *fe::sharp_punch_profile(std::get<FlatPunch>(problem.indenter), A),
        depths_mm,
        options);
  Scaled s;
  s.a = radius_mm(problem.indenter) / A;
  s.clamp = problem.preload.prestretch;
  Layout layout = contact == FeContact::Held ? Layout::Held : Layout::SlipWithoutSide;
  std::vector<FeState> states;
  std::optional<FeState> previous;
  double depth = 0.0, step = options.max_depth_step;
  for (double target_mm : depths_mm) {
    const double target = target_mm / A;
    int halvings = 0;
    std::string failure;
    while (depth < target && failure.empty()) {
      s.depth = std::min(target, depth + step);
      if (target - s.depth < 1e-3 * step) s.depth = target;  // no sliver of a last step
      StepResult result = solve_step(
          problem, layout, s, previous ? &*previous : nullptr, contact, options, s.depth == target);
      if (result.ok()) {
        depth = s.depth;
        previous = std::move(result.state);
        step = std::min(2.0 * step, options.max_depth_step);
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
      fe::fill_unreached_depths(states, depths_mm, contact, FeState{}.status, failure);
      return states;
    }
    states.push_back(*previous);
  }
  return states;
}

FeState fe_solve_at_depth(const Problem& problem, double depth_mm, FeContact contact,
                          const FeOptions& options) {
  return fe_solve_at_depths(problem, {depth_mm}, contact, options).front();
}

FeState fe_inflated_state(const Problem& problem, const FeOptions& options) {
  validate(problem);
  if (!(problem.preload.pressure_mpa > 0.0))
    throw InvalidInput("preload.pressure_mpa",
                       "the finite elements' inflated state needs a gas pressure > 0 MPa");
  check_options(options);
  // Over a sealed chamber: the dome it is closed at, the held one at the sealing pressure.
  Problem held = problem;
  held.preload.gas_volume_mm3.reset();
  return fe::solve_dome(held, options).state;
}

std::optional<double> fe_first_invariant(const FeState& state, MembranePart part,
                                         double reference_radius_mm) {
  for (const FePart& p : state.parts)
    if (p.part == part) {
      const auto f = fe::evaluate_part(p, state.order, reference_radius_mm);
      if (!f) return std::nullopt;
      return first_invariant(f->l1, f->l2);
    }
  return std::nullopt;
}

std::string to_string(FeContact contact) {
  return contact == FeContact::Held ? "held (at the indenter's edge, or where it touched)"
                                    : "frictionless";
}

}  // namespace puncture
