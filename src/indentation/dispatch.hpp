#pragma once
// From the user's Problem to the solver: the material law and the indenter are chosen at run
// time (std::variant) and dispatched here, once per solve, to the shooting for that law and that
// indenter's contact model.  A new indenter adds its contact model here.
#include <utility>
#include <variant>

#include "indentation/contact/flat_punch.hpp"
#include "indentation/shooting.hpp"
#include "puncture/options.hpp"
#include "puncture/problem.hpp"

namespace puncture::detail {

inline ShootingSettings shooting_settings(const SolverOptions& o) {
  return {{o.integration_rel_tol, o.integration_abs_tol, o.max_steps},
          o.shooting_tol,
          o.max_shooting_iterations,
          o.field_points};
}

inline FlatPunchSettings flat_punch_settings(const Problem& p) {
  return {
      p.geometry.indenter_radius_mm / p.geometry.clamp_radius_mm, p.friction, p.part_two_equation};
}

// fn(shooting) with the shooting of the problem's law and indenter; every law gives fn's result
// the same type.
template <class Fn>
decltype(auto) with_shooting(const Problem& problem, const SolverOptions& options, Fn&& fn) {
  const ShootingSettings settings = shooting_settings(options);
  const FlatPunchSettings punch = flat_punch_settings(problem);
  return std::visit(
      [&](const auto& law) -> decltype(auto) {
        using Law = std::decay_t<decltype(law)>;
        const IndentationShooting<FlatPunchContact<Law>> shooting(
            law, settings, punch, options.record_fields);
        return std::forward<Fn>(fn)(shooting);
      },
      problem.material.law);
}

}  // namespace puncture::detail
