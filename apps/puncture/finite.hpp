#pragma once
// Guards on every number written: the tool never prints NaN or infinity.
#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "cli_error.hpp"

namespace puncture::cli {

// `x`, or a SolveError naming the quantity when it is not a finite number.
inline double finite(double x, std::string_view what) {
  if (!std::isfinite(x))
    throw SolveError(
        fmt::format("the result '{}' is not a finite number; no output was written", what));
  return x;
}

// For a quantity that is legitimately unbounded in some states (e.g. the corner tension ratio
// of a membrane held at the edge): empty when +-infinity, a SolveError when NaN.
inline std::optional<double> finite_or_unbounded(double x, std::string_view what) {
  if (std::isinf(x)) return std::nullopt;
  return finite(x, what);
}

// A number of the readable summaries, 5 significant digits, checked finite.
inline std::string num(double x, std::string_view what) {
  return fmt::format("{:.5g}", finite(x, what));
}

}  // namespace puncture::cli
