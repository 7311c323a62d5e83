// The probes' meridians, for drawing them (include/puncture/indenter.hpp).
#include <cmath>
#include <numbers>

#include "puncture/indenter.hpp"

namespace puncture {

namespace {

constexpr int kChordsPerArc = 24;
constexpr double kHalfPi = std::numbers::pi / 2.0;

// An arc of radius rho about (r0, rho), polar angle t0 to t1 from the axis (t0's point included
// only when `first`).
void append_arc(std::vector<OutlinePoint>& out, double r0, double rho, double t0, double t1,
                bool first) {
  for (int k = first ? 0 : 1; k <= kChordsPerArc; ++k) {
    const double t = t0 + (t1 - t0) * k / kChordsPerArc;
    out.push_back({r0 + rho * std::sin(t), rho * (1.0 - std::cos(t))});
  }
}

}  // namespace

std::vector<OutlinePoint> outline(const Indenter& indenter) {
  std::vector<OutlinePoint> out;
  if (const auto* flat = std::get_if<FlatPunch>(&indenter)) {
    const double a = flat->radius_mm, rho = flat->fillet_radius_mm;
    out.push_back({0.0, 0.0});
    if (rho > 0.0)
      append_arc(out, a - rho, rho, 0.0, kHalfPi, true);
    else
      out.push_back({a, 0.0});
  } else if (const auto* sphere = std::get_if<SphereTipped>(&indenter)) {
    append_arc(out, 0.0, sphere->radius_mm, 0.0, kHalfPi, true);
  } else if (const auto* ball = std::get_if<Ball>(&indenter)) {
    // Over the equator to where the rod leaves the upper hemisphere.
    const double rb = ball->ball_radius_mm;
    append_arc(out, 0.0, rb, 0.0, std::numbers::pi - std::asin(ball->radius_mm / rb), true);
  } else if (const auto* cone = std::get_if<Cone>(&indenter)) {
    // The tip sphere to its tangency with the cone, then the cone's generatrix to the shank.
    const double alpha = cone->half_angle_deg * std::numbers::pi / 180.0;
    const double tangency = kHalfPi - alpha, rt = cone->tip_radius_mm;
    append_arc(out, 0.0, rt, 0.0, tangency, true);
    const auto at_tangency = out.back();
    out.push_back({cone->radius_mm,
                   at_tangency.height_mm + (cone->radius_mm - at_tangency.r_mm) / std::tan(alpha)});
  }
  return out;
}

}  // namespace puncture
