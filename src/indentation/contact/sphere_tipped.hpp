#pragma once
// The sphere-tipped probe: a cylinder of radius a ending in a hemisphere of the same radius; its
// contact model (contact_model.hpp), sliding.  Membrane parts (docs/model.md,
// "Sphere-tipped probe"):
//   the cap     the membrane lying on the hemisphere from the pole (R = 0) to the contact edge
//               (or to the equator); the pole is equibiaxial, the rest integrated outward in R
//   the side    once the contact passes the equator: the membrane on the cylinder, where without
//               friction R s1 = f is constant (the flat punch's Part II with mu = 0), with
//               friction d(R s1)/dR = mu s2 (the flat punch's Part II)
//   Part I      the free membrane, leaving the hemisphere tangentially at the contact edge, or
//               the side vertically
// Configurations and shooting parameters:
//   SlipWithoutPartTwo  contact on the hemisphere only; p = the pole's equibiaxial stretch
//   SlipWithPartTwo     contact past the equator; without friction p = lambda2 where Part I
//                       leaves the side (> a / A): the pole stretch is then fixed by the force
//                       alone, the cap carries f at the equator.  With friction p = the pole
//                       stretch, the side marched up from the equator (rough_side).
//   Stick               p = 1 / R_c, R_c the contact edge: each material point held where it
//                       touched (contact/profile_stick.hpp, every profile, under a held gas
//                       pressure too); on the fillet's face under a gas pressure p = t, the
//                       horizontal line tension where Part I leaves the held disc.
// Coulomb slip on the hemisphere and on the cylinder side (the membrane slides away from the
// pole; friction mu p points to it).
//
// The flat punch with a rounded corner (fillet radius rho < a, docs/model.md §19) is the same
// model with a flat face of radius b = a - rho before the arc (SphereTippedSettings::face): the
// face is Part III, uniform at the pole's stretch l (the parameter), and the arc of radius rho
// starts at its edge, R = b / l, with theta = 0 and lambda1 = l.  The hemisphere is b = 0.
#include <fmt/format.h>

#include <array>
#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "indentation/contact/contact_model.hpp"
#include "indentation/contact/fillet_face_under_gas.hpp"
#include "indentation/contact/flat_punch_side.hpp"
#include "indentation/contact/held_kink_pivot.hpp"
#include "indentation/contact/profile_stick.hpp"
#include "indentation/free_part.hpp"
#include "indentation/membrane_fields.hpp"
#include "mechanics/inverse_stretch.hpp"
#include "numerics/interior_maximum.hpp"
#include "numerics/root_in_bracket.hpp"
#include "numerics/shooting.hpp"

namespace puncture::detail {

// What follows the tip sphere (docs/model.md, §15): the sphere-tipped probe's cylinder side past
// the equator; nothing the model follows past the equator (a ball on a thinner rod: the membrane
// would neck above it, a status); or a cone tangent to the sphere up to a convex kink onto the
// shank (the membrane may leave the kink with a line force; wrapping the shank is a status).
enum class BeyondTipSphere { CylinderSide, Neck, Cone };

struct SphereTippedSettings {
  double a;   // tip (and cylinder) radius / stress-free clamp radius A / L0
  double mu;  // Coulomb friction coefficient (on the tip sphere and the cylinder side)
  // The flat punch with a rounded corner (docs/model.md §19) is this probe with a flat face of
  // radius b = a - rho inside an arc of radius rho: b / (A / L0); 0 for the hemisphere.
  double face = 0.0;
  BeyondTipSphere beyond = BeyondTipSphere::CylinderSide;
  double cone_half_angle = 0.0;  // the cone's half-angle from the axis [rad] (Cone only)
  double shank = 0.0;            // the shank's radius / (A / L0) (Cone only)
};

// The cap: the membrane on the hemisphere of radius a, state (theta, lambda1, e) along the
// reference radius R, theta the polar angle of the material point on the sphere (measured at the
// sphere's centre from the axis; it is also the meridian's slope), e = int W R dR the stored
// energy from the pole (/ (2 pi G H A^2)).  lambda2 = a sin(theta) / R.
//   dtheta/dR = lambda1 / a                            the meridian lies on the sphere
//   d(R s1)/dR = s2 cos(theta) + mu p r lambda1          tangential balance (Coulomb slip)
//   dlambda2/dR = (lambda1 cos(theta) - lambda2) / R    (from lambda2 = a sin(theta) / R)
// the second solved for lambda1' as in the free membrane (mechanics/free_membrane_ode.hpp).
using SphereCapState = std::array<double, 3>;

template <class Law>
struct SphereCapSystem {
  const Law& law;
  double a;
  double locking_i1;
  double mu = 0.0;  // Coulomb slip: the membrane slides away from the pole, friction points to it
  double pressure = 0.0;  // gas pressure P pressing the membrane onto the sphere (adds to p)
  // The filleted flat punch: the arc (radius a here: rho) starts at the flat face's edge, current
  // radius b + a sin(theta) (0 for the hemisphere).
  double face = 0.0;
  // Past this polar angle the profile is the cone tangent to the sphere there (infinity: the
  // sphere all along); x[0] is then the length along the profile from the pole over a.
  double tangency = std::numeric_limits<double>::infinity();
  // Which equations: the sphere's or the cone's by x[0], or one of them throughout (a march
  // integrates each part with its own, so that no stage of a step near the junction switches
  // between them: with friction the traction jumps there).
  enum class Part { ByPosition, Sphere, Cone } part = Part::ByPosition;

  void operator()(const SphereCapState& x, SphereCapState& dx, double r_ref) const {
    if (part == Part::Cone || (part == Part::ByPosition && x[0] > tangency))
      return on_cone(x, dx, r_ref);
    const double theta = x[0], l1 = x[1];
    const double l2 = (face + a * std::sin(theta)) / r_ref;
    if (!(l1 > 0.0) || !(l2 > 0.0)) return outside_domain(dx);
    const auto st = membrane_stress(law, l1, l2);
    if (!(st.i1 < locking_i1) || !(st.ds1_dl1 > 0.0) || !std::isfinite(st.ds1_dl1))
      return outside_domain(dx);
    const double dl2 = (l1 * std::cos(theta) - l2) / r_ref;
    dx[0] = l1 / a;
    // d(R s1)/dR = s2 cos(theta) + mu p r lambda1, p r lambda1 = sin(theta) (s1 l1 / l2 + s2 +
    // P a l1) (the contact pressure is Laplace's plus the gas pressure).
    // On the fillet p r lambda1 gains b (s1 lambda1 / (lambda2 rho) + P lambda1).
    const double tangential =
        mu == 0.0 ? std::cos(theta) * st.s2
                  : std::cos(theta) * st.s2 +
                        mu * std::sin(theta) * (st.s1 * l1 / l2 + st.s2 + pressure * a * l1) +
                        (face == 0.0 ? 0.0 : mu * face * (st.s1 * l1 / (l2 * a) + pressure * l1));
    dx[1] = (tangential - st.s1 - r_ref * st.ds1_dl2 * dl2) / (r_ref * st.ds1_dl1);
    dx[2] = strain_energy_density(law, l1, l2, st.i1) * r_ref;
  }

  // On the cone: a straight meridian at the slope `tangency`, r = a (sin(tangency) + (psi -
  // tangency) cos(tangency)); the meridian's curvature is 0, so the contact pressure is the hoop
  // tension's and the gas's, p r lambda1 = s2 sin(slope) + P r lambda1, and d(R s1)/dR = s2
  // (cos(slope) + mu sin(slope)) + mu P r lambda1 (docs/model.md, §15.2, §17).
  void on_cone(const SphereCapState& x, SphereCapState& dx, double r_ref) const {
    const double l1 = x[1], c = std::cos(tangency);
    const double l2 = a * (std::sin(tangency) + (x[0] - tangency) * c) / r_ref;
    if (!(l1 > 0.0) || !(l2 > 0.0)) return outside_domain(dx);
    const auto st = membrane_stress(law, l1, l2);
    if (!(st.i1 < locking_i1) || !(st.ds1_dl1 > 0.0) || !std::isfinite(st.ds1_dl1))
      return outside_domain(dx);
    const double dl2 = (l1 * c - l2) / r_ref;
    dx[0] = l1 / a;
    const double tangential =
        mu == 0.0         ? c * st.s2
        : pressure == 0.0 ? (c + mu * std::sin(tangency)) * st.s2
                          : (c + mu * std::sin(tangency)) * st.s2 + mu * pressure * l2 * r_ref * l1;
    dx[1] = (tangential - st.s1 - r_ref * st.ds1_dl2 * dl2) / (r_ref * st.ds1_dl1);
    dx[2] = strain_energy_density(law, l1, l2, st.i1) * r_ref;
  }
};

// The cap's state near the pole, from the series lambda1 = L + c R^2, lambda2 = L + e R^2,
// theta = (L R + c R^3 / 3) / a (docs/model.md): the O(R^2) balance of the tangential equation
// gives c = ((3 beta - alpha) L^3 - 3 s L^2) / (16 alpha a^2), e = c / 3 - L^3 / (6 a^2), with
// s, alpha = ds1/dlambda1 and beta = ds1/dlambda2 at the equibiaxial stretch L.  The state at R
// has an error O(R^4).
//
// With friction mu the slip traction adds mu (2 s L / a + P L^2) R to d(R s1)/dR at O(R) (the
// contact pressure at the pole is 2 s / (L a) + P, P the gas pressure): lambda1 gains b R,
// lambda2 b R / 2, with b = 2 mu (2 s L / a + P L^2) / (3 alpha); the O(R^2) terms would need the
// stresses' second derivatives, so the frictional start keeps the frictionless c and has an
// error O(R^2) (the cap then starts closer to the pole).
template <class Law>
SphereCapState sphere_cap_pole_state(const Law& law, double a, double l, double r_ref,
                                     double mu = 0.0, double pressure = 0.0) {
  const auto st = membrane_stress(law, l, l);
  const double alpha = st.ds1_dl1, beta = st.ds1_dl2, s = st.s1;
  const double c = ((3.0 * beta - alpha) * l * l * l - 3.0 * s * l * l) / (16.0 * alpha * a * a);
  const double w = strain_energy_density(law, l, l, st.i1);
  if (mu != 0.0) {
    const double b = pressure == 0.0
                         ? 4.0 * mu * s * l / (3.0 * alpha * a)
                         : 2.0 * mu * (2.0 * s * l / a + pressure * l * l) / (3.0 * alpha);
    return {(l * r_ref + 0.5 * b * r_ref * r_ref + c * r_ref * r_ref * r_ref / 3.0) / a,
            l + b * r_ref + c * r_ref * r_ref,
            0.5 * w * r_ref * r_ref};
  }
  // W R integrated from the pole: W(L, L) R^2 / 2 to the order of the start (W varies as R^2).
  return {(l * r_ref + c * r_ref * r_ref * r_ref / 3.0) / a,
          l + c * r_ref * r_ref,
          0.5 * w * r_ref * r_ref};
}

// The samples of the parts in contact, stored in ScaledSolution::part_two, centre outwards:
// (R, lambda1, psi) with psi = (length along the probe's profile from the pole) / a, so psi =
// theta <= pi/2 on the hemisphere and psi = pi/2 + (height above the equator) / a on the side.

template <class Law>
class SphereTippedContact {
 public:
  using law_type = Law;
  using Settings = SphereTippedSettings;

  SphereTippedContact(const FreePart<Law>& part_one, const SphereTippedSettings& settings)
      : part_one_(part_one),
        law_(part_one.law()),
        s_(settings),
        locking_i1_(part_one.locking_i1()),
        pressure_(part_one.pressure()),
        tangency_(cone() ? kHalfPiCap - settings.cone_half_angle : kHalfPiCap),
        side_radius_(cone() ? settings.shank : settings.a),
        end_psi_(cone() ? tangency_ + (settings.shank - settings.a * std::sin(tangency_)) /
                                          (settings.a * std::cos(tangency_))
                        : kHalfPiCap),
        held_profile_(std::make_shared<ProfileStickHistory<Law>>(part_one, held_profile())) {}

  // The stick stage's history (contact/profile_stick.hpp; built on first use, shared by copies
  // of the contact).
  const ProfileStickHistory<Law>& held_profile_history() const { return *held_profile_; }
  // Past that history's end at the cone's kink: the held membrane pivoting over it.
  HeldKinkPivot<Law> kink_pivot() const { return {*held_profile_, law_}; }

  // The pole stretch exceeds 1 (and 1 / R_c held); held on the fillet's face under a gas
  // pressure the parameter is a line tension t > 0, as on the sharp punch's held face.
  double parameter_floor(Configuration c) const {
    return c == Configuration::Stick && held_profile_->face_map() ? 0.0 : 1.0;
  }
  // Near zero load the pole strain p - 1 (2.7e-4 at the first point of the 2 mm probe's
  // 200-point curve) is held in stretches near 1: the cap's edge, and with it the depth, carry
  // ~1e-8 of rounding noise there (bench/README.md), and the curve's points may end on it.
  static constexpr bool kNoisyNearZeroLoad = true;

  // Where the cap ends, marched from the pole with pole stretch `l` (the parameter).
  struct CapEnd {
    bool at_equator = false;  // the contact reached theta = pi/2 before carrying the force
    double r = 0.0;           // reference radius of the contact edge (or of the equator)
    SphereCapState state{};
    double vertical = 0.0;    // R s1 sin(theta) there: the membrane's vertical pull
    double carried = 0.0;     // ... plus the gas pressure on the cap: the force the cap carries
    double pull = 0.0;        // R s1 there (cone): the most a vertical exit over the kink can carry
    double wrinkle_r = -1.0;  // where the hoop stress first turns compressive (with i1_max):
    double wrinkle_radius = -1.0;  // reference and current radius
  };

  // The cap from the pole until it carries the force f (R s1 sin(theta) + P r^2 / 2 = f: the
  // contact edge; the gas pressure on the cap helps the membrane hold the probe) or reaches the
  // equator (f = infinity: always the equator).  With `samples`, the cap is
  // sampled (R, lambda1, theta); with `i1_max`, I1 is tracked along it.  Empty outside the
  // material's domain.
  std::optional<CapEnd> march(double l, double f, std::vector<PartTwoSample>* samples = nullptr,
                              InteriorMaximum<SphereCapState>* i1_max = nullptr) const {
    if (!(l > 0.0) || !std::isfinite(l) || !(first_invariant(l, l) < locking_i1_))
      return std::nullopt;
    // The sphere's equations first (the cone's march switches to the cone's at the junction).
    auto cap = cap_system(cone() ? SphereCapSystem<Law>::Part::Sphere
                                 : SphereCapSystem<Law>::Part::ByPosition);
    // theta = kPoleStart there (closer with friction: that start is exact to O(R^2) only; the
    // neglected terms are O((mu theta)^2) ~ 1e-10 mu^2 relative at theta = 1e-5).  With a flat
    // face the arc starts at its edge, R = b / l, with the face's uniform state.
    double r_start =
        s_.face > 0.0 ? s_.face / l : (s_.mu == 0.0 ? kPoleStart : kPoleStartFriction) * s_.a / l;
    if (!(r_start < 1.0)) return std::nullopt;  // the face's edge must lie inside the clamp
    SphereCapState y = s_.face > 0.0
                           ? face_edge_state(l, r_start)
                           : sphere_cap_pole_state(law_, s_.a, l, r_start, s_.mu, pressure_);
    // Under a gas pressure with friction the face is not uniform: marched from the pole.
    std::vector<PartTwoSample> face_samples;
    if (fillet_face().rough()) {
      const auto e =
          fillet_face().march(l, s_.face, samples ? &face_samples : nullptr, face_points());
      if (!e) return std::nullopt;
      r_start = e->r_ref;
      y = {0.0, e->l1, e->energy};
    }
    auto vertical = [&](double r, const SphereCapState& x) {
      return r * membrane_stress(law_, x[1], radius_at(x[0]) / r).s1 * std::sin(slope_at(x[0]));
    };
    auto carried = [&](double r, const SphereCapState& x) {
      return pressure_ == 0.0 ? vertical(r, x) : vertical(r, x) + gas_load(x[0]);
    };
    auto crossed = [&](double r, const SphereCapState& x) {
      return x[0] >= end_psi_ || carried(r, x) >= f;
    };
    double r_prev = r_start, r_hit = -1.0, wrinkle_r = -1.0, wrinkle_radius = -1.0;
    SphereCapState y_prev = y, y_hit = y;
    IntegrationSettings integration = part_one_.settings().integration;
    if (samples) {
      const int n = std::max(1, part_one_.settings().field_points);
      integration.max_step = arc() / n;
    }
    if (samples && fillet_face().rough()) {
      *samples = std::move(face_samples);
    } else if (samples) {
      samples->clear();
      samples->push_back({0.0, l, 0.0});
      for (int k = 1; k < (s_.face > 0.0 ? kFacePoints : 0); ++k)  // the face, uniform
        samples->push_back({r_start * k / kFacePoints, l, 0.0});
    }
    // Inside the last step: the contact edge if the force is carried before the equator, else
    // the equator.  Trials re-take one step from the last accepted state; one that leaves the
    // material's domain counts as past the event.
    const auto at = [&](double r) {
      return step_or_advance(cap, y_prev, r_prev, r, part_one_.settings().integration);
    };
    // The root of event in (r_prev, r_end], negative at r_prev and >= 0 at r_end (states given):
    // Newton's method kept inside the bracket (Boost's newton_raphson_iterate, with the event's
    // derivative along the cap), or TOMS 748 if a trial leaves the material's domain or Newton
    // gives up.
    struct Event {
      double value;
      double slope;
    };
    auto locate = [&](auto&& event,
                      double r_end,
                      const SphereCapState& y_end,
                      SphereCapState& y_root) -> std::optional<double> {
      const double g_prev = event(r_prev, y_prev).value, g_end = event(r_end, y_end).value;
      y_root = y_prev;
      if (g_prev >= 0.0) return r_prev;
      y_root = y_end;
      if (!(g_end >= 0.0)) return std::nullopt;
      if (g_end == 0.0) return r_end;
      double r_root = 0.0;
      try {
        std::uintmax_t iterations = 60;
        r_root = boost::math::tools::newton_raphson_iterate(
            [&](double r) {
              const auto x = at(r);
              if (!x) throw IntegrationFailure{};
              const Event e = event(r, *x);
              return std::make_pair(e.value, e.slope);
            },
            r_prev + (r_end - r_prev) * g_prev / (g_prev - g_end),
            r_prev,
            r_end,
            50,
            iterations);
      } catch (...) {  // IntegrationFailure, or Boost's evaluation_error (no root seen)
        auto g = [&](double r) {
          const auto x = at(r);
          return x ? event(r, *x).value : 1.0;
        };
        r_root = root_in_bracket(g, r_prev, r_end, g_prev, g_end);
      }
      const auto x = at(r_root);
      if (!x) return std::nullopt;
      y_root = *x;
      return r_root;
    };
    const auto equator = [&](double, const SphereCapState& x) {
      return Event{x[0] - end_psi_, x[1] / arc()};
    };
    // V = R s1 sin(theta) + P (a sin(theta))^2 / 2 - f, with dV/dR = cos(theta) (s2 sin(theta)
    // + R s1 lambda1 / a + P a sin(theta) lambda1) and, with friction, + mu sin(theta)^2 (s1
    // lambda1 / lambda2 + s2 + P a lambda1).  On the fillet (arc radius rho, current radius r):
    // dV/dR = cos(theta) (s2 sin(theta) + R s1 lambda1 / rho + P r lambda1) + mu sin(theta)
    // p r lambda1.
    const auto edge = [&](double r, const SphereCapState& x) {
      if (cone() && x[0] > tangency_) {  // on the cone: V = R s1 sin(slope) (+ P r^2 / 2)
        const auto st = membrane_stress(law_, x[1], radius_at(x[0]) / r);
        const double c = std::cos(tangency_), sn = std::sin(tangency_);
        if (pressure_ > 0.0) {  // dV/dR = sin(slope) d(R s1)/dR + P r lambda1 cos(slope)
          const double gas = pressure_ * radius_at(x[0]) * x[1];
          return Event{r * st.s1 * sn + gas_load(x[0]) - f,
                       sn * ((c + s_.mu * sn) * st.s2 + s_.mu * gas) + c * gas};
        }
        return Event{r * st.s1 * sn - f, sn * (c + s_.mu * sn) * st.s2};
      }
      const double l2 = radius_at(x[0]) / r;
      const auto st = membrane_stress(law_, x[1], l2);
      const double c = std::cos(x[0]), sn = std::sin(x[0]);
      if (s_.face > 0.0) {
        const double rho = arc(), radius = arc_radius_at(x[0]);
        const double traction = sn * (st.s1 * x[1] / l2 + st.s2 + pressure_ * rho * x[1]) +
                                s_.face * (st.s1 * x[1] / (l2 * rho) + pressure_ * x[1]);
        return Event{r * st.s1 * sn + gas_load(x[0]) - f,
                     c * (st.s2 * sn + r * st.s1 * x[1] / rho + pressure_ * radius * x[1]) +
                         s_.mu * sn * traction};
      }
      const double gas = pressure_ * s_.a * x[1];
      const double friction = s_.mu * sn * sn * (st.s1 * x[1] / l2 + st.s2 + gas);
      return Event{r * st.s1 * sn + gas_load(x[0]) - f,
                   c * (st.s2 * sn + r * st.s1 * x[1] / s_.a + gas * sn) + friction};
    };
    // The cone's march stops first where the tip sphere meets the cone and restarts there, so
    // that no step (nor a trial step locating an event) spans the jump of the meridian's
    // curvature, which would cost the steps their order.
    bool to_tangency = cone() && tangency_ < end_psi_;
    double r_from = r_start;
    const auto run = [&]() {
      r_hit = -1.0;
      return integrate_part(cap, y, r_from, 1.0, integration, [&](double r, const auto& x) {
        if (r > r_from && (crossed(r, x) || (to_tangency && x[0] >= tangency_))) {
          r_hit = r;
          y_hit = x;
          return false;
        }
        r_prev = r;
        y_prev = x;
        if (samples) samples->push_back({r, x[1], x[0]});
        if (i1_max) {
          const double l2 = radius_at(x[0]) / r;
          i1_max->observe(r, x, first_invariant(x[1], l2));
          if (wrinkle_r < 0.0 && hoop_compressive(x[1], l2)) {
            wrinkle_r = r;
            wrinkle_radius = l2 * r;
          }
        }
        return true;
      });
    };
    if (!run() || r_hit < 0.0) return std::nullopt;
    if (to_tangency && y_hit[0] >= tangency_) {
      // At the junction: the edge lies on the sphere if the force is carried there already,
      // else the march goes on along the cone from the junction.
      const auto junction = [&](double, const SphereCapState& x) {
        return Event{x[0] - tangency_, x[1] / s_.a};
      };
      SphereCapState y_junction;
      const auto r_junction = locate(junction, r_hit, y_hit, y_junction);
      if (!r_junction) return std::nullopt;
      if (carried(*r_junction, y_junction) >= f) {
        r_hit = *r_junction;
        y_hit = y_junction;
      } else {
        to_tangency = false;
        cap.part = SphereCapSystem<Law>::Part::Cone;
        r_from = *r_junction;
        y = y_junction;
        if (!run() || r_hit < 0.0) return std::nullopt;
      }
    }
    // The search ends at the equator if the step passes it (R s1 sin(theta) peaks there: dV/dR
    // carries a factor cos(theta)); the force is carried before the equator if V reaches f by
    // the search's end.
    double r_stop = r_hit;
    SphereCapState y_stop = y_hit;
    if (y_hit[0] >= end_psi_) {
      const auto r_equator = locate(equator, r_hit, y_hit, y_stop);
      if (!r_equator) return std::nullopt;
      r_stop = *r_equator;
    }
    std::optional<double> r_end = r_stop;
    std::optional<SphereCapState> y_end = y_stop;
    CapEnd end;
    end.at_equator = true;
    if (std::isfinite(f) && carried(r_stop, y_stop) >= f) {
      SphereCapState y_edge;
      r_end = locate(edge, r_stop, y_stop, y_edge);
      if (!r_end) return std::nullopt;
      y_end = y_edge;
      end.at_equator = false;
    }
    end.r = *r_end;
    end.state = *y_end;
    end.vertical = vertical(end.r, end.state);
    end.carried = carried(end.r, end.state);
    end.pull = cone()
                   ? end.r * membrane_stress(law_, end.state[1], radius_at(end.state[0]) / end.r).s1
                   : end.vertical;
    end.wrinkle_r = wrinkle_r;
    end.wrinkle_radius = wrinkle_radius;
    if (samples) samples->push_back({end.r, end.state[1], end.state[0]});
    if (i1_max)
      i1_max->observe(
          end.r, end.state, first_invariant(end.state[1], radius_at(end.state[0]) / end.r));
    return end;
  }

  std::optional<FreeStart> free_start(Configuration c, double f, double p) const {
    if (!(p > 0.0) || !std::isfinite(p)) return std::nullopt;
    if (c == Configuration::SlipWithPartTwo) {
      if (rough_side_solved()) {
        const auto side = rough_side(p, f, [](double, const PartTwoState&) {});
        return side ? std::optional<FreeStart>(side->start) : std::nullopt;
      }
      if (s_.mu != 0.0) return std::nullopt;  // the ball and the cone: no side (a status)
      return side_top_start(f, p);
    }
    if (c == Configuration::Stick && kink_pivot().pivoting(p)) return kink_pivot().start(p, f);
    if (c == Configuration::Stick)
      return held_on_face(f) ? held_face_start(f, p) : held_profile_->edge_start(1.0 / p, f);
    if (c != Configuration::SlipWithoutPartTwo) return std::nullopt;
    if (fillet_face().on_face(f)) return fillet_face().start(f, p);
    const auto& cap = cap_to_edge(p, f);
    if (!cap) return std::nullopt;
    const auto* end = &cap->end;
    if (end->at_equator && cone()) return kink_start(*end, f);
    if (end->at_equator) {
      // Carried only at the equator: a vertical exit when the force is met there to round-off
      // (the lower end of the shooting bracket), else the contact would wrap the side.
      if (!(end->carried >= f * (1.0 - 1e-9))) return std::nullopt;
      return vertical_start(*end);
    }
    return edge_start(*end);
  }

  // The parts in contact once Part I is integrated from `st`: the cap re-marched from the pole
  // (its largest I1, samples and height) and, past the equator, the side down from Part I's start
  // to the equator.  Without `maxima` the largest I1 of the parts in contact is the sampled one
  // (a lower bound, for the iterations of a search that assembles its end again).
  bool attach(Configuration c, const FreeStart& st, double p, bool record, ScaledSolution& sol,
              bool maxima = true) const {
    if (c == Configuration::SlipWithPartTwo)
      return rough_side_solved() ? attach_rough_side(p, record, sol, maxima)
                                 : attach_with_side(st, record, sol, maxima);
    if (c == Configuration::Stick) {
      if (held_on_face(sol.f))
        attach_held_fillet_face(*held_profile_, law_, st, record, sol);
      else
        attach_held_profile(*held_profile_, law_, st, record, sol);
      if (kink_pivot().pivoting(p)) kink_pivot().attach(st, record, sol);
      // The pole holds as it touched (the dome's pole stretch under a gas pressure).
      sol.part_three_stretch = held_profile_->first_touch_stretch();
      return true;
    }
    if (fillet_face().on_face(sol.f))  // under a gas pressure, the fillet's face alone
      return fillet_face().attach(st, p, record ? face_points() : 0, sol);
    // The free start's march (its steps and I1 the same), unless the cap is sampled: then it is
    // marched again in shorter steps.
    std::optional<CapEnd> end;
    InteriorMaximum<SphereCapState> i1_max;
    if (record) {
      end = march(p, sol.f, &sol.part_two, &i1_max);
    } else if (const auto& cap = cap_to_edge(p, sol.f)) {
      end = cap->end;
      i1_max = cap->i1_max;
    }
    // Recorded, the cap is marched in shorter steps: its edge moves by the integration's error,
    // and an edge just short of the equator may be met at it (carrying f there to that error).
    const bool edge_at_equator = end && end->at_equator && end->carried >= sol.f * (1.0 - 1e-7);
    const bool kink_exit =
        cone() && end && end->at_equator && capacity(*end) >= sol.f * (1.0 - 1e-7);
    if (!end || (end->at_equator && st.slope != kHalfPiCap && !edge_at_equator && !kink_exit)) {
      sol.status = Status::NoConvergence;
      sol.message = "the contact edge on the sphere could not be located again";
      return false;
    }
    track_cap_maximum(i1_max, sol, maxima);
    if (end->wrinkle_r >= 0.0) {  // on the cap, inside Part I: the first
      sol.wrinkle_r = end->wrinkle_r;
      sol.wrinkle_radius = end->wrinkle_radius;
    }
    sol.r_corner = st.r0;
    sol.part_three_stretch = p;  // the pole's equibiaxial stretch (max_first_invariant_of)
    if (cone()) {
      sol.tension_ratio = st.ratio;  // the capstan factor over the kink (1 elsewhere)
      // The membrane on the cone, from the tangency to Part I's start (reported as Part II's
      // length): from Part I's current inner radius.
      const double on_cone =
          (st.state[2] * st.r0 - s_.a * std::sin(tangency_)) / std::cos(tangency_);
      sol.part_two_length = std::clamp(on_cone, 0.0, s_.a * (end_psi_ - tangency_));
      sol.depth += free_part_inner_height_on_cone(st.slope, sol.part_two_length);
    } else {
      sol.depth += cap_height(st.slope);
      sol.tension_ratio = 1.0;
    }
    return true;
  }

  template <class Residual>
  ShootingPlan plan(Stage stage, double f, Residual&& counted) const {
    ShootingPlan plan;
    plan.configuration = Configuration::SlipWithoutPartTwo;
    if (stage == Stage::Stick && held_on_face(f))
      return held_face_tension_plan(*held_profile_->face_map(), f, pressure_, counted);
    if (stage == Stage::Stick) return held_plan(f, counted);
    if (fillet_face().on_face(f))  // under a gas pressure, the fillet's face alone
      return bracket_from_below(counted,
                                Configuration::SlipWithoutPartTwo,
                                "filleted flat-punch shooting on the face under pressure");
    // The pole stretch at which the cap carries f exactly at the equator, and the clamp residual
    // of Part I leaving the equator vertically there: negative while the contact stays on the
    // hemisphere, >= 0 once it wraps the cylinder side.
    const auto onset = equator_onset(f);
    if (!onset && pressure_ > 0.0 && f <= end_gas_load()) return hemisphere_plan(f, counted);
    // A large probe (a above ~2 A / pi: 16.7 mm on A = 25 mm) puts its equator past the clamp
    // for the barely stretched membrane, and no cap reaching it inside the clamp carries just f
    // there: no onset, yet no locking either.  The contact ends on the hemisphere.
    if (!onset && !march(1.0 + kBarelyStretched, std::numeric_limits<double>::infinity()))
      return edge_on_cap_plan(f, lowest_carrying_stretch(f), kBeyondDomain, counted);
    if (!onset && !std::isfinite(locking_i1_)) return beyond_cap_capacity_plan(counted);
    if (!onset) {
      plan.status = Status::BeyondLocking;
      plan.message = cone() ? "no pole stretch lets the cone probe's tip and cone carry this force "
                              "before the material locks"
                            : "no pole stretch lets the sphere-tipped probe carry this force "
                              "before the material locks";
      return plan;
    }
    const auto indicator = side_indicator(f, *onset);
    if (indicator) keep_side_bracket(f, *indicator);
    // Under pressure a vertical exit at the equator with a pull of nearly nothing (f just above
    // the gas's share P a^2 / 2) cannot be integrated at all (the gas curls the slack membrane):
    // that is no sign of a side contact, and the cap ends on the hemisphere.
    if (!indicator && pressure_ > 0.0) return hemisphere_plan(f, counted);
    const double g_onset = indicator.value_or(kBeyondDomain);
    // Where the model ends (the ball's equator, the cone's shank), Part I leaving nearly
    // vertically makes the residual grow as the square root of the pole stretch's distance from
    // the onset's (t = sqrt(N^2 - f^2) at the kink; V stationary at the equator), and a root within
    // 1e-5 of the residual there (forces within ~2e-6 of the onset) is not resolved in doubles
    // (docs/model.md, §15.1): counted as past the onset.
    if (s_.beyond != BeyondTipSphere::CylinderSide && g_onset >= -kEndResidualMargin) {
      plan.configuration = Configuration::SlipWithPartTwo;
      plan.status = Status::OutsideModel;
      plan.message = s_.beyond == BeyondTipSphere::Neck ? kNeckNotSolved : kShankNotSolved;
      return plan;
    }
    if (g_onset >= 0.0 && rough_side_solved()) return rough_side_plan(*onset, g_onset, counted);
    if (g_onset >= 0.0) {
      // The side exists: shoot on lambda2 where Part I leaves it, between a / A (the top at the
      // clamp, residual a / A - 1 < 0) and the equator's lambda2.
      plan.configuration = Configuration::SlipWithPartTwo;
      // (A small probe's top at the clamp is past locking: side_bracket_start.)
      const double cap = s_.a / onset->end.r;
      const auto [lowest, g_low] = side_bracket_start(counted, s_.a, cap);
      if (!(g_low < 0.0)) {
        plan.status = Status::BeyondLocking;
        plan.message = "the force is beyond what the membrane on the sphere-tipped probe can carry";
        return plan;
      }
      plan.lo = lowest;
      plan.g_lo = g_low;
      plan.cap = cap;
      plan.no_root_message =
          "sphere-tipped shooting (contact on the side) found no top stretch meeting the clamp "
          "condition";
      return plan;
    }
    return edge_on_cap_plan(f, onset->stretch, g_onset, counted);
  }

  // A law without locking: the cap's pull at the equator grows with the pole stretch towards a
  // bound (the neo-Hookean sphere-tipped probe of 2 mm: 0.195086 N with mu' = 0.18, the limit load
  // 2 pi G H a = 0.150796 N without friction), and a force beyond it is carried at no pole
  // stretch's equator (docs/model.md §8.1).  With friction on the side the side carries the rest
  // (its top rises until R s1 = f): shot on the pole stretch from below.  Without it R s1 = f
  // down the side cannot meet the cap's pull: the force is beyond the limit load.  The ball and
  // the cone would wrap what the model does not follow.
  template <class Residual>
  ShootingPlan beyond_cap_capacity_plan(Residual& counted) const {
    if (s_.beyond == BeyondTipSphere::CylinderSide && rough_side_solved())
      return bracket_from_below(counted,
                                Configuration::SlipWithPartTwo,
                                s_.face > 0.0 ? "filleted flat-punch shooting (side with friction, "
                                                "beyond the arc's pull at the equator)"
                                              : "sphere-tipped shooting (side with friction, "
                                                "beyond the cap's pull at the equator)");
    ShootingPlan plan;
    plan.configuration = Configuration::SlipWithPartTwo;
    if (s_.beyond != BeyondTipSphere::CylinderSide) {
      plan.status = Status::OutsideModel;
      plan.message = s_.beyond == BeyondTipSphere::Neck ? kNeckNotSolved : kShankNotSolved;
      return plan;
    }
    plan.status = Status::LimitLoad;
    plan.message = fmt::format(
        "the force is beyond the limit load of the {}: without friction on its side the membrane "
        "carries at most the cap's pull at the equator, which tends to a bound as the pole "
        "stretch grows without limit (the material never locks)",
        s_.face > 0.0 ? "filleted flat punch" : "sphere-tipped probe");
    return plan;
  }

  // A pole stretch a little above 1: its cap reaches the equator inside the clamp unless the
  // probe is large.
  static constexpr double kBarelyStretched = 1e-6;

  // The smallest of the pole stretches 1 + 2^k kBarelyStretched whose cap carries f inside the
  // clamp, before the equator (the large probe's); 0 if none does before the material locks.
  double lowest_carrying_stretch(double f) const {
    for (int k = 0; k < 60; ++k) {
      const double l = 1.0 + std::ldexp(kBarelyStretched, k);
      if (!(first_invariant(l, l) < locking_i1_)) break;
      const auto end = march(l, f);
      if (end && !end->at_equator) return l;
    }
    return 0.0;
  }

  // The contact ends on the hemisphere.  The shooting needs a pole stretch whose cap carries f
  // before the equator with a negative clamp residual: `top` (the onset's, with residual
  // g_top), unless R s1 sin(theta) peaks on the way (the hoop stretch falls below 1 towards the
  // equator at small stretches) and reaches f earlier.  Then stretches 1 + (top - 1) / 2^k are
  // tried downward: any carrying one with a negative residual lies below the root and will do;
  // past the lowest carrying stretch, a bisection on whether the force is carried before the
  // equator finds it.
  template <class Residual>
  ShootingPlan edge_on_cap_plan(double f, double top, double g_top, Residual& counted) const {
    ShootingPlan plan;
    plan.configuration = Configuration::SlipWithoutPartTwo;
    if (!(top > 1.0)) {
      plan.status = std::isfinite(locking_i1_) ? Status::BeyondLocking : Status::NoConvergence;
      plan.message = std::isfinite(locking_i1_)
                         ? "no pole stretch lets the sphere-tipped probe carry this force before "
                           "the material locks"
                         : "no pole stretch the cap can be marched at lets the sphere-tipped probe "
                           "carry this force on its hemisphere";
      return plan;
    }
    double hi = top;
    double g_hi = g_top;
    // (The free start's march at (l, f), kept for the residual that may follow: cap_to_edge.)
    const auto carried = [&](double l) {
      const auto& cap = cap_to_edge(l, f);
      return cap && !cap->end.at_equator;
    };
    // The search stops at the first carried stretch whose residual is negative (not at the
    // carrying boundary to 1e-15), and the lowest stretch tried with g >= 0 caps the bracket: the
    // root's bracket starts ~1e-4 wide instead of ~5, half the marches at the curve's first points
    // (bench/README.md); the root is the same one, to the shooting's tolerance.
    std::optional<std::pair<double, double>> above;  // the lowest stretch tried with g >= 0
    if (carried(hi * (1.0 - 1e-12))) {
      double lo = 1.0;
      bool bracketed = false;
      const auto tried = [&](double l) {
        hi = l;
        g_hi = counted(Configuration::SlipWithoutPartTwo, l).value_or(kBeyondDomain);
        if (g_hi >= 0.0 && g_hi < kBeyondDomain) above = {l, g_hi};
        return g_hi < 0.0;
      };
      for (int k = 1; k <= 60; ++k) {
        const double l = 1.0 + (top - 1.0) / std::ldexp(1.0, k);
        if (!carried(l)) {
          lo = l;
          break;
        }
        if (tried(l)) {
          bracketed = true;
          break;
        }
      }
      for (int k = 0; k < 200 && !bracketed && hi - lo > 1e-15 * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (!carried(mid))
          lo = mid;
        else
          bracketed = tried(mid);
      }
      if (!(g_hi < 0.0)) {
        plan.status = Status::NoConvergence;
        plan.message =
            "sphere-tipped shooting: no bracket of the pole stretch (the contact edge where the "
            "cap's vertical force peaks already overshoots the clamp)";
        return plan;
      }
    }
    plan.lo = hi;
    plan.g_lo = g_hi;
    plan.cap = locking_radial_stretch(law_, 1.0);
    if (above && above->first > hi && above->first < plan.cap) {
      plan.cap = above->first;
      plan.g_cap = above->second;
      plan.branch_below = g_hi == kTurnedBack;
    }
    plan.no_root_message =
        "sphere-tipped shooting found no pole stretch meeting the clamp condition";
    return plan;
  }

  // Under a gas pressure whose share P a^2 / 2 at the equator alone exceeds f, every pole
  // stretch's cap carries f before the equator: the contact stays on the hemisphere, and the pole
  // stretch is bracketed from below (bracket_from_below).
  template <class Residual>
  ShootingPlan hemisphere_plan(double, Residual& counted) const {
    return bracket_from_below(
        counted, Configuration::SlipWithoutPartTwo, "sphere-tipped shooting under pressure");
  }

  // The flat membrane, at its pre-stretch: all of it Part I, from the pole to the clamp.
  ScaledSolution unloaded(bool record) const {
    ScaledSolution flat;
    flat.status = Status::Converged;
    flat.configuration = Configuration::Unloaded;
    const double l0 = part_one_.prestretch();
    flat.part_three_stretch = l0;
    if (record) {
      const int n = std::max(1, part_one_.settings().field_points);
      for (int k = 0; k <= n; ++k) {
        const double r = k == n ? 1.0 : static_cast<double>(k) / n;
        flat.part_one.push_back({r, 0.0, l0, l0, 0.0});
      }
    }
    return flat;
  }

  Configuration configuration(Stage stage, bool past_change) const {
    if (stage == Stage::Stick) return Configuration::Stick;
    return past_change ? Configuration::SlipWithPartTwo : Configuration::SlipWithoutPartTwo;
  }

  // The state where the contact reaches the equator (the side of zero length), as the
  // configuration with the side: its parameter is the equator's lambda2.  Empty if it never does
  // before the material locks.  Searched from a small force up, or from `f_from` up: the force of
  // a state on the loading path short of the equator.  (Under a gas pressure no onset exists
  // below the gas's share P a^2 / 2 at the equator, 0.0028 N for a = 2 mm at 0.9 kPa, so the
  // search from a small force finds none: the depth path starts from its own last state,
  // docs/model.md §17, "Beyond a hemisphere".)
  template <class Shooting>
  std::optional<ScaledSolution> slip_change(const Shooting& shooting, double f_from = 0.0) const {
    if (s_.beyond != BeyondTipSphere::CylinderSide) return std::nullopt;  // a status past it
    auto indicator = [&](double f) -> std::optional<double> {
      const auto onset = equator_onset(f);
      if (!onset) return std::nullopt;
      return side_indicator(f, *onset);
    };
    const int iterations = part_one_.settings().max_iterations;
    // Forces whose plans met the side indicator on both sides of its root bracket it (the
    // puncture's search, before the curve asks for the change): TOMS 748 on that bracket closes
    // on the root the search from a small force finds (each closes its bracket to 4 ulps),
    // without that search's steps from 1e-4 (on the 2 mm probe's curve, 77 of its marches).
    const bool bracketed =
        f_from == 0.0 && side_below_ && side_above_ && side_below_->first < side_above_->first;
    const auto f_on = bracketed ? shoot_increasing(indicator,
                                                   side_below_->first,
                                                   side_below_->second,
                                                   side_above_->first,
                                                   iterations,
                                                   0.0,
                                                   {0.0, side_above_->second})
                      : f_from > 0.0
                          ? onset_force(indicator, iterations, kOnsetStepFromPath * f_from, f_from)
                          : onset_force(indicator, iterations, 0.01);
    if (!f_on) return std::nullopt;
    const auto onset = equator_onset(*f_on);
    if (!onset) return std::nullopt;
    // (With friction on the side the parameter is the pole (face) stretch in both.)
    const double p = rough_side_solved() ? onset->stretch : s_.a / onset->end.r;
    auto sol = shooting.assemble(Configuration::SlipWithPartTwo, *f_on, p, false);
    if (!sol.integrated) return std::nullopt;
    return sol;
  }

  template <class Shooting>
  std::optional<ScaledSolution> direct_puncture(const Shooting&, double,
                                                std::optional<double> = {}) const {
    return std::nullopt;
  }

  const Law& law() const { return law_; }

  // Pole (the equibiaxial stretch is the largest I1), the cap, the side, or Part I.
  // With a flat face the pole's I1 holds on all of it: reported at its edge, as the sharp
  // punch's Part III.
  LargestFirstInvariant largest_first_invariant(const ScaledSolution& sol) const {
    if (pole_is_largest(sol))
      // (On the face alone under a gas pressure the contact disc ends before the face.)
      return s_.face > 0.0
                 ? LargestFirstInvariant{MembranePart::Tip,
                                         std::min(s_.face / sol.part_three_stretch, sol.r_corner),
                                         std::min(s_.face, sol.r_corner * sol.part_three_stretch)}
                 : LargestFirstInvariant{MembranePart::Tip, 0.0, 0.0};
    const bool with_side = sol.configuration == Configuration::SlipWithPartTwo;
    const bool on_cap = sol.max_i1_r < sol.r_corner * (1.0 - kEdgeTol);
    const bool on_side = with_side && !on_cap && sol.max_i1_r < sol.r_top * (1.0 - kEdgeTol);
    return {on_cap    ? MembranePart::Tip
            : on_side ? MembranePart::Side
                      : MembranePart::Free,
            sol.max_i1_r,
            sol.max_i1_radius};
  }

  std::string crack_location(const ScaledSolution& sol) const {
    if (cone()) return crack_location_on_cone(sol);
    const bool fillet = s_.face > 0.0;
    if (pole_is_largest(sol))
      return fillet ? "Part III, on the flat face (uniform, as stretched as the pole)"
                    : "the pole, under the tip of the sphere";
    const bool with_side = sol.configuration == Configuration::SlipWithPartTwo;
    if (std::abs(sol.max_i1_r - sol.r_top) <= kEdgeTol * sol.r_top)
      return with_side ? "the top of the contact on the cylinder side, where the membrane leaves it"
             : fillet && fillet_face().on_face(sol.f)
                 ? "the contact edge, where the membrane leaves the flat face (under the gas)"
             : fillet ? "the contact edge, where the membrane leaves the fillet"
                      : "the contact edge, where the membrane leaves the sphere";
    if (sol.max_i1_r < sol.r_corner)
      return fillet ? "on the fillet, between the flat face and the contact edge"
                    : "on the sphere, between the pole and the contact edge";
    if (with_side && sol.max_i1_r < sol.r_top) return "on the cylinder side of the probe";
    return "Part I, off the indenter";
  }

  // Part I starts at the contact edge, the cap's height above the pole, or at the top of the
  // side.
  double free_part_inner_height(const ScaledSolution& sol) const {
    if (sol.configuration == Configuration::Unloaded) return 0.0;
    if (sol.configuration == Configuration::SlipWithPartTwo) return arc() + sol.part_two_length;
    if (cone()) return free_part_inner_height_on_cone(sol.corner_slope, sol.part_two_length);
    return cap_height(sol.corner_slope);
  }

  // The cap from the pole (or the flat face, uniform and without contact pressure), then the
  // side, with the contact pressure from normal balance.
  void append_contact_fields(const ScaledSolution& sol, const FieldScales& u,
                             MembraneFields& m) const {
    const double big_a = u.clamp_radius_mm, g = u.shear_modulus_mpa;
    const double depth = sol.depth * big_a;
    const bool stuck = sol.configuration == Configuration::Stick;
    for (const auto& sample : sol.part_two) {
      const double r_ref = sample[0], l1 = sample[1], psi = sample[2];
      const bool side = !cone() && psi > kHalfPiCap;
      // (Under a gas pressure with friction the face is not uniform: psi = (r - b) / rho < 0.)
      const bool rough_face = psi < 0.0;
      const bool face = rough_face || (s_.face > 0.0 && psi == 0.0 && r_ref < s_.face / l1 &&
                                       !(stuck && held_profile_->face_map()));
      const double radius = side         ? s_.a
                            : rough_face ? s_.face + arc() * psi
                            : face       ? l1 * r_ref
                                         : radius_at(psi);
      const double l2 = r_ref > 0.0 && (!face || rough_face) ? radius / r_ref : l1;
      const auto st = membrane_stress(law_, l1, l2);
      // The flat face carries only the gas pressure; on the cone the meridian is straight: the
      // hoop tension alone presses it on.
      const double normal = face ? pressure_
                            : cone() && psi > tangency_
                                ? st.s2 * std::sin(tangency_) / (l1 * radius) + pressure_
                                : contact_pressure(l1, l2, st, side, psi);
      const double pressure = normal * g * u.thickness_mm / big_a;
      append_point(
          m,
          side ? MembranePart::Side : MembranePart::Tip,
          r_ref * big_a,
          radius * big_a,
          face ? depth : depth - profile_height(psi) * big_a,
          face     ? 0.0
          : cone() ? slope_at(psi)
                   : std::min(psi, kHalfPiCap),
          l1,
          l2,
          st,
          g,
          pressure,
          // Held: the tangential traction the probe supplies (towards the pole).
          stuck ? held_tangential(r_ref, rough_face ? radius : -1.0) * g * u.thickness_mm / big_a
                : s_.mu * pressure);
    }
  }

  // Normal balance: on the sphere p = (s1 / lambda2 + s2 / lambda1) / a (the true tensions over
  // the sphere's radius, Laplace's law), on the cylinder p = s2 / (lambda1 a); the gas pressure
  // presses the membrane onto the probe and adds to both; normalised by G H / A.
  // On the fillet (radius rho, at polar angle theta, current radius r) the two curvatures
  // differ: p = s1 / (lambda2 rho) + s2 sin(theta) / (lambda1 r).
  double contact_pressure(double l1, double l2, const MembraneStress& st, bool side,
                          double theta = 0.0) const {
    if (s_.face > 0.0 && !side)
      return st.s1 / (l2 * arc()) + st.s2 * std::sin(theta) / (l1 * arc_radius_at(theta)) +
             pressure_;
    return ((side ? 0.0 : st.s1 / l2) + st.s2 / l1) / s_.a + pressure_;
  }

  // The gas pressure's resultant on the cap up to polar angle theta, P (a sin(theta))^2 / 2 (on
  // the cone, up to the profile point psi: P r(psi)^2 / 2).
  double gas_load(double theta) const {
    const double r = radius_at(theta);
    return 0.5 * pressure_ * r * r;
  }
  // ... up to where the curved profile ends: the sphere's (fillet's) equator, the cone's kink.
  double end_gas_load() const {
    return cone() ? 0.5 * pressure_ * side_radius_ * side_radius_ : gas_load(kHalfPiCap);
  }

  // The arc's radius rho (a for the hemisphere) and the current radius of its point at polar
  // angle theta, b + rho sin(theta) (b = 0 for the hemisphere: a sin(theta) to the last bit).
  double arc() const { return s_.a - s_.face; }
  double arc_radius_at(double theta) const { return s_.face + arc() * std::sin(theta); }
  // The arc's start at the flat face's edge, R = b / l: the face's uniform stretch l, its stored
  // energy W(l, l) R^2 / 2.
  SphereCapState face_edge_state(double l, double r_edge) const {
    const auto st = membrane_stress(law_, l, l);
    return {0.0, l, 0.5 * strain_energy_density(law_, l, l, st.i1) * r_edge * r_edge};
  }

  // Height above the pole of the point at polar angle theta on the hemisphere (on the arc).
  double cap_height(double theta) const { return arc() * (1.0 - std::cos(theta)); }
  // ... and of the profile point psi (sample coordinate): past pi/2, up the cylinder.
  double profile_height(double psi) const {
    if (cone() && psi > tangency_)
      return cap_height(tangency_) + s_.a * (psi - tangency_) * std::sin(tangency_);
    return psi <= kHalfPiCap ? cap_height(psi) : arc() * (1.0 + (psi - kHalfPiCap));
  }
  // The profile point psi's current radius and the meridian's slope there: on the sphere (the
  // fillet) arc_radius_at(psi) and psi, on the cone (psi past the tangency) the straight
  // generatrix.
  double radius_at(double psi) const {
    if (cone() && psi > tangency_)
      return s_.a * (std::sin(tangency_) + (psi - tangency_) * std::cos(tangency_));
    return arc_radius_at(psi);
  }
  double slope_at(double psi) const { return cone() && psi > tangency_ ? tangency_ : psi; }
  // Part I's inner end above the pole on the cone probe: at the slope (on the tip sphere), or
  // the tangency's height plus the membrane's length on the cone times its slope's sine.
  double free_part_inner_height_on_cone(double slope, double on_cone) const {
    return cap_height(std::min(slope, tangency_)) + on_cone * std::sin(tangency_);
  }

  // The cap marched from pole stretch l until it carries f (or to the equator), with its largest
  // I1 tracked: the last one marched, kept for the attachment that follows the free start at the
  // same (l, f).
  struct CapMarch {
    double l;
    double f;
    CapEnd end;
    InteriorMaximum<SphereCapState> i1_max;
  };
  const std::optional<CapMarch>& cap_to_edge(double l, double f) const {
    if (last_cap_ && last_cap_->l == l && last_cap_->f == f) return last_cap_;
    InteriorMaximum<SphereCapState> i1_max;
    const auto end = march(l, f, nullptr, &i1_max);
    if (end)
      last_cap_ = CapMarch{l, f, *end, i1_max};
    else
      last_cap_.reset();
    return last_cap_;
  }

  // The cap that carries f exactly at the equator: its pole stretch, its end and its largest I1
  // tracked along the march (attach_with_side's, when it samples nothing).
  struct EquatorOnset {
    double stretch;
    CapEnd end;
    InteriorMaximum<SphereCapState> i1_max;
  };
  // V at the equator grows with the pole stretch, and the onset depends on the force alone (the
  // cap from the pole to the equator knows nothing of Part I): a force asked again (the plan,
  // then the attachment, at one force; a Jacobian's second column at the force of its first)
  // returns the onset found for it (the same march).  Else secant steps from the last onsets
  // (onset_by_secant: the depth Newton asks for nearby forces in turn); else the root is
  // bracketed from the last onset found, else from 1, and refined by TOMS 748 to a few ulps.
  std::optional<EquatorOnset> equator_onset(double f) const {
    for (const auto& known : onsets_)
      if (known && known->f == f) return known->onset;
    if (auto onset = onset_by_secant(f)) return onset;
    auto g = [&](double l) -> std::optional<double> {
      const auto end = march(l, std::numeric_limits<double>::infinity());
      if (!end) return std::nullopt;
      return capacity(*end) - f;
    };
    auto found = [&](double l) { return kept_onset(f, cap_to_equator(l)); };
    std::optional<double> root;
    if (const double l0 = onsets_[0] ? onsets_[0]->onset.stretch : 0.0; l0 > 1.0) {
      // V there is the last onset's own march.
      const double g0 = capacity(onsets_[0]->onset.end) - f;
      if (g0 < 0.0) {
        root = shoot_increasing(g,
                                l0,
                                g0,
                                std::numeric_limits<double>::infinity(),
                                part_one_.settings().max_iterations,
                                1e-3 * (l0 - 1.0));
      } else {
        // Step down towards 1 until V falls below f (V = 0 at 1).
        double hi = l0, g_hi = g0, step = 1e-3 * (l0 - 1.0), lo = l0;
        std::optional<double> g_lo;
        for (int k = 0; k < 60; ++k, step *= 2.0) {
          lo = std::max(1.0, hi - step);
          g_lo = lo == 1.0 ? std::optional<double>(end_gas_load() - f) : g(lo);
          if (g_lo && *g_lo < 0.0) break;
          if (g_lo) {
            hi = lo;
            g_hi = *g_lo;
          }
        }
        if (g_lo && *g_lo < 0.0) {
          if (g_hi == 0.0) return found(hi);
          std::uintmax_t iterations =
              static_cast<std::uintmax_t>(part_one_.settings().max_iterations);
          const auto bracket = boost::math::tools::toms748_solve(
              [&](double l) { return g(l).value_or(kBeyondDomain); },
              lo,
              hi,
              *g_lo,
              g_hi,
              [](double x0, double x1) {
                return std::abs(x1 - x0) <=
                       4.0 * std::numeric_limits<double>::epsilon() * std::abs(x1);
              },
              iterations);
          root = 0.5 * (bracket.first + bracket.second);
        }
      }
    }
    if (root) {
      if (auto warm = found(*root)) return warm;
    }
    // From the flat membrane (also when the warm start's bracket ends where the march fails).
    // Under a gas pressure the cap carries its share P a^2 / 2 at the equator even unstretched:
    // no onset when that alone exceeds f.
    const double cap = locking_radial_stretch(law_, 1.0);
    const double g_flat = pressure_ == 0.0 ? -f : end_gas_load() - f;
    if (!(g_flat < 0.0)) return std::nullopt;
    root = shoot_increasing(
        g, 1.0, g_flat, cap, part_one_.settings().max_iterations, std::isfinite(cap) ? 0.0 : 0.05);
    if (!root) return std::nullopt;
    return found(*root);
  }

  // The onset at f by secant steps on V at the equator - f, started from the last onsets found
  // (Lambda_e(f) through the nearest and the trail of earlier ones: the start and its slope): the
  // pole stretch whose next step would move it by at most kOnsetStretchTol (relative) is the
  // root, and its march, which tracked the largest I1, the onset's (no march again).  That
  // tolerance, 1e-12, lies below the march's own error (relative integration tolerance 3e-11):
  // the onset differs from TOMS 748's bracketed root by less than that (sphere_tipped_test).
  // Without a history near f, from a power law (onset_by_power_law).  Empty when there is no
  // history, a step leaves the stretches above 1 or the material's domain, or the steps do not
  // converge: the bracketing search runs then.
  std::optional<EquatorOnset> onset_by_secant(double f) const {
    if (!onsets_[0] || !onsets_[1]) return std::nullopt;
    const ForceOnset& a = *onsets_[0];
    const ForceOnset& b = *onsets_[1];
    const ForceOnset& near = std::abs(f - a.f) <= std::abs(f - b.f) ? a : b;
    if (!(std::abs(f - near.f) <= kOnsetSecantReach * f))
      return pressure_ == 0.0 ? onset_by_power_law(f) : std::nullopt;
    // A force within kOnsetLinearReach of an onset whose slope the secant measured (the depth
    // Newton's next iterate at a point): from that onset along that slope, ~1e-14 off.
    if (near.dv_dl > 0.0 && std::abs(f - near.f) <= kOnsetLinearReach * f)
      return onset_secant_steps(
          f, near.onset.stretch + (f - near.f) / near.dv_dl, 1.0 / near.dv_dl, kOnsetSecantSteps);
    // The start: Lambda_e through the nearest onset and the trail of onsets at distinct forces
    // (one per curve point), a polynomial in log f (Newton's divided differences), and its slope.
    // Near locking Lambda_e(f) bends sharply: through three onsets a point's first start was
    // ~5e-6 off, three marches; through six in log f ~3e-9 (median), two.
    std::array<double, kTrailLength + 1> nx{}, nl{};
    std::size_t n = 0;
    const auto add_node = [&](double node_f, double stretch) {
      if (!(std::abs(node_f - f) <= kOnsetSecantReach * f) || !(node_f > 0.0)) return;
      for (std::size_t i = 0; i < n; ++i)
        if (std::abs(std::exp(nx[i]) - node_f) <= kTrailSpacing * f) return;
      nx[n] = std::log(node_f);
      nl[n++] = stretch;
    };
    add_node(near.f, near.onset.stretch);
    for (auto it = onset_trail_.rbegin(); it != onset_trail_.rend() && n <= kTrailLength; ++it)
      add_node(it->first, it->second);
    if (n < 2) add_node((&near == &a ? b : a).f, (&near == &a ? b : a).onset.stretch);
    if (n < 2) {  // the two last onsets closer than the trail's spacing: their secant
      nx = {std::log(a.f), std::log(b.f)};
      nl = {a.onset.stretch, b.onset.stretch};
      n = 2;
    }
    for (std::size_t k = 1; k < n; ++k)
      for (std::size_t i = n - 1; i >= k; --i) nl[i] = (nl[i] - nl[i - 1]) / (nx[i] - nx[i - k]);
    const double x = std::log(f);
    double l = nl[n - 1], dl_dx = 0.0;
    for (std::size_t i = n - 1; i-- > 0;) {
      dl_dx = dl_dx * (x - nx[i]) + l;
      l = l * (x - nx[i]) + nl[i];
    }
    const double dl_df = dl_dx / f;
    if (!(l > 1.0) || !std::isfinite(l) || !(dl_df > 0.0) || !std::isfinite(dl_df))
      return std::nullopt;
    return onset_secant_steps(f, l, dl_df, kOnsetSecantSteps);
  }

  // Farther from the last onsets (the puncture's search, the curve's first points), without a gas
  // pressure (V_e then grows with the stretch from 0 at 1: one root): started from
  // the power law Lambda_e - 1 ~ f^k through the two last onsets of distinct forces, which
  // leaves the start a few per cent off, and more steps.  The same root: the secant's steps end
  // as above, or the bracketing search runs.
  std::optional<EquatorOnset> onset_by_power_law(double f) const {
    const ForceOnset& a = *onsets_[0];
    const ForceOnset* b = nullptr;
    for (const auto& known : {onsets_[1], onsets_[2]})
      if (known && known->f != a.f && !b) b = &*known;
    if (!b || !(a.f > 0.0) || !(b->f > 0.0)) return std::nullopt;
    const double ea = a.onset.stretch - 1.0, eb = b->onset.stretch - 1.0;
    if (!(ea > 0.0) || !(eb > 0.0)) return std::nullopt;
    const double power = std::log(ea / eb) / std::log(a.f / b->f);
    if (!(power > 0.0) || !std::isfinite(power)) return std::nullopt;
    // From the onset nearer f in log f.
    const ForceOnset& near = std::abs(std::log(f / a.f)) <= std::abs(std::log(f / b->f)) ? a : *b;
    const double e = (near.onset.stretch - 1.0) * std::pow(f / near.f, power);
    return onset_secant_steps(f, 1.0 + e, power * e / f, kOnsetFarSteps);
  }
  // Secant steps on V at the equator - f from pole stretch l, with dLambda/df = dl_df there.
  std::optional<EquatorOnset> onset_secant_steps(double f, double l, double dl_df,
                                                 int steps) const {
    double slope = 1.0 / dl_df, l_prev = 0.0, g_prev = 0.0;
    if (!(slope > 0.0) || !std::isfinite(slope)) return std::nullopt;
    for (int k = 0; k < steps; ++k) {
      if (!(l > 1.0) || !std::isfinite(l)) return std::nullopt;
      auto onset = cap_to_equator(l);
      if (!onset) return std::nullopt;
      const double g = capacity(onset->end) - f;
      if (k > 0 && std::abs(l - l_prev) > kOnsetSlopeSpan * l) {
        const double s = (g - g_prev) / (l - l_prev);
        if (s > 0.0 && std::isfinite(s)) slope = s;
      }
      const double step = -g / slope;
      if (std::abs(step) <= kOnsetStretchTol * l) return kept_onset(f, std::move(onset), slope);
      l_prev = l;
      g_prev = g;
      l += step;
    }
    return std::nullopt;
  }
  // Secant steps for the onset: at most this many, from an onset whose force is within
  // kOnsetSecantReach of f (relative; farther, the bracketing search); the last step's
  // relative size that makes its start the root; a slope is updated only from stretches this far
  // apart (relative: closer, V's rounding would dominate it).  The trail: this many onsets whose
  // forces lie at least kTrailSpacing apart (relative).
  static constexpr int kOnsetSecantSteps = 6;
  static constexpr int kOnsetFarSteps = 10;
  static constexpr double kOnsetSecantReach = 0.2;
  static constexpr double kOnsetLinearReach = 1e-6;
  static constexpr double kOnsetStretchTol = 1e-12;
  static constexpr std::size_t kTrailLength = 5;
  static constexpr double kTrailSpacing = 1e-4;
  static constexpr double kOnsetSlopeSpan = 1e-12;

  // The cap marched from pole stretch l to the equator with its largest I1 tracked: a candidate
  // onset.  Empty outside the material's domain.
  std::optional<EquatorOnset> cap_to_equator(double l) const {
    InteriorMaximum<SphereCapState> i1_max;
    const auto end = march(l, std::numeric_limits<double>::infinity(), nullptr, &i1_max);
    if (!end) return std::nullopt;
    return EquatorOnset{l, *end, i1_max};
  }
  // A candidate onset for f, kept (as the last) if it carries f at the equator: far from f
  // there when a bracketing ends where the march fails (e.g. a law without locking whose V at
  // the equator stays below f at every stretch), while a true root meets it to the
  // integration's accuracy (absolute, at the tiny forces where V at the equator crosses zero: an
  // unstretched pole leaves the cap in hoop compression towards the equator).
  std::optional<EquatorOnset> kept_onset(double f, std::optional<EquatorOnset> candidate,
                                         double dv_dl = 0.0) const {
    // A root must carry f at the equator (the bracketing may end where the march fails, e.g. a
    // law without locking whose V at the equator stays below f at every stretch): short of f
    // there, by as little as f exceeds V's bound (1e-3 relative let a neo-Hookean force 2e-5
    // beyond its limit load pass as an onset, a state at 66 mm with I1 ~ 1e23), while a true root,
    // bracketed to a few ulps, meets it to the integration's accuracy (absolute, at the tiny
    // forces where V at the equator crosses zero: an unstretched pole leaves the cap in hoop
    // compression towards the equator).
    if (!candidate || !(std::abs(capacity(candidate->end) - f) <= kOnsetMatch * f + 1e-9))
      return std::nullopt;
    onsets_[2] = std::move(onsets_[1]);
    onsets_[1] = std::move(onsets_[0]);
    onsets_[0] = ForceOnset{f, std::move(*candidate), dv_dl};
    if (onset_trail_.empty() || std::abs(onset_trail_.back().first - f) > kTrailSpacing * f) {
      onset_trail_.emplace_back(f, onsets_[0]->onset.stretch);
      if (onset_trail_.size() > kTrailLength) onset_trail_.pop_front();
    }
    return onsets_[0]->onset;
  }
  // The side indicator's sign at force f, from a plan (without a gas pressure, on the cylinder
  // side's model): the largest force where it was negative and the smallest where it was not.
  void keep_side_bracket(double f, double g) const {
    if (pressure_ != 0.0 || s_.beyond != BeyondTipSphere::CylinderSide || !std::isfinite(g)) return;
    if (g < 0.0 && (!side_below_ || f > side_below_->first)) side_below_.emplace(f, g);
    if (g >= 0.0 && (!side_above_ || f < side_above_->first)) side_above_.emplace(f, g);
  }
  // Pole stretch of the onset, for the tests.
  std::optional<double> equator_onset_stretch(double f) const {
    const auto onset = equator_onset(f);
    return onset ? std::optional<double>(onset->stretch) : std::nullopt;
  }

  // Clamp residual of Part I leaving the equator vertically at force f (Part II of zero length):
  // the same whether counted as the cap's end or the side's top.  Empty past locking.
  std::optional<double> side_indicator(double f, const EquatorOnset& onset) const {
    return part_one_.residual(f, side_top_start(f, side_radius_ / onset.end.r));
  }

  const SphereTippedSettings& settings() const { return s_; }

  static constexpr const char* kNeckNotSolved =
      "outside the ball model: the contact passes the ball's equator; the membrane would wrap the "
      "upper hemisphere and form a neck above the ball, which is not solved (docs/model.md, "
      "section 15.1)";
  static constexpr const char* kShankNotSolved =
      "outside the cone model: the contact reaches the shank (the membrane would wrap the "
      "cylinder above the cone-shank kink, which is not solved; docs/model.md, section 15.2)";

 private:
  // Where the cap starts: the polar angle there (the series' error, O((L R / a)^4) = 1e-16,
  // is far below the integration's tolerance).
  static constexpr double kPoleStart = 1e-4;
  static constexpr double kPoleStartFriction = 1e-5;
  static constexpr double kHalfPiCap = boost::math::constants::half_pi<double>();
  static constexpr double kEdgeTol = 1e-9;
  static constexpr int kFacePoints = 4;  // samples of the uniform flat face, pole included
  static constexpr double kEndResidualMargin = 1e-5;
  static constexpr double kOnsetMatch = 1e-8;  // an equator onset's pull against f (relative)
  // The first step of the onset's search from a loading path's state (relative to its force): a
  // step of the path (0.01 A in depth) moves the force by ~1 % near the equator.
  static constexpr double kOnsetStepFromPath = 0.01;

  bool cone() const { return s_.beyond == BeyondTipSphere::Cone; }
  // The filleted punch's face under a gas pressure (fillet_face_under_gas.hpp).
  FilletFaceUnderGas<Law> fillet_face() const {
    return {law_, locking_i1_, pressure_, s_.mu, s_.face, arc(), part_one_.settings().integration};
  }
  // Samples of the face under a gas pressure: as many as of the arc.
  int face_points() const { return std::max(1, part_one_.settings().field_points); }
  // Held on the fillet's face alone under a gas pressure (f < P b^2 / 2, the held face's map).
  bool held_on_face(double f) const {
    return held_profile_->face_map() && f < 0.5 * pressure_ * s_.face * s_.face;
  }
  // Held there, Part I leaves the face horizontally at the held disc's edge c = sqrt(2 f / P), R
  // from the face's map, with the radial line tension t = R s1 (the parameter, as on the sharp
  // punch's held face).
  std::optional<FreeStart> held_face_start(double f, double t) const {
    if (!(t > 0.0) || !std::isfinite(t)) return std::nullopt;
    const double c = std::sqrt(2.0 * f / pressure_);
    const auto r = held_profile_->face_map()->radius_at(c);
    if (!r || !(*r > 0.0)) return std::nullopt;
    const double l2 = c / *r;
    const auto l1 = invert_radial_stress(law_, t / *r, l2);
    if (!l1 || !(first_invariant(*l1, l2) < locking_i1_)) return std::nullopt;
    return FreeStart{{t, *l1, l2, 0.0}, *r, 0.0, 1.0};
  }
  // The stick stage's plan: the held profile's, then on the cone the pivot over the kink (from the
  // kink's force, or just below it where the history's last interval does not bracket the root).
  template <class Residual>
  ShootingPlan held_plan(double f, Residual& counted) const {
    const auto pivot = kink_pivot();
    if (!pivot.follows()) return held_profile_plan(*held_profile_, f, counted);
    const auto& p = held_profile_->points();
    if (!(f < pivot.kink().f)) return pivot.plan(counted);
    auto plan = held_profile_plan(*held_profile_, f, counted);
    if (!plan.ok() && f > p[p.size() - 2].f) return pivot.plan(counted);
    return plan;
  }
  HeldProfile held_profile() const {
    return {.arc = arc(),
            .face = s_.face,
            .tangency = cone() ? tangency_ : std::numeric_limits<double>::infinity(),
            .end_psi = end_psi_,
            .end = cone()                               ? HeldProfileEnd::Kink
                   : s_.beyond == BeyondTipSphere::Neck ? HeldProfileEnd::Neck
                                                        : HeldProfileEnd::CylinderSide};
  }
  // The held membrane's tangential traction towards the tip at r (/ (G H / A)); on the held face
  // under a gas pressure (face_radius >= 0, its current radius) the face map's.
  double held_tangential(double r, double face_radius) const {
    const auto* face = held_profile_->face_map();
    return face && face_radius >= 0.0 ? face->tangential_near(face_radius)
                                      : held_profile_->traction_near(r).tangential;
  }

  // The cap's system, with the cone past the tangency for the cone probe (by position, or the
  // sphere's or the cone's equations throughout).
  SphereCapSystem<Law> cap_system(
      typename SphereCapSystem<Law>::Part part = SphereCapSystem<Law>::Part::ByPosition) const {
    SphereCapSystem<Law> cap{law_, arc(), locking_i1_, s_.mu, pressure_, s_.face};
    if (cone()) {
      cap.tangency = tangency_;
      cap.part = part;
    }
    return cap;
  }

  // What the cap can carry at the end of the curved profile: at the sphere's equator its vertical
  // pull; at the cone's kink R s1 times the capstan factor over the kink's whole angle, the pull
  // of a vertical exit.
  double capacity(const CapEnd& end) const {
    if (!cone()) return end.carried;
    const double pull =
        s_.mu == 0.0 ? end.pull : end.pull * std::exp(s_.mu * (kHalfPiCap - tangency_));
    return pressure_ == 0.0 ? pull : pull + end_gas_load();  // the gas's share inside the kink
  }

  // Part I leaving the cone-shank kink (the cap carried less than f up to it): the membrane
  // turns over the kink with a line force, lambda2 continuous, R s1 = N continuous without
  // friction and raised by the capstan factor exp(mu (slope - cone's slope)) with it (the
  // membrane slides outward over the kink, §5), at the slope where N exp(...) sin(slope) = f,
  // between the cone's and vertical; none when even a vertical exit carries less than f (the
  // membrane would wrap the shank).
  // Under a gas pressure the membrane's pull over the kink is f less the gas's share inside it.
  std::optional<FreeStart> kink_start(const CapEnd& end, double force) const {
    if (!(capacity(end) >= force * (1.0 - 1e-9))) return std::nullopt;
    const double f = pressure_ == 0.0 ? force : force - end_gas_load();
    double slope = std::asin(std::min(1.0, f / end.pull)), ratio = 1.0;
    if (s_.mu != 0.0) {
      // sin(slope) exp(mu (slope - tangency)) = f / N grows with the slope on [tangency, pi/2].
      const double kappa = f / end.pull;
      auto g = [&](double x) { return std::sin(x) * std::exp(s_.mu * (x - tangency_)) - kappa; };
      const double g_lo = g(tangency_), g_hi = g(kHalfPiCap);
      if (g_lo >= 0.0) {
        slope = tangency_;
      } else if (g_hi <= 0.0) {
        slope = kHalfPiCap;
      } else {
        slope = root_in_bracket(g, tangency_, kHalfPiCap, g_lo, g_hi);
      }
      ratio = std::exp(s_.mu * (slope - tangency_));
    }
    // R s1 cos(slope) past the kink; without friction sqrt(N^2 - f^2), exact near vertical.
    const double t = s_.mu == 0.0 ? std::sqrt(std::max(0.0, (end.pull - f) * (end.pull + f)))
                                  : end.pull * ratio * std::cos(slope);
    const double l1_in = end.state[1], l2 = radius_at(end.state[0]) / end.r;
    double l1 = l1_in;
    if (ratio != 1.0) {  // s1 raised by the capstan factor at the same hoop stretch
      const auto raised = invert_radial_stress(law_, ratio * end.pull / end.r, l2);
      if (!raised) return std::nullopt;
      l1 = *raised;
    }
    return FreeStart{{t, l1, l2, 0.0}, end.r, slope, ratio};
  }

  std::string crack_location_on_cone(const ScaledSolution& sol) const {
    if (pole_is_largest(sol)) return "the pole, under the tip sphere";
    if (std::abs(sol.max_i1_r - sol.r_top) <= kEdgeTol * sol.r_top) {
      if (sol.corner_slope > tangency_)
        return "the kink where the cone meets the shank, where the membrane leaves the probe";
      return sol.corner_slope < tangency_
                 ? "the contact edge, where the membrane leaves the tip sphere"
                 : "the contact edge, where the membrane leaves the cone";
    }
    if (sol.max_i1_r < sol.r_corner)
      return sol.max_i1_radius <= s_.a * std::sin(tangency_)
                 ? "on the tip sphere, between the pole and the cone"
                 : "on the cone, between the tip sphere and the contact edge";
    return "Part I, off the indenter";
  }

  bool pole_is_largest(const ScaledSolution& sol) const {
    const double l = sol.part_three_stretch;
    return first_invariant(l, l) >= sol.max_i1 * (1.0 - 1e-12);
  }

  // Part I leaving the side vertically at R = a / p: R s1 = f - P a^2 / 2 (the gas pressure on
  // the probe's cross-section takes its share), t = 0.
  std::optional<FreeStart> side_top_start(double f, double p) const {
    if (!(p > side_radius_)) return std::nullopt;  // the top must lie inside the clamp
    const double pull = pressure_ == 0.0 ? f : f - end_gas_load();
    if (!(pull > 0.0)) return std::nullopt;
    const auto l1 = invert_radial_stress(law_, pull * p / side_radius_, p);
    if (!l1) return std::nullopt;
    return FreeStart{{0.0, *l1, p, 0.0}, side_radius_ / p, kHalfPiCap, 1.0};
  }

  // Part I leaving the sphere tangentially at the contact edge: slope theta, t = R s1 cos(theta).
  FreeStart edge_start(const CapEnd& end) const {
    const double theta = slope_at(end.state[0]), l1 = end.state[1];
    const double l2 = radius_at(end.state[0]) / end.r;
    const double t = end.vertical / std::tan(theta);  // R s1 cos(theta), R s1 sin(theta) = f
    return FreeStart{{t, l1, l2, 0.0}, end.r, theta, 1.0};
  }
  // Part I leaving the equator vertically (t = 0).
  FreeStart vertical_start(const CapEnd& end) const {
    const double l1 = end.state[1], l2 = s_.a / end.r;
    return FreeStart{{0.0, l1, l2, 0.0}, end.r, kHalfPiCap, 1.0};
  }

  // The cap's largest I1 (refined between samples with `maxima`, else sampled) into the
  // solution's, if it is larger.
  void track_cap_maximum(const InteriorMaximum<SphereCapState>& i1_max, ScaledSolution& sol,
                         bool maxima) const {
    const auto cap = cap_system();
    auto cap_i1 = [&](double r, const SphereCapState& y) {
      return first_invariant(y[1], radius_at(y[0]) / r);
    };
    const auto found = maxima ? refined_maximum(i1_max, cap, cap_i1) : i1_max.sampled();
    if (found.value > sol.max_i1) {
      sol.max_i1 = found.value;
      sol.max_i1_r = found.r;
      sol.max_i1_radius = radius_at(found.state[0]);
    }
  }

  // The side's largest I1 (refined between samples when `maxima`) into the solution's, if larger.
  void track_side_maximum(const InteriorMaximum<PartTwoState>& side_max,
                          const PartTwoSystem<Law>& side, ScaledSolution& sol, bool maxima) const {
    const auto found = maxima ? refined_maximum(side_max,
                                                side,
                                                [&](double r, const PartTwoState& x) {
                                                  return first_invariant(x[0], s_.a / r);
                                                })
                              : side_max.sampled();
    if (found.value > sol.max_i1) {
      sol.max_i1 = found.value;
      sol.max_i1_r = found.r;
      sol.max_i1_radius = s_.a;
    }
  }

  // Contact past the equator: the cap is the one that carries f at the equator; the side, where
  // R s1 = f, runs from Part I's start down to the equator (the flat punch's Part II without
  // friction, which also gives its length).
  bool attach_with_side(const FreeStart& st, bool record, ScaledSolution& sol, bool maxima) const {
    const double f = sol.f;
    const auto onset = equator_onset(f);
    if (!onset || !(st.r0 >= onset->end.r * (1.0 - 1e-12))) {
      sol.status = Status::NoConvergence;
      sol.message = onset ? "the top of the side contact lies below the hemisphere's equator"
                          : "no pole stretch lets the cap carry the force at the equator";
      return false;
    }
    const double r_eq = std::min(onset->end.r, st.r0);
    // The onset's march tracked the cap's I1 already; sampled, the cap is marched again in
    // shorter steps.
    InteriorMaximum<SphereCapState> i1_max = onset->i1_max;
    std::vector<PartTwoSample> cap_samples;
    if (record) {
      i1_max = {};
      if (!march(onset->stretch, std::numeric_limits<double>::infinity(), &cap_samples, &i1_max)) {
        sol.status = Status::NoConvergence;
        sol.message = "the cap up to the equator could not be integrated again";
        return false;
      }
    }
    track_cap_maximum(i1_max, sol, maxima);
    // The side, from Part I's start down to the equator.
    const PartTwoSystem<Law> side{law_, s_.a, 0.0, PartTwoEquation::RingBalance, locking_i1_};
    PartTwoState y{st.state[1], 0.0};
    InteriorMaximum<PartTwoState> side_max;
    std::vector<PartTwoSample> side_samples;
    IntegrationSettings integration = part_one_.settings().integration;
    if (record) integration.max_step = s_.a / std::max(1, part_one_.settings().field_points);
    bool ok = true;
    if (st.r0 > r_eq) {
      ok = integrate_part(side, y, st.r0, r_eq, integration, [&](double r, const PartTwoState& x) {
        if (record) side_samples.push_back({r, x[0], x[1]});
        side_max.observe(r, x, first_invariant(x[0], s_.a / r));
        return true;
      });
    }
    if (!ok) {
      sol.status = Status::BeyondLocking;
      sol.message = "the membrane on the probe's side reaches the locking stretch";
      return false;
    }
    track_side_maximum(side_max, side, sol, maxima);
    const double length = y[1];  // current length of the side
    if (record) {
      sol.part_two = std::move(cap_samples);
      // The side's samples were taken downward; psi = pi/2 + (height above the equator) / a.
      for (auto it = side_samples.rbegin(); it != side_samples.rend(); ++it)
        sol.part_two.push_back({(*it)[0], (*it)[1], kHalfPiCap + (length - (*it)[2]) / arc()});
    }
    sol.r_corner = r_eq;
    sol.part_three_stretch = onset->stretch;
    sol.part_two_length = length;
    sol.depth += arc() + length;
    sol.tension_ratio = 1.0;
    return true;
  }

  // ---- Coulomb slip on the cylinder side, past the equator of the tip sphere or of the fillet
  // (docs/model.md §15, §19; the ball and the cone end at their equator or kink, a status).  Both
  // sliding configurations are shot on the pole (face) stretch l: the cap (face and arc) to the
  // equator, where it carries R_e s1 <= f - P a^2 / 2, then the side marched up from it with
  // friction (PartTwoSystem: d(R s1)/dR = mu (s2 + P a lambda1)) until R s1 = f - P a^2 / 2,
  // where Part I leaves vertically.  An initial-value problem from the axis outward, as the flat
  // punch's under a gas pressure with friction.
  bool rough_side_solved() const {
    return s_.mu != 0.0 && s_.beyond == BeyondTipSphere::CylinderSide;
  }

  struct RoughSide {
    FreeStart start;
    double length;  // the side's current length, equator to top
    CapEnd cap;     // the cap's end at the equator
  };
  // observe(R, (lambda1, y)) at the side's steps, y = minus the height above the equator.  Empty
  // when the cap carries more than f at the equator (no side; 1e-9 relative is the onset
  // itself) or cannot be marched.  Under a gas pressure the membrane's pull is f less the gas's
  // share on the probe's cross-section, P a^2 / 2 (side_top_start).  A top beyond the clamp stands
  // in as Part I of zero length at the clamp, whose residual a - L0 < 0 the top's approach to the
  // clamp tends to.
  template <class Observer>
  std::optional<RoughSide> rough_side(double l, double f, Observer&& observe,
                                      std::vector<PartTwoSample>* cap_samples = nullptr,
                                      InteriorMaximum<SphereCapState>* i1_max = nullptr) const {
    const auto end = march(l, std::numeric_limits<double>::infinity(), cap_samples, i1_max);
    const double pull = pressure_ == 0.0 ? f : f - gas_load(kHalfPiCap);
    if (!end || !end->at_equator || !(pull > 0.0)) return std::nullopt;
    const double q_equator = end->vertical;  // R s1 there
    if (!(q_equator <= pull * (1.0 + 1e-9))) return std::nullopt;
    const PartTwoSystem<Law> side = rough_side_system();
    IntegrationSettings integration = part_one_.settings().integration;
    if (cap_samples) integration.max_step = s_.a / std::max(1, part_one_.settings().field_points);
    auto excess = [&](double r, const PartTwoState& y) {
      const double v = r * membrane_stress(law_, y[0], s_.a / r).s1 - pull;
      return std::isfinite(v) ? v : 1.0;
    };
    PartTwoState y{end->state[1], 0.0}, y_prev = y;
    double r_top = end->r, r_prev = end->r, r_hit = -1.0;
    if (q_equator >= pull) {
      observe(r_top, y);
    } else {
      if (!integrate_part(side, y, end->r, 1.0, integration, [&](double r, const PartTwoState& x) {
            if (excess(r, x) >= 0.0) {
              r_hit = r;
              return false;
            }
            r_prev = r;
            y_prev = x;
            observe(r, x);
            return true;
          }))
        return std::nullopt;
      if (r_hit < 0.0)
        return RoughSide{{{0.0, y[0], s_.a, 0.0}, 1.0, kHalfPiCap, 1.0}, -y[1], *end};
      auto gap_at = [&](double r) {
        const auto x = step_or_advance(side, y_prev, r_prev, r, part_one_.settings().integration);
        return x ? excess(r, *x) : 1.0;
      };
      const double g_prev = gap_at(r_prev), g_hit = gap_at(r_hit);
      if (!(g_prev * g_hit <= 0.0)) return std::nullopt;
      r_top = root_in_bracket(gap_at, r_prev, r_hit, g_prev, g_hit);
      const auto x = step_or_advance(side, y_prev, r_prev, r_top, part_one_.settings().integration);
      if (!x) return std::nullopt;
      y = *x;
      observe(r_top, y);
    }
    // lambda1 at the top from R s1 = f - P a^2 / 2 exactly, as the frictionless start has it.
    const double l2 = s_.a / r_top;
    const auto l1 = invert_radial_stress(law_, pull / r_top, l2, y[0]);
    if (!l1) return std::nullopt;
    return RoughSide{{{0.0, *l1, l2, 0.0}, r_top, kHalfPiCap, 1.0}, -y[1], *end};
  }

  // The cap again (samples, largest I1) and the side up to Part I's start (samples from the
  // equator up, psi = pi/2 + height / rho; its largest I1 refined between steps).
  bool attach_rough_side(double l, bool record, ScaledSolution& sol, bool maxima) const {
    InteriorMaximum<SphereCapState> i1_max;
    InteriorMaximum<PartTwoState> side_max;
    std::vector<PartTwoSample> cap_samples, side_samples;
    const auto side = rough_side(
        l,
        sol.f,
        [&](double r, const PartTwoState& y) {
          if (record) side_samples.push_back({r, y[0], y[1]});
          side_max.observe(r, y, first_invariant(y[0], s_.a / r));
        },
        record ? &cap_samples : nullptr,
        &i1_max);
    if (!side) {
      sol.status = Status::NoConvergence;
      sol.message = "the side with friction could not be marched up to where Part I starts again";
      return false;
    }
    track_cap_maximum(i1_max, sol, maxima);
    if (side_max.observed()) track_side_maximum(side_max, rough_side_system(), sol, maxima);
    if (record) {
      sol.part_two = std::move(cap_samples);
      for (const auto& x : side_samples)
        sol.part_two.push_back({x[0], x[1], kHalfPiCap - x[2] / arc()});
    }
    sol.r_corner = side->cap.r;
    sol.part_three_stretch = l;
    sol.part_two_length = side->length;
    sol.depth += arc() + side->length;
    sol.tension_ratio = 1.0;
    return true;
  }

  // The cylinder side with Coulomb slip (and the gas pressure's share of the contact pressure).
  PartTwoSystem<Law> rough_side_system() const {
    return {law_, s_.a, s_.mu, PartTwoEquation::RingBalance, locking_i1_, pressure_};
  }

  // Friction on the side: the pole (face) stretch below the equator onset's (where the side has
  // zero length and the residual is the side indicator, >= 0), from the first of 1 + (onset - 1)
  // 2^-k (k = 1, 2, ...) with a negative clamp residual (a longer side, its top nearer the
  // clamp); the candidate before it caps the bracket.
  template <class Residual>
  ShootingPlan rough_side_plan(const EquatorOnset& onset, double g_onset, Residual& counted) const {
    ShootingPlan plan;
    plan.configuration = Configuration::SlipWithPartTwo;
    double cap = onset.stretch, g_cap = g_onset;
    for (int k = 1; k <= 60; ++k) {
      const double l = 1.0 + (onset.stretch - 1.0) * std::ldexp(1.0, -k);
      const auto g = counted(Configuration::SlipWithPartTwo, l);
      if (g && *g < 0.0) {
        plan.lo = l;
        plan.g_lo = *g;
        plan.cap = cap;
        plan.g_cap = g_cap;
        plan.no_root_message =
            s_.face > 0.0 ? "filleted flat-punch shooting (side with friction) found no face "
                            "stretch meeting the clamp condition"
                          : "sphere-tipped shooting (side with friction) found no pole stretch "
                            "meeting the clamp condition";
        return plan;
      }
      if (g) {
        cap = l;
        g_cap = *g;
      }
    }
    plan.status = Status::NoConvergence;
    plan.message = s_.face > 0.0 ? "filleted flat-punch shooting (side with friction): no face "
                                   "stretch with a negative clamp residual"
                                 : "sphere-tipped shooting (side with friction): no pole stretch "
                                   "with a negative clamp residual";
    return plan;
  }

  const FreePart<Law>& part_one_;
  const Law& law_;
  SphereTippedSettings s_;
  double locking_i1_;
  double pressure_;     // gas pressure P under the membrane (0: none)
  double tangency_;     // polar angle where the tip sphere ends: pi/2, or the cone's tangency
  double side_radius_;  // radius where the curved profile ends: the cylinder's a, the shank's
  double end_psi_;      // the profile coordinate there (pi/2: the equator; the cone's kink)
  std::shared_ptr<ProfileStickHistory<Law>> held_profile_;  // the stick stage's contact map
  // The last three equator onsets found (the last first) and the forces they carry: the answers
  // when those forces are asked again, and the start of the next (one solve runs single-threaded
  // on its own contact model, whose settings never change).
  struct ForceOnset {
    double f;
    EquatorOnset onset;
    double dv_dl = 0.0;  // dV/dLambda there, as the secant steps that found it measured it (or 0)
  };
  mutable std::array<std::optional<ForceOnset>, 3> onsets_;
  // (force, onset stretch) of the last onsets at distinct forces, the oldest first.
  mutable std::deque<std::pair<double, double>> onset_trail_;
  // (force, side indicator) of keep_side_bracket: the bracket of slip_change's root.
  mutable std::optional<std::pair<double, double>> side_below_, side_above_;
  // The last cap marched to its contact edge (cap_to_edge): the free start's, which the
  // attachment at the same pole stretch and force reuses.
  mutable std::optional<CapMarch> last_cap_;
};

}  // namespace puncture::detail
