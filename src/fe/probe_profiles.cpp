// The smooth probes' profiles, as pieces of constant curvature from the pole.
#include "fe/probe_profiles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

#include "fe/piecewise_profile.hpp"
#include "fe/sphere_tipped_profile.hpp"

namespace puncture::fe {
namespace {

constexpr double kHalfPi = 0.5 * std::numbers::pi;
using Piece = PiecewiseProfile::Piece;

// The flat face of radius b = a - rho (zero curvature from the pole), the fillet of radius rho
// from the face's edge to its equator, then the cylinder side: curvature jumps at the face's
// edge and at the fillet's equator.
std::unique_ptr<RigidProfile> filleted(const FlatPunch& punch, double scale) {
  const double a = punch.radius_mm / scale, rho = punch.fillet_radius_mm / scale;
  const std::vector<Piece> pieces{{0.0, 0.0, a - rho, MembranePart::Tip},
                                  {1.0 / rho, 0.0, kHalfPi * rho, MembranePart::Tip},
                                  {0.0, kHalfPi, 0.0, MembranePart::Side}};
  return std::make_unique<PiecewiseProfile>(pieces, std::numeric_limits<double>::infinity(), "");
}

// The tip sphere of radius RT to the tangency (polar angle pi/2 - alpha), the cone to the
// shank's radius a, then the shank: a convex kink the contact may not pass (the shooting's
// model ends there too once the membrane would wrap the shank).
std::unique_ptr<RigidProfile> cone(const Cone& c, double scale) {
  const double a = c.radius_mm / scale, rt = c.tip_radius_mm / scale;
  const double tangency = kHalfPi - c.half_angle_deg * std::numbers::pi / 180.0;
  const double on_cone = (a - rt * std::sin(tangency)) / std::cos(tangency);
  std::vector<Piece> pieces{{1.0 / rt, 0.0, rt * tangency, MembranePart::Tip}};
  if (on_cone > 0.0) pieces.push_back({0.0, tangency, on_cone, MembranePart::Tip});
  pieces.push_back({0.0, kHalfPi, 0.0, MembranePart::Side});
  return std::make_unique<PiecewiseProfile>(
      pieces,
      rt * tangency + std::max(on_cone, 0.0),
      "the membrane would leave the cone's kink onto the shank (not modelled by the finite "
      "elements)");
}

// The ball of radius RB up to its equator, where the contact must stop (past it the membrane
// would wrap the upper half and neck onto the rod); for the gap, the upper half to the rod of
// radius a and the rod.
std::unique_ptr<RigidProfile> ball(const Ball& b, double scale) {
  const double rb = b.ball_radius_mm / scale, a = b.radius_mm / scale;
  const double top = std::numbers::pi - std::asin(a / rb);  // polar angle where the rod starts
  const std::vector<Piece> pieces{{1.0 / rb, 0.0, top * rb, MembranePart::Tip},
                                  {0.0, kHalfPi, 0.0, MembranePart::Side}};
  return std::make_unique<PiecewiseProfile>(
      pieces, kHalfPi * rb, "the contact would pass the ball's equator (outside the model)");
}

}  // namespace

std::unique_ptr<RigidProfile> sharp_punch_profile(const FlatPunch& punch, double scale) {
  const double a = punch.radius_mm / scale;
  const std::vector<Piece> pieces{{0.0, 0.0, a, MembranePart::Tip},
                                  {0.0, kHalfPi, 0.0, MembranePart::Side}};
  return std::make_unique<PiecewiseProfile>(pieces, std::numeric_limits<double>::infinity(), "");
}

std::unique_ptr<RigidProfile> smooth_profile(const Indenter& indenter, double scale) {
  if (const auto* sphere = std::get_if<SphereTipped>(&indenter))
    return std::make_unique<SphereTippedProfile>(sphere->radius_mm / scale);
  if (const auto* punch = std::get_if<FlatPunch>(&indenter))
    return punch->fillet_radius_mm > 0.0 ? filleted(*punch, scale) : nullptr;
  if (const auto* c = std::get_if<Cone>(&indenter)) return cone(*c, scale);
  return ball(std::get<Ball>(indenter), scale);
}

}  // namespace puncture::fe
