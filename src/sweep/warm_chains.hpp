#pragma once
// The warm chains of a sweep (SweepSpec::warm_start): which points are solved one after another
// from the previous one's puncture, and how the chains are dealt to the shares of a run.
#include <cstddef>

#include "puncture/sweep.hpp"

namespace puncture::detail {

// A grid line of `line` points cut into `per_line` chains of at most `length`; without chains,
// line = length = per_line = 1 (every point its own chain).
struct ChainLayout {
  std::size_t points = 0;
  std::size_t line = 1;
  std::size_t length = 1;
  std::size_t per_line = 1;

  std::size_t chain_count() const { return points / line * per_line; }
  std::size_t chain_of(std::size_t index) const {
    return index / line * per_line + index % line / length;
  }
  PointRange chain(std::size_t c) const;
};

// Of a valid spec: chains along the last parameter of a grid whose puncture is solved, with
// warm_start on; none otherwise.
ChainLayout chain_layout(const SweepSpec& spec);

// The chains of one share of a run from `first`: c0 + offset + m stride (m = 0 .. count - 1),
// c0 the chain of `first`; each delivers its points from `first` on.
struct ShareChains {
  ChainLayout layout;
  std::size_t first = 0, offset = 0, stride = 1;
  std::size_t count = 0;   // chains
  std::size_t points = 0;  // points delivered (from `first` on)

  std::size_t chain(std::size_t m) const { return layout.chain_of(first) + offset + m * stride; }
  // The points of chain m: solved from `solved.begin`, delivered from `delivered_begin` on.
  PointRange solved(std::size_t m) const { return layout.chain(chain(m)); }
  std::size_t delivered_begin(std::size_t m) const;
  std::size_t delivered(std::size_t m) const { return solved(m).end - delivered_begin(m); }
};

ShareChains share_chains(const SweepSpec& spec, std::size_t first, std::size_t offset,
                         std::size_t stride);

}  // namespace puncture::detail
