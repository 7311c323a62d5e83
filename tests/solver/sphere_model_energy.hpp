#pragma once
// The stored energy and depth of a sphere-model contact's equilibrium (the sphere-tipped probe,
// the flat punch with a rounded corner), computed apart from the solver's own bookkeeping: the
// work-conjugacy tests differentiate them.
#include <array>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <limits>
#include <optional>
#include <type_traits>

#include "indentation/contact/flat_punch_side.hpp"
#include "indentation/shooting.hpp"
#include "mechanics/free_membrane_ode.hpp"
#include "mechanics/inverse_stretch.hpp"

namespace puncture::test {

// Stored energy (/ (2 pi G H A^2)) and depth (/ A) of the equilibrium at force f, each part
// integrated independently of the solve's own bookkeeping: the cap's int W R dR from its march
// (with a flat face, the face's W(l, l) R_b^2 / 2 is the march's start),
// the side's by Gauss-Kronrod quadrature of W(lambda1(R), a / R) R with lambda1 from R s1 = f
// (with friction, marched up from the equator with its ring balance: rough_side_energy),
// Part I by the free-membrane system that carries the energy (StrainsAndIntegrals).
struct EnergyAndDepth {
  double energy;
  double depth;
  Configuration configuration;
};

// The cylinder side with Coulomb slip (docs/model.md §15, §19), marched up from the equator
// (R_e, lambda1_e) with the flat punch's ring balance d(R s1)/dR = mu s2, and its stored energy
// int W R dR to R_top.  State (lambda1, y, e), y = minus the height above the equator.
template <class Law>
struct RoughSideWithEnergy {
  detail::PartTwoSystem<Law> side;
  void operator()(const std::array<double, 3>& x, std::array<double, 3>& dx, double r) const {
    detail::PartTwoState y{x[0], x[1]}, dy{};
    side(y, dy, r);
    dx[0] = dy[0];
    dx[1] = dy[1];
    const double l2 = side.a / r;
    dx[2] = strain_energy_density(side.law, x[0], l2, first_invariant(x[0], l2)) * r;
  }
};

template <class Law>
std::optional<double> rough_side_energy(const Law& law, double a, double mu, double r_equator,
                                        double l1_equator, double r_top) {
  const RoughSideWithEnergy<Law> system{
      {law, a, mu, PartTwoEquation::RingBalance, law.locking_i1()}};
  std::array<double, 3> x{l1_equator, 0.0, 0.0};
  if (r_top > r_equator &&
      !detail::integrate_part(system,
                              x,
                              r_equator,
                              r_top,
                              detail::IntegrationSettings{1e-13, 1e-15, 1000000},
                              [](double, const auto&) { return true; }))
    return std::nullopt;
  return x[2];
}

// Part I's stored energy from its start `st` (a FreeStart) to the clamp (/ (2 pi G H A^2)) at
// force f without a gas pressure: integrated in strains with the running energy, to 1e-13; empty
// where the integration fails.
template <class Law, class Start>
std::optional<double> part_one_energy(const Law& law, double f, const Start& st) {
  using namespace puncture::detail;
  const FreeMembraneSystem<Law, StrainsAndIntegrals> system{
      law, TransverseLoad{f, 0.0}, law.locking_i1()};
  StrainsAndIntegrals::State x{st.state[0], st.state[1] - 1.0, st.state[2] - 1.0, 0.0, 0.0, 0.0};
  const IntegrationSettings integration{1e-13, 1e-15, 1000000};
  if (!integrate_part(system, x, st.r0, 1.0, integration, [](double, const auto&) { return true; }))
    return std::nullopt;
  return x[5];
}

template <class Shooting>
std::optional<EnergyAndDepth> energy_at(const Shooting& shooting, double f) {
  using namespace puncture::detail;
  const auto sol = shooting.solve(Stage::Slip, f);
  if (!sol.ok()) return std::nullopt;
  const auto& contact = shooting.contact();
  const auto& law = contact.law();
  const double a = contact.settings().a;
  const auto st = contact.free_start(sol.configuration, f, sol.parameter);
  if (!st) return std::nullopt;
  double energy = 0.0;
  if (sol.configuration == Configuration::SlipWithoutPartTwo) {
    const auto cap = contact.march(sol.parameter, f);
    if (!cap) return std::nullopt;
    energy += cap->state[2];
  } else if (contact.settings().mu != 0.0) {
    // Coulomb slip on the side: the cap at the pole stretch up to the equator, then the side
    // marched up with its ring balance and its energy to Part I's start.
    const auto cap = contact.march(sol.parameter, std::numeric_limits<double>::infinity());
    if (!cap || !cap->at_equator) return std::nullopt;
    energy += cap->state[2];
    const auto side =
        rough_side_energy(law, a, contact.settings().mu, cap->r, cap->state[1], st->r0);
    if (!side) return std::nullopt;
    energy += *side;
  } else {
    const auto onset = contact.equator_onset(f);
    if (!onset) return std::nullopt;
    energy += onset->end.state[2];
    auto side_density = [&](double r) {
      const double l2 = a / r;
      const double l1 = *invert_radial_stress(law, f / r, l2);
      return strain_energy_density(law, l1, l2, first_invariant(l1, l2)) * r;
    };
    energy += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
        side_density, onset->end.r, st->r0, 15, 1e-14);
  }
  // Part I from its start, in strains with the running energy.
  const auto part_one = part_one_energy(law, f, *st);
  if (!part_one) return std::nullopt;
  energy += *part_one;
  return EnergyAndDepth{energy, sol.depth, sol.configuration};
}

}  // namespace puncture::test
