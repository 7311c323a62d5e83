#pragma once
// The root of a residual increasing in x on (floor, inf), bracketed outward from a guess: the
// held membrane's edge stretch (contact/*_stick.hpp, flat_punch_held_face.hpp), where the
// previous history point's stretch is the guess and a stretch past locking is beyond the root.
#include <algorithm>
#include <optional>

#include "numerics/root_in_bracket.hpp"
#include "numerics/shooting.hpp"

namespace puncture::detail {

// Up from the guess while g is negative, down towards the floor while positive (a step that
// doubles each time); a value outside g's domain (empty) counts as beyond (positive).  Empty if
// no sign change is found.
template <class Residual>
std::optional<double> root_from_guess(Residual& g, double guess, double floor) {
  double lo = std::max(guess, floor * (1.0 + 1e-12)), hi = lo;
  double g_lo = residual_or_beyond(g, lo), g_hi = g_lo;
  double d = 1e-3 * (lo - floor) + 1e-9;
  for (int k = 0; k < 80 && g_hi < 0.0; ++k, d *= 2.0) {
    lo = hi;
    g_lo = g_hi;
    hi = lo + d;
    g_hi = residual_or_beyond(g, hi);
  }
  for (int k = 0; k < 80 && g_lo >= 0.0; ++k) {
    hi = lo;
    g_hi = g_lo;
    lo = std::max(hi - d, floor + 0.5 * (hi - floor));
    d *= 2.0;
    g_lo = residual_or_beyond(g, lo);
  }
  if (!(g_lo < 0.0) || !(g_hi >= 0.0) || g_hi >= kBeyondDomain) return std::nullopt;
  return root_in_bracket([&](double x) { return residual_or_beyond(g, x); }, lo, hi, g_lo, g_hi);
}

}  // namespace puncture::detail
