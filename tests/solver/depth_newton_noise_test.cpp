// DepthNewton::guarded (indentation/depth_newton.hpp) on a model shooting whose depth carries
// rounding-like noise of a chosen size: Newton cannot meet its tolerance below that noise, and the
// guarded solve then returns its best state when the noise is within its noise tolerance, and
// nothing when it is not; without noise the guarded solve is Newton's own.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>

#include "indentation/depth_newton.hpp"

namespace puncture::test {
namespace {

using detail::DepthNewton;
using detail::ScaledSolution;

// An ill-conditioned pair like the sphere-tipped probe's near zero load (bench/README.md): at
// force f and pole strain e = p - 1, clamp residual e (ln(e / e0) - ln(f / f0) / 2) and depth
// d0 (f / f0)^(1/3) (e / e0)^(-1/4), with the depth times (1 + noise * h), h in [-1, 1] a hash of
// the bits of (f, p): noise that no smooth model has.
struct NoisyModelShooting {
  double noise = 0.0;
  static constexpr double kE0 = 2.7e-4, kF0 = 1.4e-7, kD0 = 6.2e-3;
  double parameter_floor(Configuration) const { return 1.0; }
  ScaledSolution assemble(Configuration c, double f, double p, bool, bool = true) const {
    ScaledSolution s;
    s.configuration = c;
    s.f = f;
    s.parameter = p;
    const double e = p - 1.0;
    std::uint64_t h = std::bit_cast<std::uint64_t>(f) * 0x9E3779B97F4A7C15ULL ^
                      std::bit_cast<std::uint64_t>(p) * 0xC2B2AE3D27D4EB4FULL;
    h ^= h >> 29;
    const double unit = static_cast<double>(h % 2000001) / 1e6 - 1.0;  // in [-1, 1]
    s.residual = e * (std::log(e / kE0) - 0.5 * std::log(f / kF0));
    s.depth = kD0 * std::cbrt(f / kF0) * std::pow(e / kE0, -0.25) * (1.0 + noise * unit);
    s.integrated = true;
    s.status = Status::Converged;
    return s;
  }
  ScaledSolution assemble_at_contact(Configuration c, double q, double p, bool) const {
    return assemble(c, q - p, p, false);
  }
};

constexpr auto kNoisyModelConfiguration = Configuration::SlipWithoutPartTwo;

TEST(DepthNewtonNoise, GuardedSolveEndsOnTheNoiseWithinItsTolerance) {
  const NoisyModelShooting model{1e-8};
  const double d = 1.1 * NoisyModelShooting::kD0, f0 = 1.5e-7, p0 = 1.0 + 3e-4;
  DepthNewton<NoisyModelShooting> plain(model, 1e-9);
  EXPECT_FALSE(plain.solve(kNoisyModelConfiguration, d, f0, p0));  // 1e-8 of noise: 1e-9 is not met
  DepthNewton<NoisyModelShooting> guarded(model, 1e-9);
  guarded.guarded(1e-7);
  const auto s = guarded.solve(kNoisyModelConfiguration, d, f0, p0);
  ASSERT_TRUE(s);
  // Its residuals are the noise's size: the depth within 1e-7 (the noise tolerance), in fact
  // within a few times the noise; the clamp residual relative to e as the solver judges it.
  EXPECT_LE(std::abs(s->depth - d) / d, 3e-8);
  EXPECT_LE(std::abs(s->residual) / (s->parameter - 1.0), 3e-8);
  // ... and the force within the noise's reach of the noise-free root: e = e0 (f / f0)^(1/2)
  // meets the clamp condition, so d = d0 (f / f0)^(5/24) and f = f0 (d / d0)^(24/5); a relative
  // depth error moves f by 24/5 of it.
  const double f_exact = NoisyModelShooting::kF0 * std::pow(d / NoisyModelShooting::kD0, 4.8);
  EXPECT_LE(std::abs(s->f - f_exact) / f_exact, 4.8 * 3e-8);
}

TEST(DepthNewtonNoise, GuardedSolveRefusesNoiseBeyondItsTolerance) {
  const NoisyModelShooting model{1e-6};
  DepthNewton<NoisyModelShooting> guarded(model, 1e-9);
  guarded.guarded(1e-7);
  EXPECT_FALSE(
      guarded.solve(kNoisyModelConfiguration, 1.1 * NoisyModelShooting::kD0, 1.5e-7, 1.0 + 3e-4));
}

TEST(DepthNewtonNoise, WithoutNoiseTheGuardChangesNothing) {
  const NoisyModelShooting model{0.0};
  const double d = 1.3 * NoisyModelShooting::kD0, f0 = 2e-7, p0 = 1.0 + 3.5e-4;
  DepthNewton<NoisyModelShooting> plain(model, 1e-9), guarded(model, 1e-9);
  guarded.guarded(1e-7);
  const auto a = plain.solve(kNoisyModelConfiguration, d, f0, p0),
             b = guarded.solve(kNoisyModelConfiguration, d, f0, p0);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->f, b->f);
  EXPECT_EQ(a->parameter, b->parameter);
  EXPECT_LE(std::abs(a->depth - d) / d, 1e-9);
}

}  // namespace
}  // namespace puncture::test
