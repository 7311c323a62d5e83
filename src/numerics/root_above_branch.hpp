#pragma once
// The root of a residual g, increasing in x, that is undefined below a branch point x_b and
// rises from it like a square root, g ~ c (sqrt(x - x_b) - sqrt(e)), with its root e above x_b,
// e possibly tiny against the distance of a start from it.  (The clamp residual of a membrane on
// a smooth probe near zero load: below x_b Part I turns back towards the axis,
// nested_depth_solve.hpp.)  Newton or the secant on g from above overshoot past x_b there, and
// bracketing solvers fed a stand-in value below it interpolate badly (TOMS 748 took 28
// evaluations on such a bracket at the sphere-tipped curve's seed); x is a quadratic in g on that
// model, so inverse quadratic interpolation through three defined values is exact for it.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace puncture::detail {

struct BranchRoot {
  double x = 0.0;
  double g = 0.0;      // the residual there: within the tolerance, or the noise the bracket met
  double slope = 0.0;  // dg/dx: the secant through the last two defined values
  int evaluations = 0;
};

// How root_above_branch searches.
struct BranchRootSearch {
  double up_step = 0.0;  // the first step up from an undefined start (then doubling)
  double probe = 0.0;    // the forward difference's step for the first slope
  double tol = 0.0;      // on |g|
  int max_evaluations = 40;
  std::optional<double> slope;  // dg/dx known near the root: the probe is spared
  double below = -std::numeric_limits<double>::infinity();  // an x known to lie below the root
};

// From x0: while g is undefined, x grows by up_step, doubling; from the first defined value, a
// step of Newton's method on g |g| (half Newton's on g from above, exact on a square root) with
// the slope by a forward difference (or the known one), then inverse quadratic interpolation
// through the last three defined values (the secant through two), kept inside the bracket of the
// values met (bisection otherwise).  The root is the first x with |g| <= tol, or, once the
// bracket is a few ulps wide, the defined x with the smallest |g| met (the evaluations' noise).
// Empty when no defined value is met, the bracket does not close in max_evaluations, or g rises
// nowhere.  G: double -> std::optional<double> (empty: undefined, below the branch point).
template <class G>
std::optional<BranchRoot> root_above_branch(G&& g, double x0, const BranchRootSearch& search) {
  const double up_step = search.up_step, probe = search.probe, tol = search.tol;
  const int max_evaluations = search.max_evaluations;
  const std::optional<double> known_slope = search.slope;
  struct Trial {
    double x, g;
  };
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lo = search.below, hi = inf;  // the largest x below the root, the smallest above it
  std::array<Trial, 3> last{};         // the last defined values, newest first
  int defined = 0, evaluations = 0;
  std::optional<Trial> best;
  auto at = [&](double x) -> std::optional<Trial> {
    ++evaluations;
    const std::optional<double> value = g(x);
    if (!value || !std::isfinite(*value)) {
      lo = std::max(lo, x);
      return std::nullopt;
    }
    const Trial t{x, *value};
    if (t.g < 0.0)
      lo = std::max(lo, x);
    else
      hi = std::min(hi, x);
    last = {t, last[0], last[1]};
    defined = std::min(defined + 1, 3);
    if (!best || std::abs(t.g) < std::abs(best->g)) best = t;
    return t;
  };
  auto found = [&](const Trial& t) {
    const double secant = defined >= 2 && last[0].x != last[1].x
                              ? (last[0].g - last[1].g) / (last[0].x - last[1].x)
                              : 0.0;
    return BranchRoot{t.x, t.g, secant, evaluations};
  };
  std::optional<Trial> t = at(x0);
  for (double step = up_step; !t && evaluations < max_evaluations; step *= 2.0) t = at(lo + step);
  if (!t) return std::nullopt;
  if (std::abs(t->g) <= tol) return found(*t);
  double slope = known_slope.value_or(0.0);
  if (!known_slope) {
    const std::optional<Trial> side = at(t->x + probe);
    if (!side) return std::nullopt;
    if (std::abs(side->g) <= tol) return found(*side);
    slope = (side->g - t->g) / probe;
  }
  if (!(slope > 0.0) || !std::isfinite(slope)) return std::nullopt;
  double next = t->x - (t->g > 0.0 ? 0.5 : 1.0) * t->g / slope;
  double expand = std::max(std::abs(next - t->x), probe);  // outward while one side is unknown
  // Interpolation that stalls (on a value next to the branch point, where g curves most) is
  // replaced by bisection: when the last defined value is not half the one two before it.
  int since_bisection = 0;
  while (evaluations < max_evaluations) {
    if (++since_bisection > 2 && defined == 3 && std::abs(last[0].g) > 0.5 * std::abs(last[2].g))
      next = inf;
    if (!(next > lo && next < hi)) {
      since_bisection = 0;
      if (std::isfinite(lo) && std::isfinite(hi))
        next = 0.5 * (lo + hi);
      else
        next = std::isfinite(hi) ? hi - expand : lo + expand;
      expand *= 2.0;
    }
    t = at(next);
    if (t && std::abs(t->g) <= tol) return found(*t);
    if (std::isfinite(lo) && std::isfinite(hi) &&
        hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * std::abs(hi))
      return best ? std::optional<BranchRoot>(found(*best)) : std::nullopt;
    // x as a quadratic in g through the last three defined values (Lagrange at g = 0), or as
    // a line through two.
    const Trial& a = last[0];
    const Trial& b = last[1];
    next = a.x - a.g * (a.x - b.x) / (a.g - b.g);
    if (defined == 3) {
      const Trial& c = last[2];
      if (a.g != c.g && b.g != c.g && a.g != b.g)
        next = a.x * b.g * c.g / ((a.g - b.g) * (a.g - c.g)) +
               b.x * a.g * c.g / ((b.g - a.g) * (b.g - c.g)) +
               c.x * a.g * b.g / ((c.g - a.g) * (c.g - b.g));
    }
    if (!std::isfinite(next)) next = inf;  // bisection
  }
  return std::nullopt;
}

}  // namespace puncture::detail
