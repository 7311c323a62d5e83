#pragma once
// Counter-based randomness for the sweep's point list: every number is a hash of (seed, point,
// parameter), so point i's inputs never depend on which points were drawn before it.
#include <cstddef>
#include <cstdint>

namespace puncture::detail {

// SplitMix64's finaliser (Steele, Lea and Flood 2014): a bijection of 64-bit words that mixes
// every input bit into every output bit.
constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

constexpr std::uint64_t hash64(std::uint64_t seed, std::uint64_t a, std::uint64_t b = 0,
                               std::uint64_t c = 0) {
  return mix64(mix64(mix64(mix64(seed) ^ a) ^ b) ^ c);
}

// A uniform number in (0, 1) from 53 bits of a hash: (k + 1/2) / 2^53, never 0 or 1.
constexpr double unit_open(std::uint64_t bits) {
  return (static_cast<double>(bits >> 11) + 0.5) * 0x1.0p-53;
}

// A pseudo-random permutation of {0, ..., n - 1} evaluated one index at a time (memory flat in
// n): a four-round Feistel network on the smallest even number of bits covering n, walked along
// its cycle until it lands below n (a permutation of the larger domain restricted to the
// smaller; fewer than four steps on average).
class IndexPermutation {
 public:
  IndexPermutation(std::size_t n, std::uint64_t key) : n_(n), key_(key) {
    while ((std::uint64_t{1} << (2 * half_bits_)) < n_) ++half_bits_;
    mask_ = (std::uint64_t{1} << half_bits_) - 1;
  }

  std::size_t operator()(std::size_t index) const {
    std::uint64_t x = index;
    do x = encrypt(x);
    while (x >= n_);
    return static_cast<std::size_t>(x);
  }

 private:
  std::uint64_t encrypt(std::uint64_t x) const {
    std::uint64_t left = x >> half_bits_, right = x & mask_;
    for (std::uint64_t round = 0; round < 4; ++round) {
      const std::uint64_t next = left ^ (hash64(key_, round, right) & mask_);
      left = right;
      right = next;
    }
    return (left << half_bits_) | right;
  }

  std::uint64_t n_;
  std::uint64_t key_;
  unsigned half_bits_ = 1;
  std::uint64_t mask_ = 1;
};

}  // namespace puncture::detail
