#pragma once
// Gaussian noise that is the same on every platform: std::mt19937 is specified exactly, but
// std::normal_distribution is not, so the normal deviates are made here (Box-Muller).
#include <cmath>
#include <numbers>
#include <random>

namespace puncture::test {

class SeededNoise {
 public:
  SeededNoise(unsigned seed, double sd) : rng_(seed), sd_(sd) {}
  double operator()() {
    // Two uniforms in (0, 1] from 32-bit draws.
    const double u1 = (static_cast<double>(rng_()) + 1.0) / 4294967296.0;
    const double u2 = (static_cast<double>(rng_()) + 1.0) / 4294967296.0;
    return sd_ * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  std::mt19937 rng_;
  double sd_;
};

}  // namespace puncture::test
