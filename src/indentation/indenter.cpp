#include "puncture/indenter.hpp"

#include <fmt/format.h>

namespace puncture {

namespace {

template <class... Shapes>
struct Overloaded : Shapes... {
  using Shapes::operator()...;
};
template <class... Shapes>
Overloaded(Shapes...) -> Overloaded<Shapes...>;

}  // namespace

double radius_mm(const Indenter& indenter) {
  return std::visit(Overloaded{[](const FlatPunch& p) { return p.radius_mm; },
                               [](const SphereTipped& p) { return p.radius_mm; },
                               [](const Ball& p) { return p.radius_mm; },
                               [](const Cone& p) { return p.radius_mm; }},
                    indenter);
}

std::string describe(const Indenter& indenter) {
  return std::visit(
      Overloaded{[](const FlatPunch& p) {
                   if (p.fillet_radius_mm > 0.0)
                     return fmt::format("flat punch, radius {:g} mm, corner fillet radius {:g} mm",
                                        p.radius_mm,
                                        p.fillet_radius_mm);
                   return fmt::format("flat punch, radius {:g} mm", p.radius_mm);
                 },
                 [](const SphereTipped& p) {
                   return fmt::format("sphere-tipped probe, radius {:g} mm", p.radius_mm);
                 },
                 [](const Ball& p) {
                   return fmt::format("ball, radius {:g} mm, on a rod of radius {:g} mm",
                                      p.ball_radius_mm,
                                      p.radius_mm);
                 },
                 [](const Cone& p) {
                   return fmt::format(
                       "cone, half-angle {:g} deg, tip radius {:g} mm, shank radius {:g} mm",
                       p.half_angle_deg,
                       p.tip_radius_mm,
                       p.radius_mm);
                 }},
      indenter);
}

bool sharp_flat_punch(const Indenter& indenter) {
  const auto* punch = std::get_if<FlatPunch>(&indenter);
  return punch && !(punch->fillet_radius_mm > 0.0);
}

}  // namespace puncture
