// The free membrane's ODE (src/mechanics/free_membrane_ode.hpp) under a point force, a pressure
// or both.  Under one load alone its right-hand side must equal, bit for bit, the systems Part I
// and the inflation integrated before they shared it (copied below as they were); under both,
// the vertical balance R s1 sin(phi) = f + P r^2 / 2 must hold along an integrated solution.
// That balance is not imposed by the integration: lambda1 follows from d(R s1)/dR = s2 cos(phi)
// and t from the radial balance with the pressure's share, and R s1(lambda1, lambda2) equals
// sqrt(t^2 + g^2) all along only if that share is right for the combined load.
#include "mechanics/free_membrane_ode.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>

#include "numerics/integrate.hpp"
#include "puncture/material.hpp"

namespace puncture::detail {
namespace {

// Part I's system before the merge (commit 29ee6e2, src/mechanics/free_membrane_ode.hpp).
template <class Law>
struct ForceOnlyReference {
  const Law& law;
  double f;
  double max_i1;

  void operator()(const std::array<double, 4>& x, std::array<double, 4>& dx, double r_ref) const {
    const double t = x[0], l1 = x[1], l2 = x[2];
    if (!(l1 > 0.0) || !(l2 > 0.0)) throw IntegrationFailure{};
    const auto st = membrane_stress(law, l1, l2);
    if (!(st.i1 < max_i1) || !std::isfinite(st.ds1_dl1)) throw IntegrationFailure{};
    const double s_total = std::sqrt(t * t + f * f);
    const double cos_phi = t / s_total, sin_phi = f / s_total;
    const double dl2 = (l1 * cos_phi - l2) / r_ref;
    const double dl1 = (cos_phi * st.s2 - st.s1 - r_ref * st.ds1_dl2 * dl2) / (r_ref * st.ds1_dl1);
    dx[0] = st.s2;
    dx[1] = dl1;
    dx[2] = dl2;
    dx[3] = l1 * sin_phi;
  }
};

// The inflation's system before the merge (commit 29ee6e2, src/inflation/inflation_ode.hpp).
template <class Law>
struct PressureOnlyReference {
  const Law& law;
  double pressure;
  double max_i1;

  void operator()(const std::array<double, 6>& x, std::array<double, 6>& dx, double r_ref) const {
    const double t = x[0], l1 = 1.0 + x[1], l2 = 1.0 + x[2];
    if (!(l1 > 0.0) || !(l2 > 0.0)) throw IntegrationFailure{};
    const auto st = membrane_stress(law, l1, l2);
    if (!(st.i1 < max_i1) || !(st.ds1_dl1 > 0.0) || !std::isfinite(st.ds1_dl1))
      throw IntegrationFailure{};
    const double r = l2 * r_ref;
    const double g = 0.5 * pressure * r * r;
    const double s_total = std::hypot(t, g);
    const double cos_phi = t / s_total, sin_phi = g / s_total;
    const double one_minus_cos = t > 0.0 ? g * g / (s_total * (s_total + t)) : 1.0 - cos_phi;
    const double dl2 = (x[1] * cos_phi - x[2] - one_minus_cos) / r_ref;
    const double dl1 = (cos_phi * st.s2 - st.s1 - r_ref * st.ds1_dl2 * dl2) / (r_ref * st.ds1_dl1);
    dx[0] = st.s2 - pressure * r * l1 * sin_phi;
    dx[1] = dl1;
    dx[2] = dl2;
    dx[3] = l1 * sin_phi;
    dx[4] = std::numbers::pi * r * r * l1 * sin_phi;
    dx[5] = strain_energy_density(law, l1, l2, st.i1) * r_ref;
  }
};

const MaterialLaw kLaws[] = {
    Gent{125.0},
    Gent{10.0},
    NeoHookean{},
    MooneyRivlin{0.2},
    Yeoh{0.05, 0.001},
    std::get<Ogden>(ogden_material({0.63, 0.0012, -0.01}, {1.3, 5.0, -2.0}).law),
    ArrudaBoyce{50.0},
    GentGent{125.0, 0.2}};

std::string name_of(const MaterialLaw& law) {
  return std::visit([](const auto& l) { return std::string(l.name()); }, law);
}

// Both systems at one point: both leave the domain (the reference throws, the library's returns
// NaN), or neither does and every component has the same bits.
// True when neither threw (the point is inside the material's domain).
template <class State, class A, class B>
bool expect_same_bits(const A& a, const B& b, const State& x, double r_ref,
                      const std::string& where) {
  State da{}, db{};
  bool threw_a = false, threw_b = false;
  try {
    a(x, da, r_ref);
  } catch (const IntegrationFailure&) {
    threw_a = true;
  }
  b(x, db, r_ref);
  threw_b = !all_finite(db);  // the library's systems return NaN outside the domain
  EXPECT_EQ(threw_a, threw_b) << where;
  if (threw_a || threw_b) return false;
  for (std::size_t k = 0; k < x.size(); ++k)
    EXPECT_EQ(std::bit_cast<std::uint64_t>(da[k]), std::bit_cast<std::uint64_t>(db[k]))
        << where << ", component " << k << ": " << da[k] << " vs " << db[k];
  return true;
}

TEST(FreeMembraneOdeSolver, PointForceAloneIsPartOneBitForBit) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> t_of(-0.3, 1.5), l_of(0.7, 4.0), r_of(0.01, 1.0),
      f_of(1e-4, 1.5);
  int inside = 0;  // points inside the material's domain (the others throw in both)
  for (const auto& law : kLaws)
    std::visit(
        [&](const auto& l) {
          using Law = std::decay_t<decltype(l)>;
          for (int k = 0; k < 4000; ++k) {
            const double f = f_of(rng), r_ref = r_of(rng);
            const Stretches::State x{t_of(rng), l_of(rng), l_of(rng), 0.1};
            const ForceOnlyReference<Law> before{l, f, l.locking_i1()};
            const FreeMembraneSystem<Law, Stretches> now{l, TransverseLoad{f, 0.0}, l.locking_i1()};
            inside +=
                expect_same_bits(before, now, x, r_ref, name_of(law) + " #" + std::to_string(k));
          }
        },
        law);
  EXPECT_GT(inside, 12000);
}

TEST(FreeMembraneOdeSolver, PressureAloneIsTheInflationBitForBit) {
  std::mt19937_64 rng(20240612);
  std::uniform_real_distribution<double> t_of(-0.3, 1.5), e_of(-0.3, 3.0), r_of(1e-4, 1.0),
      log_p_of(-6.0, 0.7);
  int inside = 0;
  for (const auto& law : kLaws)
    std::visit(
        [&](const auto& l) {
          using Law = std::decay_t<decltype(l)>;
          for (int k = 0; k < 4000; ++k) {
            const double pressure = std::pow(10.0, log_p_of(rng)), r_ref = r_of(rng);
            // Small strains as well as large: the layout's cancellation-free branch.
            const double scale = k % 2 == 0 ? 1.0 : 1e-5;
            const StrainsAndIntegrals::State x{
                t_of(rng), scale * e_of(rng), scale * e_of(rng), 0.1, 0.2, 0.3};
            const PressureOnlyReference<Law> before{l, pressure, l.locking_i1()};
            const FreeMembraneSystem<Law, StrainsAndIntegrals> now{
                l, TransverseLoad{0.0, pressure}, l.locking_i1()};
            inside +=
                expect_same_bits(before, now, x, r_ref, name_of(law) + " #" + std::to_string(k));
          }
        },
        law);
  EXPECT_GT(inside, 12000);
}

// The two layouts describe the same membrane: under the same combined load their common
// derivatives agree to rounding.
TEST(FreeMembraneOdeSolver, LayoutsAgreeUnderCombinedLoad) {
  std::mt19937_64 rng(20240613);
  std::uniform_real_distribution<double> t_of(0.05, 1.5), l_of(1.05, 3.0), r_of(0.05, 1.0),
      f_of(-0.2, 0.5), p_of(0.0, 2.0);
  const Gent law{125.0};
  for (int k = 0; k < 2000; ++k) {
    const TransverseLoad load{f_of(rng), p_of(rng)};
    const double r_ref = r_of(rng), t = t_of(rng), l1 = l_of(rng), l2 = l_of(rng);
    const Stretches::State xs{t, l1, l2, 0.0};
    const StrainsAndIntegrals::State xe{t, l1 - 1.0, l2 - 1.0, 0.0, 0.0, 0.0};
    Stretches::State ds{};
    StrainsAndIntegrals::State de{};
    FreeMembraneSystem<Gent, Stretches>{law, load, law.locking_i1()}(xs, ds, r_ref);
    FreeMembraneSystem<Gent, StrainsAndIntegrals>{law, load, law.locking_i1()}(xe, de, r_ref);
    for (int j = 0; j < 4; ++j) {
      const double scale = std::abs(ds[0]) + std::abs(ds[1]) + std::abs(ds[2]) + std::abs(ds[3]);
      EXPECT_NEAR(ds[j], de[j], 1e-12 * scale) << "#" << k << ", component " << j;
    }
  }
}

// R s1 / sqrt(t^2 + g^2) - 1 along a solution integrated from a start that satisfies it.
template <class Layout, class System>
double worst_vertical_imbalance(const System& system, const MaterialLaw& law, double l1, double l2,
                                double r0) {
  const double s1 = std::visit([&](const auto& l) { return membrane_stress(l, l1, l2).s1; }, law);
  const double g0 = system.load.vertical(l2 * r0);
  const double s_total = r0 * s1;
  typename Layout::State x{};
  x[0] = std::sqrt((s_total - g0) * (s_total + g0));
  x[1] = Layout::integrals ? l1 - 1.0 : l1;
  x[2] = Layout::integrals ? l2 - 1.0 : l2;
  double worst = 0.0;
  int steps = 0;
  const IntegrationSettings tight{1e-12, 1e-14, 100000};
  const bool reached =
      integrate_part(system, x, r0, 1.0, tight, [&](double r_ref, const typename Layout::State& y) {
        const double a = Layout::lambda1(y), b = Layout::lambda2(y);
        const double rs1 =
            r_ref * std::visit([&](const auto& l) { return membrane_stress(l, a, b).s1; }, law);
        const double g = system.load.vertical(b * r_ref);
        worst = std::max(worst, std::abs(rs1 / std::hypot(y[0], g) - 1.0));
        ++steps;
        return true;
      });
  EXPECT_TRUE(reached);
  EXPECT_GT(steps, 5);
  return worst;
}

// The combined load without the pressure's share in the radial balance (dt/dR = s2): what the
// check below must be able to tell from the right equations.
template <class Law>
struct WithoutRadialPressure {
  FreeMembraneSystem<Law, Stretches> system;
  TransverseLoad load;
  void operator()(const Stretches::State& x, Stretches::State& dx, double r_ref) const {
    system(x, dx, r_ref);
    const double l1 = x[1], r = x[2] * r_ref, g = load.vertical(r);
    dx[0] += load.pressure * r * l1 * g / std::hypot(x[0], g);
  }
};

TEST(FreeMembraneOdeSolver, CombinedLoadKeepsTheVerticalBalance) {
  struct Load {
    double f, pressure;
  };
  // Force and pressure pushing together, and a force against the pressure (an indenter on an
  // inflated dome: f < 0 in this sign convention), the vertical load changing sign along the way.
  // From lambda1 = 1.5, lambda2 = 1.3 at R = 0.2 every law reaches R = 1 without turning back.
  for (const Load c : {Load{0.05, 0.5}, Load{0.1, 0.3}, Load{0.02, 1.0}, Load{-0.02, 0.5}})
    for (const auto& law : kLaws)
      std::visit(
          [&](const auto& l) {
            using Law = std::decay_t<decltype(l)>;
            const TransverseLoad load{c.f, c.pressure};
            const std::string where = name_of(law) + " at f = " + std::to_string(c.f) +
                                      ", P = " + std::to_string(c.pressure);
            const FreeMembraneSystem<Law, Stretches> stretches{l, load, l.locking_i1()};
            const FreeMembraneSystem<Law, StrainsAndIntegrals> strains{l, load, l.locking_i1()};
            EXPECT_LT(worst_vertical_imbalance<Stretches>(stretches, law, 1.5, 1.3, 0.2), 1e-10)
                << where;
            EXPECT_LT(worst_vertical_imbalance<StrainsAndIntegrals>(strains, law, 1.5, 1.3, 0.2),
                      1e-10)
                << where;
            // Without the pressure's radial share the balance drifts far: the check can tell.
            const WithoutRadialPressure<Law> wrong{stretches, load};
            EXPECT_GT(worst_vertical_imbalance<Stretches>(wrong, law, 1.5, 1.3, 0.2), 1e-3)
                << where;
          },
          law);
}

}  // namespace
}  // namespace puncture::detail
