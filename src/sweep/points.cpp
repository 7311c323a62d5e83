// The deterministic point list: point i from the spec and i alone.
#include "points.hpp"

#include <fmt/format.h>

#include <boost/random/sobol.hpp>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "point_hash.hpp"
#include "puncture/sweep.hpp"

namespace puncture {

namespace {

// Salts keeping the streams of one seed apart.
constexpr std::uint64_t kPointSeed = 1, kStratum = 2, kJitter = 3, kMonteCarlo = 4;

double number_or_nan(const std::string& text) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0' ? x : std::numeric_limits<double>::quiet_NaN();
}

// Grid: the mixed-radix digits of the index, the last parameter fastest.
void grid_levels(const SweepSpec& spec, std::size_t index, SweepPoint& point) {
  const std::size_t d = spec.parameters.size();
  std::vector<std::size_t> digit(d);
  for (std::size_t j = d; j-- > 0;) {
    const std::size_t n = spec.parameters[j].levels.size();
    digit[j] = index % n;
    index /= n;
  }
  for (std::size_t j = 0; j < d; ++j) point.texts[j] = spec.parameters[j].levels[digit[j]];
}

// The unit-cube coordinates u in (0, 1) of the sampled designs.
std::vector<double> unit_coordinates(const SweepSpec& spec, std::size_t index) {
  const std::size_t d = spec.parameters.size();
  const std::size_t n = spec.samples;
  std::vector<double> u(d);
  switch (spec.design) {
    case SweepDesign::LatinHypercube:
      for (std::size_t j = 0; j < d; ++j) {
        const std::size_t stratum =
            detail::IndexPermutation(n, detail::hash64(spec.seed, kStratum, j))(index);
        // Jitter within the stratum, kept 2^-10 of its width off its edges so that rounding
        // never moves a point into the next stratum.
        const double r = 0x1.0p-10 + (1.0 - 0x1.0p-9) * detail::unit_open(detail::hash64(
                                                            spec.seed, kJitter, index, j));
        u[j] = (static_cast<double>(stratum) + r) / static_cast<double>(n);
      }
      break;
    case SweepDesign::Sobol: {
      boost::random::sobol_engine<std::uint32_t, 32> sobol(d);
      sobol.seed(static_cast<std::uint32_t>(
          index));  // skips `index` points (the zero point is never generated)
      for (std::size_t j = 0; j < d; ++j) u[j] = static_cast<double>(sobol()) * 0x1.0p-32;
      break;
    }
    case SweepDesign::MonteCarlo:
      for (std::size_t j = 0; j < d; ++j)
        u[j] = detail::unit_open(detail::hash64(spec.seed, kMonteCarlo, index, j));
      break;
    case SweepDesign::Grid:
      break;
  }
  return u;
}

}  // namespace

SweepPoint sweep_point(const SweepSpec& spec, std::size_t index) {
  if (const auto errors = validation_errors(spec); !errors.empty())
    throw InvalidInput(errors, "invalid sweep:");
  const std::size_t count = point_count(spec);
  if (index >= count)
    throw InvalidInput("index",
                       fmt::format("index: point {} of a sweep of {} points", index, count));
  return detail::point_of_valid_spec(spec, index);
}

SweepPoint detail::point_of_valid_spec(const SweepSpec& spec, std::size_t index) {
  SweepPoint point;
  point.index = index;
  point.seed = detail::hash64(spec.seed, kPointSeed, index);
  const std::size_t d = spec.parameters.size();
  point.texts.resize(d);
  point.values.resize(d);
  if (spec.design == SweepDesign::Grid) {
    grid_levels(spec, index, point);
    for (std::size_t j = 0; j < d; ++j) point.values[j] = number_or_nan(point.texts[j]);
  } else {
    const std::vector<double> u = unit_coordinates(spec, index);
    for (std::size_t j = 0; j < d; ++j) {
      point.values[j] = spec.parameters[j].distribution.quantile(u[j]);
      point.texts[j] = fmt::format("{}", point.values[j]);  // shortest form reading back exactly
    }
  }
  return point;
}

}  // namespace puncture
