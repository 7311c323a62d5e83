#pragma once
// Seeded random membranes over the documented parameter ranges, for the reliability sweep.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "puncture/problem.hpp"

namespace puncture::test {

// Log-uniform in [lo, hi]: the ranges span decades.
inline double log_uniform(std::mt19937_64& gen, double lo, double hi) {
  return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(gen));
}
inline double uniform(std::mt19937_64& gen, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(gen);
}

// The laws drawn: the paper's three, or Yeoh's alone.
enum class Laws { Paper, Yeoh };
// How the membrane is mounted: stress-free, pre-stretched by L0 in [1.001, 3] (log-uniform in
// L0 - 1), with the mounted I1 at most half the critical one, or inflated by a gas pressure p with
// p A / (G H) log-uniform in [0.01, 1.2] (below the limit points: nearer to them, with 1.2 to 2,
// 1 in 300 failed numerically, seed 20261127 case 277, docs/model.md §17),
// sliding and frictionless, the flat punch (even cases) or the sphere-tipped probe (odd cases).
enum class Mounting { StressFree, Prestretched, Inflated };

// Case `index` of the sweep with `seed`: clamp 5-100 mm, a/A 1e-3-0.5, H 0.01-2 mm,
// G 0.005-5 MPa, Gent (J_lim 10-1000), neo-Hookean or Mooney-Rivlin (alpha 0-0.5) -- or Yeoh
// (C20/G 1e-4-0.1, C30/G 1e-6-1e-2, each zero a fifth of the time) --, friction 0-10 (a quarter
// frictionless), every stick rule, both Part II equations, and a critical I1 between 5 and 200
// below the law's locking value.
inline Problem random_membrane(std::uint64_t seed, int index, Laws laws = Laws::Paper,
                               Mounting mounting = Mounting::StressFree) {
  std::mt19937_64 gen(seed * 1000003u + static_cast<std::uint64_t>(index));
  Problem p;
  p.geometry.clamp_radius_mm = log_uniform(gen, 5.0, 100.0);
  p.indenter = FlatPunch{p.geometry.clamp_radius_mm * log_uniform(gen, 1e-3, 0.5)};
  p.geometry.thickness_mm = log_uniform(gen, 0.01, 2.0);
  p.material.shear_modulus_mpa = log_uniform(gen, 0.005, 5.0);
  double locking = INFINITY;
  if (laws == Laws::Yeoh) {
    const double c2 = uniform(gen, 0.0, 1.0) < 0.2 ? 0.0 : log_uniform(gen, 1e-4, 0.1);
    const double c3 = uniform(gen, 0.0, 1.0) < 0.2 ? 0.0 : log_uniform(gen, 1e-6, 1e-2);
    p.material.law = Yeoh{c2, c3};
  } else {
    switch (std::uniform_int_distribution<int>(0, 2)(gen)) {
      case 0: {
        const double j_lim = log_uniform(gen, 10.0, 1000.0);
        p.material.law = Gent{j_lim};
        locking = 3.0 + j_lim;
        break;
      }
      case 1:
        p.material.law = NeoHookean{};
        break;
      default:
        p.material.law = MooneyRivlin{uniform(gen, 0.0, 0.5)};
        break;
    }
  }
  p.friction = uniform(gen, 0.0, 1.0) < 0.25 ? 0.0 : log_uniform(gen, 0.01, 10.0);
  p.critical_i1 = std::min(log_uniform(gen, 5.0, 200.0), 3.0 + 0.9 * (locking - 3.0));
  p.part_two_equation =
      uniform(gen, 0.0, 1.0) < 0.8 ? PartTwoEquation::RingBalance : PartTwoEquation::PaperEq18;
  const double force_scale = force_scale_n(p);
  switch (std::uniform_int_distribution<int>(0, 4)(gen)) {
    case 0:
      p.stick = {StickRule::None, 0.0};
      break;
    case 1:
      p.stick = {StickRule::Force, force_scale * log_uniform(gen, 1e-3, 0.3)};
      break;
    case 2:
      p.stick = {StickRule::Depth, p.geometry.clamp_radius_mm * log_uniform(gen, 0.01, 0.5)};
      break;
    case 3:
      p.stick = {
          StickRule::EdgeTension,
          p.material.shear_modulus_mpa * p.geometry.thickness_mm * log_uniform(gen, 0.01, 2.0)};
      break;
    default:
      p.stick = {StickRule::Always, 0.0};
      break;
  }
  // Drawn last, so that the stress-free sweeps keep their membranes.
  if (mounting == Mounting::Prestretched) {
    const double l0 = 1.0 + log_uniform(gen, 1e-3, 2.0);
    // 2 L0^2 + L0^-4 <= I1c / 2 holds for L0 <= sqrt(I1c / 4) (the L0^-4 term is below 1).
    const double cap = std::sqrt(std::max(0.25 * p.critical_i1 - 0.5, 1.0));
    p.preload.prestretch = std::min(l0, cap);
  }
  if (mounting == Mounting::Inflated) {
    const double scale =
        p.material.shear_modulus_mpa * p.geometry.thickness_mm / p.geometry.clamp_radius_mm;
    p.preload.pressure_mpa = log_uniform(gen, 0.01, 1.2) * scale;
    p.stick = {StickRule::None, 0.0};
    // Frictionless: the flat punch takes no friction under pressure yet, and the sphere-tipped
    // probe's Coulomb slip was drawn when it ended at the cylinder side (beyond a friction of ~4
    // it fails numerically with or without pressure: seed 20261127 cases 21, 63, 193, 249 of an
    // earlier draw); its side friction (docs/model.md §15) is not drawn here yet.
    p.friction = 0.0;
    if (index % 2 == 1) p.indenter = SphereTipped{radius_mm(p.indenter)};
  }
  return p;
}

}  // namespace puncture::test
