#pragma once
// The ball's and the cone's own dimensions, and what their contact models do not solve yet
// (docs/model.md, §15.1, §15.2 and §15.5): part of validation_errors(Problem).
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <variant>
#include <vector>

#include "puncture/outcome.hpp"
#include "puncture/problem.hpp"

namespace puncture::detail {

inline void append_ball_errors(std::vector<ValidationError>& errors, const Ball& ball,
                               double clamp_radius_mm) {
  const double rb = ball.ball_radius_mm, rod = ball.radius_mm;
  if (!std::isfinite(rb) || !(rb > rod))
    errors.push_back({"indenter.ball_radius_mm",
                      fmt::format("ball radius must be a finite number larger than the rod's "
                                  "radius ({} mm), got {} mm",
                                  rod,
                                  rb)});
  else if (rb >= clamp_radius_mm)
    errors.push_back({"indenter.ball_radius_mm",
                      fmt::format("ball radius must be smaller than the clamp radius ({} mm): "
                                  "the ball must fit through the opening, got {} mm",
                                  clamp_radius_mm,
                                  rb)});
}

inline void append_cone_errors(std::vector<ValidationError>& errors, const Cone& cone) {
  const double alpha = cone.half_angle_deg, rt = cone.tip_radius_mm;
  const bool angle_ok = std::isfinite(alpha) && alpha > 0.0 && alpha < 90.0;
  if (!angle_ok)
    errors.push_back({"indenter.half_angle_deg",
                      fmt::format("cone half-angle (from the axis) must lie in (0, 90) degrees, "
                                  "got {}",
                                  alpha)});
  if (!std::isfinite(rt) || rt <= 0.0)
    errors.push_back({"indenter.tip_radius_mm",
                      fmt::format("tip radius must be a finite number > 0 mm (a sharp cone makes "
                                  "the stretch at its apex unbounded at a finite force), got {}",
                                  rt)});
  else if (angle_ok && std::isfinite(cone.radius_mm) && cone.radius_mm > 0.0) {
    // The tip sphere meets the cone at the radius RT cos(alpha): inside the shank.
    const double tangency_mm = rt * std::cos(alpha * std::numbers::pi / 180.0);
    if (tangency_mm > cone.radius_mm)
      errors.push_back({"indenter.tip_radius_mm",
                        fmt::format("tip radius {} mm meets a {} deg cone at radius {} mm, beyond "
                                    "the shank's {} mm: it must be <= {} mm",
                                    rt,
                                    alpha,
                                    tangency_mm,
                                    cone.radius_mm,
                                    cone.radius_mm / std::cos(alpha * std::numbers::pi / 180.0))});
  }
}

// The ball's and the cone's dimensions (both slide, or are held by a stick rule, §15.5).
inline void append_probe_shape_errors(std::vector<ValidationError>& errors, const Problem& p) {
  if (const auto* ball = std::get_if<Ball>(&p.indenter))
    append_ball_errors(errors, *ball, p.geometry.clamp_radius_mm);
  if (const auto* cone = std::get_if<Cone>(&p.indenter)) append_cone_errors(errors, *cone);
  // Held on the ball or the cone (docs/model.md §15.5, §17.3; the flat punch's own check covers
  // the fillet): from the flat membrane or the dome inflated at a held pressure; over a sealed
  // chamber the pressure changes along the history: not solved.
  const bool held_profile =
      std::holds_alternative<Ball>(p.indenter) || std::holds_alternative<Cone>(p.indenter);
  if (held_profile && p.stick.rule != StickRule::None && p.preload.gas_volume_mm3)
    errors.push_back({"stick.rule",
                      fmt::format("over a sealed gas chamber the {} is solved sliding only so "
                                  "far: stick rule must be 'none', got '{}'",
                                  describe(p.indenter),
                                  to_string(p.stick.rule))});
}

}  // namespace puncture::detail
