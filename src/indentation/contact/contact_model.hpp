#pragma once
// What the shooting asks of an indenter's contact model (the flat punch's is
// contact/flat_punch.hpp).  The shooting (indentation/shooting.hpp) integrates the free membrane,
// Part I, from where it leaves the indenter to the clamp and shoots on one parameter; everything
// about the indenter lives in the contact model:
//
//   using law_type; using Settings;          the material law; the contact's own settings
//   Contact(const FreePart<Law>&, const Settings&)
//   double parameter_floor(Configuration)    every shooting parameter of the configuration
//                                            exceeds it (the depth Newton works on p - floor)
//   std::optional<FreeStart> free_start(Configuration, f, p)
//                                            where and how Part I starts at force f and
//                                            parameter p; empty outside the material's domain
//   bool attach(Configuration, const FreeStart&, p, record, ScaledSolution&)
//                                            the parts in contact, after Part I was integrated:
//                                            their stretches, height and largest I1; false (with
//                                            status and message set) when they cannot be solved
//   optional: static constexpr bool kNoisyNearZeroLoad
//                                            the depth carries rounding noise beyond the curve's
//                                            tolerance near zero load: the curve's points may
//                                            end on it (follow_curve, kNoiseLimitedResidual)
//   optional, for depth control near a limit load (depth_newton.hpp); without them depth control
//   works on (f, p) alone:
//   bool contact_controls(Configuration)     whether contact_start gives that configuration
//   std::optional<FreeStart> contact_start(Configuration, q, p, record, ScaledSolution&)
//                                            the configuration given by a contact quantity q
//                                            and p, the force an output (set in the solution
//                                            with the parts in contact)
//   ShootingPlan plan(Stage, f, counted_residual)
//                                            which configuration the stage is in at force f and
//                                            the bracket of its parameter
//   ScaledSolution unloaded(bool record)     the state at zero force
//   Configuration configuration(Stage, bool past_change)
//                                            the configuration of a stage before / after the
//                                            change along the sliding branch (slip_change)
//   std::optional<ScaledSolution> slip_change(const Shooting&)
//                                            where the sliding configuration changes, if it does
//   std::optional<ScaledSolution> direct_puncture(const Shooting&, double critical_i1,
//                                                 std::optional<double> start)
//                                            a puncture solved directly, when the contact knows
//                                            one (else the loading path is searched); `start`:
//                                            a neighbouring problem's shooting parameter there
//                                            (SolverOptions::puncture_top_stretch_start)
//   std::string crack_location(const ScaledSolution&)   where the largest I1 is, in words
//   LargestFirstInvariant largest_first_invariant(const ScaledSolution&)
//                                            where the largest I1 is: part and radii
//   const Law& law()
//   void append_contact_fields(const ScaledSolution&, const FieldScales&, MembraneFields&)
//                                            the fields of the parts in contact, centre outwards
//   double free_part_inner_height(const ScaledSolution&)
//                                            how far Part I's inner end lies above the tip
//
// Adding an indenter: a contact model with these members, an alternative in the dispatch
// (indentation/dispatch.hpp); the shooting and the loading-curve driver are unchanged.
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "numerics/shooting.hpp"
#include "puncture/equilibrium.hpp"

namespace puncture::detail {

// Where the largest I1 of a state is (normalised radii).
struct LargestFirstInvariant {
  MembranePart part = MembranePart::Free;
  double reference_radius = 0.0;  // R / A
  double radius = 0.0;            // r / A
};

// How the shooting at one force proceeds: the configuration and a bracket start (lo, g_lo < 0)
// with an upper cap of the parameter, or why there is no shooting (status and message).
struct ShootingPlan {
  Status status = Status::Converged;
  std::string message;
  Configuration configuration = Configuration::Unloaded;
  double lo = 0.0;
  double g_lo = 0.0;
  double cap = std::numeric_limits<double>::infinity();
  std::optional<double> g_cap;  // the residual at the cap, when the plan has evaluated it
  double initial_step = 0.0;    // without a cap: the bracket's first step (0: 5% of lo)
  std::string no_root_message;  // what to say when the bracketing finds no root
  // g_lo is the stand-in of a Part I turned back (kTurnedBack) below a square-root branch point
  // the root lies just above, and g_cap is known: searched down from the cap through defined
  // residuals only (numerics/root_above_branch.hpp), as TOMS 748 interpolates badly to the
  // stand-in (the sphere-tipped probe near zero load).
  bool branch_below = false;
  bool ok() const { return status == Status::Converged; }
};

// Where the bracket on lambda2 at the top of the side contact (Part II) starts: at its floor a / A
// the top is at the clamp and the residual tends to a / A - 1 < 0, unless the probe is so small
// (a << A) that the material locks there; then tops from the cap downward, floor + (cap - floor)
// / 2^k, until the residual is negative.  {lo, g(lo)}; g(lo) >= 0 (or the beyond-domain stand-in)
// when no top below the cap has a negative residual.
template <class Residual>
std::pair<double, double> side_bracket_start(Residual& counted, double floor, double cap) {
  const double lowest = floor * (1.0 + 1e-9);
  if (const auto g_floor = counted(Configuration::SlipWithPartTwo, lowest))
    return {lowest, *g_floor};
  for (int k = 1; k <= 50; ++k) {
    const double p = floor + (cap - floor) / std::ldexp(1.0, k);
    if (const auto g = counted(Configuration::SlipWithPartTwo, p); g && *g < 0.0) return {p, *g};
  }
  return {lowest, kBeyondDomain};
}

// A plan for `configuration` whose parameter (a stretch > 1) is bracketed from below: the first
// of 1 + 2^-k (k = 1, 2, ...) with a negative clamp residual (a membrane too slack to reach the
// clamp).  The candidate before it, where the residual was >= 0, caps the bracket; without one
// the bracket grows from there in small steps (far above the root, a strongly stretched Part I
// may fail and its stand-in residual be negative again, so a cap at locking would not bracket).
// NoConvergence naming `what` when no candidate is negative.  For contacts under a gas pressure,
// where the unloaded membrane is not the flat one and no onset bounds the parameter.
template <class Residual>
ShootingPlan bracket_from_below(Residual& counted, Configuration configuration, const char* what) {
  ShootingPlan plan;
  plan.configuration = configuration;
  std::optional<double> g_above;  // the residual at the previous candidate
  for (int k = 1; k <= 60; ++k) {
    const double p = 1.0 + std::ldexp(1.0, -k);
    const auto g = counted(configuration, p);
    if (g && *g < 0.0) {
      plan.lo = p;
      plan.g_lo = *g;
      if (g_above) {
        plan.cap = 1.0 + std::ldexp(1.0, 1 - k);
        plan.g_cap = *g_above;
      } else {
        plan.initial_step = 0.05 * (p - 1.0);
      }
      plan.no_root_message = std::string(what) + " found no stretch meeting the clamp condition";
      return plan;
    }
    g_above = g;
  }
  plan.status = Status::NoConvergence;
  plan.message = std::string(what) + ": no stretch with a negative clamp residual";
  return plan;
}

// The force at which a contact changes configuration (slip_change): the first root of an
// onset indicator, negative at small forces, found by bracketing upward from a force far below
// any onset (1e-4 of the force scale, or `f_probe`: a loading path's last state before the
// change) with the given step.  Empty when the indicator is not negative there or no root is
// bracketed.
template <class Indicator>
std::optional<double> onset_force(Indicator&& indicator, int max_iterations, double step,
                                  double f_probe = 1e-4) {
  const auto g0 = indicator(f_probe);
  if (!g0 || *g0 >= 0.0) return std::nullopt;
  return shoot_increasing(
      indicator, f_probe, *g0, std::numeric_limits<double>::infinity(), max_iterations, step);
}

}  // namespace puncture::detail
