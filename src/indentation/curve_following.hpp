#pragma once
// The displacement-controlled loading curve for any indenter (a shooting, shooting.hpp): equally
// spaced depths from zero to puncture, each by a Newton corrector (DepthNewton) from an
// extrapolation of the previous points, across the stick -> slip switch and the contact model's
// change of configuration on the sliding branch.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "indentation/depth_newton.hpp"
#include "indentation/nested_depth_solve.hpp"
#include "indentation/partial_slip_path.hpp"
#include "indentation/puncture_search.hpp"
#include "indentation/solver_scales.hpp"
#include "numerics/gauss_legendre.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::detail {

// Extrapolation of (f, p) to a new depth from the last converged points of a segment: the
// predictor of the Newton corrector.  Near zero depth f ~ depth^3 and p - 1 ~ depth^2
// (membrane theory), so it works with log f and log(p - p0) (p0 the parameter's floor) against
// log depth: from one point with those powers, from two to six by Lagrange interpolation.  (More
// points amplify the points' own error, ~1e-9, beyond what they gain: with six the first guess
// of a point deep in the curve is ~1e-8 off, one Newton step from converged.)
struct Predictor {
  std::vector<std::array<double, 3>> history;  // depth, f, parameter
  static constexpr std::size_t kOrder = 6;     // points used at most
  bool usable() const { return !history.empty(); }
  std::array<double, 2> at(double d, double floor) const {
    const std::size_t n = history.size(), m = std::min<std::size_t>(n, kOrder);
    if (n == 1) {
      const auto& h = history.front();
      const double ratio = d / h[0];
      return {h[1] * ratio * ratio * ratio, floor + (h[2] - floor) * ratio * ratio};
    }
    std::array<double, 2> out{0.0, 0.0};
    for (std::size_t i = n - m; i < n; ++i) {
      double w = 1.0;
      for (std::size_t j = n - m; j < n; ++j)
        if (j != i) w *= std::log(d / history[j][0]) / std::log(history[i][0] / history[j][0]);
      out[0] += w * std::log(history[i][1]);
      out[1] += w * std::log(history[i][2] - floor);
    }
    return {std::exp(out[0]), floor + std::exp(out[1])};
  }
};

// On a contact model whose depth is noisy near zero load (kNoisyNearZeroLoad), a curve point
// whose Newton steps stall at the evaluations' noise (in solve_at_depth's newton_at_depth,
// DepthNewton::guarded) is accepted if its residuals are within this many times the tolerance:
// on the sphere-tipped probe the noise is ~1e-8 (bench/README.md), where the force search that
// took over before also ended on the noise (it accepts a depth within 1e-5, kDepthMatch).
inline constexpr double kNoiseLimitedResidual = 100.0;

// Whether a contact model's depth is noisy near zero load (contact_model.hpp).
template <class Contact>
constexpr bool noisy_near_zero_load() {
  if constexpr (requires { Contact::kNoisyNearZeroLoad; })
    return Contact::kNoisyNearZeroLoad;
  else
    return false;
}

// The curve's point of state `sol` at `depth_mm` in `stage`.
template <class Contact>
CurvePoint curve_point_of(const Problem& p, const Contact& contact, const ScaledSolution& sol,
                          Stage stage, double depth_mm) {
  const SolverScales units = solver_scales(p);
  CurvePoint pt;
  pt.depth_mm = depth_mm;
  pt.force_n = sol.f * units.force_n;
  pt.normalized_force = units.normalized_force(sol.f);
  pt.stage = stage;
  pt.configuration = sol.configuration;
  pt.part_three_stretch = sol.part_three_stretch;
  pt.part_two_length_mm = sol.part_two_length * units.length_mm;
  pt.corner_slope_rad = sol.corner_slope;
  if (sol.configuration != Configuration::Unloaded) {
    pt.contact_edge_radius_mm = sol.edge_radius * units.length_mm;
    pt.contact_edge_height_mm = contact.free_part_inner_height(sol) * units.length_mm;
  }
  pt.max_first_invariant = max_first_invariant_of(sol);
  pt.beyond_puncture = any_exceeded(p, contact, sol);
  return pt;
}

// Fills out.points along the depth grid; false (with out.status/message) on failure.
// `change`: where the sliding configuration changes (the contact model's slip_change), if it does.
// Where that search found none and a point fails past a change, the change is found from the
// last point (past_change_on_path), set as the curve's onset and put in `found_change`.
template <class Shooting>
bool follow_curve(const Problem& p, const Shooting& shooting, double curve_tol,
                  const StageBoundary& boundary, double end_depth, bool has_switch,
                  const std::optional<ScaledSolution>& change, const CurveOptions& curve,
                  LoadingCurve& out, std::optional<ScaledSolution>* found_change = nullptr) {
  const SolverScales units = solver_scales(p);
  const double scale = units.force_n;
  const double big_a = units.length_mm;
  const auto& contact = shooting.contact();
  DepthNewton<Shooting> newton(shooting, curve_tol);
  newton.without_maxima(true);  // only the points' own states need their largest I1
  // On a noisy model without a gas pressure, sliding from the first touch (where it was
  // measured, bench/README.md; any rule that holds nothing gives the same curve); the flat
  // punch's points, the inflated membranes' paths and curves with a held stage (whose switch
  // points and partial slip start from their own states) kept as they were.
  const bool sped_up = noisy_near_zero_load<std::decay_t<decltype(contact)>>() &&
                       p.preload.pressure_mpa == 0.0 && boundary.first_stage == Stage::Slip;
  if (sped_up) {
    newton.extrapolated_jacobian();
    newton.valley_start();
  }
  Predictor predictor;
  Stage segment_stage = boundary.first_stage;
  Configuration last_configuration = Configuration::Unloaded;
  std::optional<double> last_contact_q;        // the last point's contact quantity (DepthControl)
  std::optional<ScaledSolution> last_sliding;  // the last point's state, on the sliding branch
  auto stage_at = [&](double depth) {
    if (boundary.first_stage == Stage::Slip) return Stage::Slip;
    if (!boundary.switches || depth <= boundary.depth_mm) return Stage::Stick;
    return Stage::Slip;
  };
  auto expected_configuration = [&](double depth, Stage stage) {
    return contact.configuration(
        stage, out.part_two_onset_depth_mm && depth >= *out.part_two_onset_depth_mm);
  };
  auto add_point = [&](double depth, Stage stage) -> bool {
    if (stage != segment_stage) {
      predictor.history.clear();
      newton.reset();
      segment_stage = stage;
    }
    const double d = depth / big_a;
    std::optional<ScaledSolution> sol;
    double f_predicted = 0.0;  // the predictor's force at d, if any
    if (d > 0.0 && !predictor.usable()) {
      // Seed a new segment with one solve at a known force: a small one at the start of the
      // curve (the power-law predictor carries it to the first depth), the held force at the
      // stick -> slip switch.
      const double f_seed =
          out.points.size() > 1 ? out.points.back().normalized_force * units.prestretch : 1e-4;
      // (On a later inflated state, next to its dome: dome_branch_start.)
      const auto seed = out.points.size() > 1 ? shooting.solve(stage, f_seed)
                                              : dome_branch_start(shooting, stage);
      if (seed.ok()) {
        predictor.history = {{seed.depth, seed.f, seed.parameter}};
        last_configuration = seed.configuration;
      }
    }
    if (d > 0.0 && predictor.usable()) {
      const Configuration c = expected_configuration(depth, stage);
      auto guess = predictor.at(d, shooting.parameter_floor(c));
      f_predicted = guess[0];
      if (c != last_configuration) {
        newton.reset();
        if (c == contact.configuration(Stage::Slip, true) && change) {
          // The new configuration starts where the old one ends (the flat punch: Part II starts
          // with zero length at the onset, its top stretch from the onset Part III stretch),
          // while the force keeps following the curve.
          guess[1] = change->parameter;
          predictor.history = {{change->depth, change->f, change->parameter}};
        }
      }
      sol = newton.solve(c, d, guess[0], guess[1]);
      if (!sol && last_contact_q && c == last_configuration &&
          shooting.control_of(c) == DepthControl::Contact) {
        // Near a limit load the force Newton's steps cross it: the contact's own quantity, from
        // the last point's, takes the depth instead.
        DepthNewton<Shooting> contact_newton(shooting, curve_tol, false, DepthControl::Contact);
        sol = contact_newton.solve(c, d, *last_contact_q, guess[1]);
      }
      if (!sol && sped_up && predictor.history.size() == 1) {
        // The segment's first point from its seed: along the valley of states meeting the
        // clamp condition (nested_depth_solve.hpp), where Newton's start lies outside its basin.
        // Its parameter from the seed's with p - p0 ~ f^(1/2), the sphere's near zero load (the
        // predictor's d^2 in depth put it below the branch point).
        const auto& seed = predictor.history.front();
        const double floor = shooting.parameter_floor(c);
        const double p_start = floor + (seed[2] - floor) * std::sqrt(guess[0] / seed[1]);
        NestedDepthSolve<Shooting> nested(shooting, curve_tol, kNoiseLimitedResidual * curve_tol);
        sol = nested.solve(c, d, guess[0], p_start);
      }
    }
    if (!sol) {
      newton.reset();
      using Contact = std::decay_t<decltype(contact)>;
      // Sped up, the fallback's force search starts from the predictor's force, not the
      // last point's (at the curve's first points, f ~ depth^3, that cost two more force solves).
      const bool from_prediction = sped_up && std::isfinite(f_predicted) && f_predicted > 0.0;
      const double f_guess = from_prediction             ? f_predicted
                             : predictor.history.empty() ? 0.0
                                                         : predictor.history.back()[1];
      const double noise_tol =
          noisy_near_zero_load<Contact>() ? kNoiseLimitedResidual * curve_tol : 0.0;
      sol = shooting.solve_at_depth(stage, d, f_guess, noise_tol);
    }
    if (!sol->ok() && stage == Stage::Slip && shooting.settings().dome_later_state &&
        !(last_sliding && last_sliding->depth < d))
      if (auto on = dome_branch_at_depth(shooting, stage, d)) sol = std::move(on);
    if (!sol->ok() && stage == Stage::Slip && last_sliding) {
      // Where the searches by force close on another branch's state (near an inflation limit
      // point, docs/model.md §17), depth control from the last point stays on the path.
      ScaledSolution from = *last_sliding;
      if (auto on = shooting.continue_in_depth(from, d); on && on->ok()) sol = std::move(on);
    }
    if (!sol->ok() && stage == Stage::Slip && last_sliding && !out.part_two_onset_depth_mm)
      if (auto passed = past_change_on_path(shooting, *last_sliding, d)) {
        // The contact changed its configuration between the last point and this one where the
        // contact model's own search for the change found none (the sphere's equator on a dome
        // beyond a hemisphere, docs/model.md §17): found from the last point, it is the curve's.
        out.part_two_onset_depth_mm = passed->change.depth * big_a;
        out.part_two_onset_force_n = passed->change.f * scale;
        if (found_change) *found_change = passed->change;
        predictor.history = {{passed->change.depth, passed->change.f, passed->change.parameter}};
        newton.reset();
        sol = std::move(passed->state);
      }
    if (sol->ok() && stage == Stage::Slip && last_sliding && !out.part_two_onset_depth_mm &&
        sol->configuration != last_sliding->configuration &&
        sol->configuration == contact.configuration(Stage::Slip, true))
      if (auto passed = change_past(shooting, *last_sliding); passed && passed->depth < d) {
        // The point was reached past a change the contact model's search from a small force did
        // not find (solve_at_depth: from the deepest state short of it): the change is the
        // curve's, found from the last point.
        out.part_two_onset_depth_mm = passed->depth * big_a;
        out.part_two_onset_force_n = passed->f * scale;
        predictor.history = {{passed->depth, passed->f, passed->parameter}};
        newton.reset();
        if (found_change) *found_change = std::move(*passed);
      }
    if (!sol->ok()) {
      out.status = sol->status;
      out.message =
          fmt::format("at depth {:.6g} mm ({} stage): {}", depth, to_string(stage), sol->message);
      return false;
    }
    if (sol->configuration != Configuration::Unloaded)
      predictor.history.push_back({d, sol->f, sol->parameter});
    last_configuration = sol->configuration;
    if (stage == Stage::Slip) last_sliding = *sol;
    last_contact_q.reset();
    if (shooting.control_of(sol->configuration) == DepthControl::Contact)
      last_contact_q = depth_unknown(DepthControl::Contact, *sol);
    out.points.push_back(curve_point_of(p, contact, *sol, stage, depth));
    return true;
  };
  // After a `coulomb` release on a curved probe the path is the partial-slip family's up to its
  // hand-over to the sliding model (partial_slip_path.hpp).
  const auto partial = has_switch ? partial_slip_segment(p, shooting, boundary) : std::nullopt;
  if (partial) {
    out.stick_slip.full_sliding_depth_mm = partial->handover_depth_mm;
    out.stick_slip.full_sliding_force_n = partial->handover_force_n;
  }
  bool after_partial = false;  // the first sliding point past the hand-over starts a new segment
  auto add_partial_point = [&](double depth) -> bool {
    if (depth < partial->first_depth_mm) {
      // Within a few um of the release the front's search does not resolve the family (its
      // annulus ~1e-3 of the release edge wide): the held state stands for it there.
      if (!add_point(depth, Stage::Stick)) return false;
      CurvePoint& held = out.points.back();
      held.stage = Stage::Slip;
      held.configuration = Configuration::PartialSlip;
      held.slip_front_reference_radius_mm = partial->release.slip_front_reference_radius_mm;
      held.slip_front_radius_mm = held.contact_edge_radius_mm;
      after_partial = true;
      return true;
    }
    auto pt = partial->at_depth(depth);
    if (!pt) {
      out.status = Status::NoConvergence;
      out.message = fmt::format(
          "at depth {:.6g} mm (partial slip after the coulomb release): no state of the "
          "family reaches this depth",
          depth);
      return false;
    }
    pt->depth_mm = depth;  // the family's depth, to its search's 1e-13
    for (const auto& c : failure_criteria(p))
      if (std::holds_alternative<CriticalFirstInvariant>(c) &&
          pt->max_first_invariant > critical_value(c) * (1.0 + 1e-8))
        pt->beyond_puncture = true;
    out.points.push_back(*pt);
    after_partial = true;
    return true;
  };
  auto add_path_point = [&](double depth, Stage stage) -> bool {
    if (partial && stage == Stage::Slip && partial->covers(depth)) return add_partial_point(depth);
    if (after_partial && stage == Stage::Slip) {
      // Past the hand-over the sliding model's segment starts from the family's last force.
      predictor.history.clear();
      newton.reset();
      after_partial = false;
    }
    return add_point(depth, stage);
  };
  const bool given = !curve.depths_mm.empty();
  const int n = given ? static_cast<int>(curve.depths_mm.size()) : curve.points;
  // The last depth is end_depth itself (end_depth * (n - 1) / (n - 1) may miss it by an ulp).
  auto grid = [&](int k) {
    if (given) return curve.depths_mm[static_cast<std::size_t>(k)];
    return k == n - 1 ? end_depth : end_depth * k / (n - 1);
  };
  for (int k = 0; k < n; ++k) {
    const double depth = grid(k);
    const double prev_depth = k == 0 ? -1.0 : grid(k - 1);
    if (has_switch && depth >= boundary.depth_mm && prev_depth < boundary.depth_mm) {
      // Both sides of the switch, at the switch depth (which may be a grid depth: the last one
      // when the membrane punctures as it starts sliding).
      if (!add_point(boundary.depth_mm, Stage::Stick)) return false;
      if (partial) {
        // The family starts from the held state (an empty annulus): no jump.
        out.points.push_back(partial->release);
        out.points.back().depth_mm = boundary.depth_mm;
        after_partial = true;
      } else if (!add_point(boundary.depth_mm, Stage::Slip)) {
        return false;
      }
      out.stick_slip.force_sliding_n = out.points.back().force_n;
    }
    if (!(has_switch && depth == boundary.depth_mm) && !add_path_point(depth, stage_at(depth)))
      return false;
    if (curve.progress) curve.progress(k + 1, n);
  }
  return true;
}

// The change of configuration on the sliding branch (the flat punch: Part II appears) as the
// loading path meets it.
struct SlidingChange {
  std::optional<ScaledSolution> state;  // where the sliding membrane changes configuration
  std::optional<double> depth_mm;       // where the path changes configuration [mm]
  // A membrane held past that depth slides straight into the changed configuration at the
  // stick -> slip switch (depth_mm is then the switch's, and `state` empty).
  bool at_switch = false;
};

template <class Shooting>
SlidingChange sliding_change(const Shooting& shooting, const StageBoundary& boundary,
                             double big_a) {
  SlidingChange out;
  if (boundary.first_stage != Stage::Slip && !boundary.switches) return out;
  // On a later inflated state the search from a small force finds the first state's change: the
  // curve finds its own from its points (follow_curve).
  if (shooting.settings().dome_later_state) return out;
  out.state = shooting.contact().slip_change(shooting);
  if (!out.state) return out;
  out.depth_mm = out.state->depth * big_a;
  if (boundary.switches && *out.depth_mm < boundary.depth_mm) {
    out.at_switch = true;
    out.depth_mm = boundary.depth_mm;
    out.state.reset();
  }
  return out;
}

// Panels of the 10-point Gauss-Legendre rule on each smooth piece of the path; on a pre-tensioned
// membrane (pre-stretched or inflated) the first, from zero depth, graded towards it: there the
// force is not smooth at zero depth (~ depth / log(depth), as a point load's), while on a slack
// one it goes as depth^3 and depths far below 1e-3 of the puncture's are beyond the solver.
// tests/solver/puncture_energy_test.cpp measures the result against dense curves.
inline constexpr int kEnergyPanels = 12;
inline constexpr int kEnergyGradedPanels = 10;

// Sets the puncture's energy to puncture [mJ], int_0^depth F d(depth) to the puncture depth (the
// switch's, when it punctures there).  F(depth) is smooth on each piece of the path (held; sliding
// before and after the contact's change of configuration), so each piece gets composite
// Gauss-Legendre quadrature, the forces at its nodes from the curve driver (follow_curve); the
// jump at the switch is at one depth and adds no area.  A path that cannot be followed leaves the
// energy empty and says why in the message.
template <class Shooting>
void add_energy_to_puncture(const Problem& p, const Shooting& shooting, double curve_tol,
                            const StageBoundary& boundary, const SlidingChange& change,
                            bool puncture_at_switch, PuncturePrediction& puncture,
                            int panels = kEnergyPanels) {
  const double end = puncture_at_switch ? boundary.depth_mm : puncture.depth_mm;
  const bool slides = !(puncture_at_switch && puncture.stage == Stage::Stick);
  const bool has_switch = boundary.switches && boundary.depth_mm <= end && slides;
  std::vector<double> cuts{0.0};
  if (boundary.switches && boundary.depth_mm < end) cuts.push_back(boundary.depth_mm);
  if (change.state && *change.depth_mm > cuts.back() && *change.depth_mm < end)
    cuts.push_back(*change.depth_mm);
  // After a `coulomb` release the path's partial slip hands over to the sliding model where its
  // front reaches the pole (partial_slip_path.hpp): the force's slope need not be smooth there.
  if (has_switch)
    if (const auto partial = partial_slip_segment(p, shooting, boundary);
        partial && partial->handover_depth_mm > boundary.depth_mm &&
        partial->handover_depth_mm < end) {
      cuts.push_back(partial->handover_depth_mm);
      std::sort(cuts.begin(), cuts.end());
    }
  cuts.push_back(end);
  QuadratureNodes q;
  const bool pretensioned = p.preload.pressure_mpa > 0.0 || p.preload.prestretch > 1.0;
  append_graded_gauss_legendre(cuts[0], cuts[1], panels, pretensioned ? kEnergyGradedPanels : 0, q);
  for (std::size_t i = 1; i + 1 < cuts.size(); ++i)
    append_gauss_legendre(cuts[i], cuts[i + 1], panels, q);
  CurveOptions at_nodes;
  at_nodes.depths_mm = q.nodes;
  LoadingCurve path;
  path.part_two_onset_depth_mm = change.depth_mm;
  auto note = [&](const std::string& why) {
    puncture.message +=
        (puncture.message.empty() ? "" : "; ") + fmt::format("no energy to puncture: {}", why);
  };
  if (q.nodes.empty()) {
    puncture.energy_to_puncture_mj = 0.0;
    return;
  }
  std::optional<ScaledSolution> found;
  if (!follow_curve(p,
                    shooting,
                    curve_tol,
                    boundary,
                    end,
                    has_switch,
                    change.state,
                    at_nodes,
                    path,
                    &found)) {
    note(path.message);
    return;
  }
  // The path changed configuration where the contact model's search found no change (under a
  // gas pressure, follow_curve): again with the pieces meeting there, as the curve's energy.
  if (found && !change.state && found->depth * solver_scales(p).length_mm < end) {
    SlidingChange at_found = change;
    at_found.depth_mm = found->depth * solver_scales(p).length_mm;
    at_found.state = std::move(found);
    add_energy_to_puncture(
        p, shooting, curve_tol, boundary, at_found, puncture_at_switch, puncture, panels);
    return;
  }
  // The driver adds both states at the switch depth, which no node is: the nodes' points are
  // the others, in order.
  double work = 0.0;
  std::size_t j = 0;
  for (const CurvePoint& pt : path.points)
    if (j < q.nodes.size() && pt.depth_mm == q.nodes[j]) work += q.weights[j++] * pt.force_n;
  if (j != q.nodes.size()) {
    note("the path's depths do not match the quadrature's");
    return;
  }
  puncture.energy_to_puncture_mj = work;
}

// The curve of a valid problem; `shooting` (made with `options` without fields) serves every
// solve, `options` makes the state at puncture physical.
template <class Shooting>
LoadingCurve curve_to_puncture(const Problem& p, const Shooting& shooting,
                               const CurveOptions& curve, const SolverOptions& options) {
  LoadingCurve out;
  const SolverScales units = solver_scales(p);
  const double scale = units.force_n;
  const double big_a = units.length_mm;
  const auto switch_point = locate_switch(p, shooting);
  const StageBoundary& boundary = switch_point.boundary;
  if (boundary.status != Status::Converged) {
    out.status = boundary.status;
    out.message = boundary.message;
    return out;
  }
  bool puncture_at_switch = false;
  out.puncture = find_puncture(p, options, shooting, switch_point, puncture_at_switch);
  double end_depth = curve.depths_mm.empty() ? curve.max_depth_mm : curve.depths_mm.back();
  if (end_depth <= 0.0) {
    if (!out.puncture.ok()) {
      // The puncture's own failure: physical when the membrane has no puncture point.
      out.status = out.puncture.status;
      out.message = "cannot end the curve at puncture: " + out.puncture.message;
      return out;
    }
    // A puncture at the switch is the sliding state at the switch depth (its own depth agrees
    // to the solver's accuracy): the curve ends with the switch.
    end_depth = puncture_at_switch ? boundary.depth_mm : out.puncture.depth_mm;
  }
  // A membrane that punctures as it starts sliding, where no sliding state at the switch depth
  // is reached (the puncture state lies shallower): the curve ends with the held state.
  const bool slides_in_curve =
      !(puncture_at_switch && out.puncture.ok() && out.puncture.stage == Stage::Stick);
  const bool has_switch = boundary.switches && boundary.depth_mm <= end_depth && slides_in_curve;
  if (has_switch) {
    out.stick_slip.occurs = true;
    out.stick_slip.depth_mm = boundary.depth_mm;
    out.stick_slip.force_stuck_n = boundary.force_stuck_n;
  }
  SlidingChange change = sliding_change(shooting, boundary, big_a);
  out.part_two_onset_depth_mm = change.depth_mm;
  out.part_two_onset_at_switch = change.at_switch;
  // At the switch: the sliding force there, set below.
  if (change.state) out.part_two_onset_force_n = change.state->f * scale;
  std::optional<ScaledSolution> found_change;
  if (!follow_curve(p,
                    shooting,
                    options.curve_tol,
                    boundary,
                    end_depth,
                    has_switch,
                    change.state,
                    curve,
                    out,
                    &found_change))
    return out;
  if (found_change) {  // found along the path: the energy's pieces end there too
    change.depth_mm = found_change->depth * big_a;
    change.state = std::move(found_change);
  }
  if (options.energy_to_puncture && out.puncture.ok())
    add_energy_to_puncture(
        p, shooting, options.curve_tol, boundary, change, puncture_at_switch, out.puncture);
  // Past the puncture depth the membrane has punctured, whatever its I1 does after a switch.
  if (out.puncture.ok())
    for (auto& pt : out.points)
      if (pt.depth_mm > out.puncture.depth_mm * (1.0 + 1e-9)) pt.beyond_puncture = true;
  if (out.part_two_onset_at_switch) {
    if (out.stick_slip.occurs)
      out.part_two_onset_force_n = out.stick_slip.force_sliding_n;
    else  // the curve ends before the switch
      out.part_two_onset_depth_mm.reset();
  }
  out.status = Status::Converged;
  return out;
}

}  // namespace puncture::detail
