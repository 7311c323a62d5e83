#pragma once
// From the user's Problem to the solver: the material law and the indenter are chosen at run
// time (std::variant).  The indenter is dispatched here, once per solve, to the shooting for its
// contact model; the law travels as a RuntimeLaw, which picks the law at each stress evaluation
// (mechanics/runtime_law.hpp).  A new indenter adds its contact model here.
#include <numbers>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>

#include "indentation/contact/flat_punch.hpp"
#include "indentation/contact/sphere_tipped.hpp"
#include "indentation/inflated_dome.hpp"
#include "indentation/shooting.hpp"
#include "mechanics/runtime_law.hpp"
#include "puncture/options.hpp"
#include "puncture/problem.hpp"

namespace puncture::detail {

inline ShootingSettings shooting_settings(const SolverOptions& o, double prestretch = 1.0) {
  return {{o.integration_rel_tol, o.integration_abs_tol, o.max_steps},
          o.shooting_tol,
          o.max_shooting_iterations,
          o.field_points,
          prestretch};
}

// Each indenter shape (an alternative of Indenter): its contact model, and that model's settings
// from the problem.  A new shape adds one overload of each.
template <class Law>
FlatPunchContact<Law> contact_model_of(const FlatPunch&);  // declared for its type only
inline FlatPunchSettings contact_settings(const Problem& p, const FlatPunch& punch) {
  return {punch.radius_mm / reference_clamp_radius_mm(p), p.friction, p.part_two_equation};
}

template <class Law>
SphereTippedContact<Law> contact_model_of(const SphereTipped&);  // declared for its type only
inline SphereTippedSettings contact_settings(const Problem& p, const SphereTipped& probe) {
  return {probe.radius_mm / reference_clamp_radius_mm(p), p.friction};
}

// The flat punch with a rounded corner is the sphere-tipped model with a flat face of radius
// a - rho inside the arc (contact/sphere_tipped.hpp): chosen at run time by with_shooting, the
// sharp punch (rho = 0) keeps FlatPunchContact.
inline SphereTippedSettings filleted_settings(const Problem& p, const FlatPunch& punch) {
  const double length = reference_clamp_radius_mm(p);
  return {.a = punch.radius_mm / length,
          .mu = p.friction,
          .face = (punch.radius_mm - punch.fillet_radius_mm) / length};
}

// The ball is the sphere-tipped probe of its own radius up to its equator (the rod never
// touches before); the cone, its tip sphere followed by the cone up to the shank.
template <class Law>
SphereTippedContact<Law> contact_model_of(const Ball&);  // declared for its type only
inline SphereTippedSettings contact_settings(const Problem& p, const Ball& ball) {
  return {.a = ball.ball_radius_mm / reference_clamp_radius_mm(p),
          .mu = p.friction,
          .beyond = BeyondTipSphere::Neck};
}

template <class Law>
SphereTippedContact<Law> contact_model_of(const Cone&);  // declared for its type only
inline SphereTippedSettings contact_settings(const Problem& p, const Cone& cone) {
  const double unit = reference_clamp_radius_mm(p);
  return {.a = cone.tip_radius_mm / unit,
          .mu = p.friction,
          .beyond = BeyondTipSphere::Cone,
          .cone_half_angle = cone.half_angle_deg * std::numbers::pi / 180.0,
          .shank = cone.radius_mm / unit};
}

template <class Law, class Shape>
using ContactModelOf = decltype(contact_model_of<Law>(std::declval<const Shape&>()));

// fn(shooting) with the shooting of the problem's law and indenter; every indenter gives fn's
// result the same type.
// Under a gas pressure the membrane is inflated first (inflated_dome; a pressure it cannot hold
// throws PhysicalFailure, which reporting_failures turns into the result's status).
template <class Fn>
decltype(auto) with_shooting(const Problem& problem, const SolverOptions& options, Fn&& fn) {
  ShootingSettings settings = shooting_settings(options, problem.preload.prestretch);
  std::optional<ScaledSolution> dome_state;
  if (auto dome = inflated_dome(problem, options)) {
    settings.pressure = dome->pressure;
    settings.dome_height = dome->height;
    settings.dome_pole_stretch = dome->state.part_three_stretch;
    settings.dome_overhangs = overhangs_clamp(*dome);
    settings.dome_later_state = dome->later_state;
    dome_state = std::move(dome->state);
  }
  const RuntimeLaw law(problem.material.law);
  return std::visit(
      [&](const auto& shape) -> decltype(auto) {
        using Shape = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<Shape, FlatPunch>) {
          if (shape.fillet_radius_mm > 0.0) {
            const IndentationShooting<SphereTippedContact<RuntimeLaw>> shooting(
                law,
                settings,
                filleted_settings(problem, shape),
                options.record_fields,
                dome_state);
            return std::forward<Fn>(fn)(shooting);
          }
        }
        using Contact = ContactModelOf<RuntimeLaw, Shape>;
        const IndentationShooting<Contact> shooting(
            law, settings, contact_settings(problem, shape), options.record_fields, dome_state);
        return std::forward<Fn>(fn)(shooting);
      },
      problem.indenter);
}

}  // namespace puncture::detail
