#include "indentation/face_slip.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>
#include <vector>

#include "puncture/equilibrium.hpp"

namespace puncture::detail {
namespace {

// Part III's material in a state: reference radii R (increasing) and current radii r.
struct Face {
  std::vector<double> reference_mm, current_mm;
};

Face face_of(const Equilibrium& e) {
  Face out;
  const auto& m = e.fields;
  for (std::size_t i = 0; i < m.part.size(); ++i) {
    if (m.part[i] != MembranePart::Tip) continue;
    out.reference_mm.push_back(m.reference_radius_mm[i]);
    out.current_mm.push_back(m.radius_mm[i]);
  }
  return out;
}

// r at reference radius x, linear between samples (x inside them).
double radius_at(const Face& f, double x) {
  const auto it = std::upper_bound(f.reference_mm.begin(), f.reference_mm.end(), x);
  const std::size_t j = std::clamp<std::size_t>(
      static_cast<std::size_t>(it - f.reference_mm.begin()), 1, f.reference_mm.size() - 1);
  const double x0 = f.reference_mm[j - 1], x1 = f.reference_mm[j];
  const double t = x1 > x0 ? (x - x0) / (x1 - x0) : 0.0;
  return f.current_mm[j - 1] + t * (f.current_mm[j] - f.current_mm[j - 1]);
}

}  // namespace

bool face_friction_direction_matters(const Problem& p) {
  // A sealed chamber sealed flat (P = 0) is pressurised as soon as the probe presses it.
  return std::holds_alternative<FlatPunch>(p.indenter) &&
         (p.preload.pressure_mpa > 0.0 || p.preload.gas_volume_mm3) && p.friction > 0.0;
}

std::optional<FaceSlip> face_slip(const Problem& p, double depth_mm) {
  // 400 samples resolve the face; a step of 1e-3 of the depth (at least 1e-3 mm) moves its
  // material by far more than the interpolation error between them.
  SolverOptions options;
  options.field_points = 400;
  const double step = std::max(1e-3 * depth_mm, 1e-3);
  const auto a = solve_at_depth(p, depth_mm, Stage::Slip, options);
  const auto b = solve_at_depth(p, depth_mm + step, Stage::Slip, options);
  if (!a.ok() || !b.ok()) return std::nullopt;
  const Face fa = face_of(a), fb = face_of(b);
  if (fa.reference_mm.size() < 3 || fb.reference_mm.size() < 2) return std::nullopt;
  FaceSlip out{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (std::size_t i = 1; i < fa.reference_mm.size(); ++i) {  // the pole (i = 0) stays at 0
    if (fa.reference_mm[i] > fb.reference_mm.back()) break;
    const double slip = radius_at(fb, fa.reference_mm[i]) - fa.current_mm[i];
    out.least_mm = std::min(out.least_mm, slip);
    out.most_mm = std::max(out.most_mm, slip);
  }
  if (!std::isfinite(out.least_mm)) return std::nullopt;
  return out;
}

std::optional<std::string> inward_face_slip(const Problem& p, double depth_mm) {
  if (!face_friction_direction_matters(p)) return std::nullopt;
  const auto slip = face_slip(p, depth_mm);
  if (!slip || slip->least_mm > 0.0) return std::nullopt;
  return fmt::format(
      "at {:.6g} mm the membrane on the punch's face slides inward (toward the axis), where the "
      "model's friction under a gas pressure assumes it slides outward: this state is not the "
      "membrane's (docs/model.md §17)",
      depth_mm);
}

}  // namespace puncture::detail
