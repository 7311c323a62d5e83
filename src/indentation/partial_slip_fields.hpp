#pragma once
// The fields along the meridian of a partial-slip state (contact/partial_slip.hpp), centre
// outwards: the held face or pole at the first touch's stretch, the held core's grid points
// (their frozen stretches and tractions), the slipping annulus from the slip front to the
// contact's edge (Coulomb traction mu p), then Part I to the clamp.  The front and the edge appear
// on both sides (the core's and the annulus's, the annulus's and Part I's): the stretches are
// continuous there, the friction traction jumps at the front and vanishes past the edge.
#include <cmath>

#include "indentation/contact/partial_slip.hpp"
#include "indentation/membrane_fields.hpp"
#include "mechanics/field_point.hpp"
#include "puncture/membrane_fields.hpp"

namespace puncture::detail {

// Samples of the annulus between the front and the edge (its stretches vary smoothly).
inline constexpr int kPartialSlipAnnulusFieldSamples = 16;

// Appends the state's fields to `m`; false where the annulus or Part I cannot be re-solved.
// `depth_mm` is the state's depth (the deflections are measured from the clamp plane).
template <class Law>
bool append_partial_slip_fields(const PartialSlip<Law>& slip, const PartialSlipState& st,
                                const FieldScales& u, MembraneFields& m) {
  const auto& history = slip.history();
  const auto& part_one = slip.part_one();
  const auto& law = part_one.law();
  const HeldProfile& q = history.profile();
  const double big_a = u.clamp_radius_mm, g = u.shear_modulus_mpa;
  const double to_mpa = g * u.thickness_mm / big_a;  // tractions / (G H / A)
  const double depth = st.at_edge.depth * big_a;
  // A point on the profile at psi (reference radius r, stretches l1, l2).
  auto on_profile =
      [&](double r, double psi, double l1, double l2, double pressure, double friction) {
        append_point(m,
                     MembranePart::Tip,
                     r * big_a,
                     q.radius(psi) * big_a,
                     depth - q.height(psi) * big_a,
                     q.slope(psi),
                     l1,
                     l2,
                     membrane_stress(law, l1, l2),
                     g,
                     pressure * to_mpa,
                     friction * to_mpa);
      };
  // The first material touched: the pole (a sphere's), or the flat face's disc (held flat at its
  // stretch, pressed only by the gas).
  const double l0 = history.first_touch_stretch();
  const double start = history.start();
  if (start > 0.0) {
    for (const double r : {0.0, start})
      append_point(m,
                   MembranePart::Tip,
                   r * big_a,
                   l0 * r * big_a,
                   depth,
                   0.0,
                   l0,
                   l0,
                   membrane_stress(law, l0, l0),
                   g,
                   part_one.pressure() * to_mpa,
                   0.0);
  } else {
    const StuckTraction pole = history.traction_at(0.0, 0.0, l0, 0.0);
    on_profile(0.0, 0.0, l0, l0, pole.pressure, 0.0);
  }
  // The held core: its grid points strictly inside the front, then the front itself.
  const auto& pts = history.points();
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const StuckPoint& pt = pts[k];
    if (!(pt.r > start) || !(pt.r < st.front)) continue;
    const StuckTraction t = history.traction(k);
    on_profile(pt.r, pt.theta, pt.l1, q.radius(pt.theta) / pt.r, t.pressure, t.tangential);
  }
  const auto front_psi = history.psi_at(st.front);
  const auto front_l1 = history.stretch_at(st.front);
  if (!front_psi || !front_l1) return false;
  // The front's pressure from its stretches (the normal balance, as the annulus's: p is
  // continuous there), its frozen tangential traction interpolated between the grid points.
  const double front_pressure = history.traction_at(st.front, *front_psi, *front_l1, 0.0).pressure;
  on_profile(st.front,
             *front_psi,
             *front_l1,
             q.radius(*front_psi) / st.front,
             front_pressure,
             history.traction_near(st.front).tangential);
  // The annulus, from the front (its own side) to the edge: Coulomb slip, tau = mu p.
  for (int i = 0; i <= kPartialSlipAnnulusFieldSamples; ++i) {
    const double r = st.front + (st.edge - st.front) * i / kPartialSlipAnnulusFieldSamples;
    const auto at = slip.march(st.front, r);
    if (!at) return false;
    const auto [psi, l1] = *at;
    const double l2 = q.radius(psi) / r;
    const auto s = membrane_stress(law, l1, l2);
    const double p = slip.pressure(s.s1, s.s2, l1, l2, psi, q.on_cone(psi));
    on_profile(r, psi, l1, l2, p, slip.mu() * p);
  }
  // Part I from the edge to the clamp: its height from the edge, which lies the profile's height
  // above the tip.
  const auto free_start = slip.free_start(st.edge, st.at_edge.psi, st.at_edge.l1);
  if (!free_start) return false;
  std::vector<PartOneSample> samples;
  const auto run = part_one.run(st.at_edge.f, *free_start, &samples, false);
  if (!run.ok) return false;
  ScaledSolution sol;
  sol.f = st.at_edge.f;
  sol.depth = st.at_edge.depth;
  sol.part_one = std::move(samples);
  append_free_fields(law, sol, q.height(st.at_edge.psi), u, m, part_one.pressure());
  return true;
}

}  // namespace puncture::detail
