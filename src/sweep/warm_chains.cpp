// The warm chains of a grid and how a run's shares take them.
#include "warm_chains.hpp"

#include <algorithm>

namespace puncture::detail {

PointRange ChainLayout::chain(std::size_t c) const {
  const std::size_t line_begin = c / per_line * line;
  const std::size_t begin = c % per_line * length;
  return {line_begin + begin, line_begin + std::min(line, begin + length)};
}

ChainLayout chain_layout(const SweepSpec& spec) {
  ChainLayout layout;
  layout.points = point_count(spec);
  // A chain carries the puncture search's start: without a puncture there is nothing to carry.
  if (spec.design != SweepDesign::Grid || !spec.warm_start || !spec.outputs.puncture ||
      spec.parameters.empty())
    return layout;
  layout.line = spec.parameters.back().levels.size();
  layout.length = std::min(layout.line, kWarmChainPoints);
  layout.per_line = (layout.line + layout.length - 1) / layout.length;
  return layout;
}

std::size_t ShareChains::delivered_begin(std::size_t m) const {
  return std::max(solved(m).begin, first);
}

ShareChains share_chains(const SweepSpec& spec, std::size_t first, std::size_t offset,
                         std::size_t stride) {
  ShareChains share;
  share.layout = chain_layout(spec);
  share.first = first;
  share.offset = offset;
  share.stride = stride;
  if (first >= share.layout.points) return share;
  const std::size_t from = share.layout.chain_of(first) + offset;
  const std::size_t chains = share.layout.chain_count();
  share.count = from < chains ? (chains - from + stride - 1) / stride : 0;
  if (share.layout.length == 1) {  // every point its own chain
    share.points = share.count;
    return share;
  }
  for (std::size_t m = 0; m < share.count; ++m) share.points += share.delivered(m);
  return share;
}

}  // namespace puncture::detail

namespace puncture {

PointRange warm_chain_of(const SweepSpec& spec, std::size_t index) {
  if (auto errors = validation_errors(spec); !errors.empty())
    throw InvalidInput(std::move(errors), "invalid sweep:");
  const detail::ChainLayout layout = detail::chain_layout(spec);
  if (index >= layout.points)
    throw InvalidInput("index",
                       "index: point " + std::to_string(index) + " is beyond the sweep's " +
                           std::to_string(layout.points) + " points");
  return layout.chain(layout.chain_of(index));
}

std::size_t share_of_point(const SweepSpec& spec, std::size_t first_point, std::size_t stride,
                           std::size_t index) {
  const detail::ChainLayout layout = detail::chain_layout(spec);
  if (stride < 1 || index < first_point || index >= layout.points)
    throw InvalidInput("index",
                       "share_of_point: needs stride >= 1 and first_point <= index < the sweep's "
                       "points");
  return (layout.chain_of(index) - layout.chain_of(first_point)) % stride;
}

}  // namespace puncture
