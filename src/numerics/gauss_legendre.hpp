#pragma once
// Composite Gauss-Legendre quadrature on an interval as a list of nodes and weights, for an
// integrand evaluated in one sweep (the loading curve's depths) rather than one call at a time.
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <cstddef>
#include <vector>

namespace puncture::detail {

struct QuadratureNodes {
  std::vector<double> nodes;  // increasing
  std::vector<double> weights;
};

// Appends `panels` equal panels of the 10-point Gauss-Legendre rule on [lo, hi] (exact for
// polynomials of degree 19 on each panel), nodes in increasing order; none when hi <= lo.
inline void append_gauss_legendre(double lo, double hi, int panels, QuadratureNodes& q) {
  if (!(hi > lo) || panels < 1) return;
  using Rule = boost::math::quadrature::gauss<double, 10>;
  const auto& x = Rule::abscissa();  // the non-negative half, increasing
  const auto& w = Rule::weights();
  const double half = 0.5 * (hi - lo) / panels;
  auto add = [&](double node, double weight) {
    q.nodes.push_back(node);
    q.weights.push_back(weight);
  };
  for (int k = 0; k < panels; ++k) {
    const double mid = lo + (2 * k + 1) * half;
    for (std::size_t i = x.size(); i-- > 0;)
      if (x[i] > 0.0) add(mid - half * x[i], half * w[i]);
    for (std::size_t i = 0; i < x.size(); ++i) add(mid + half * x[i], half * w[i]);
  }
}

// As append_gauss_legendre, with the panel at `lo` split geometrically into `graded` panels,
// [lo, lo + h 2^-graded], ..., [lo + h / 2, lo + h] (h the panel width): an integrand that is not
// smooth at lo (a pre-tensioned membrane's force goes as depth / log(depth)) then costs at most
// the last one's share, ~ (2^-graded)^2 of the whole.
inline void append_graded_gauss_legendre(double lo, double hi, int panels, int graded,
                                         QuadratureNodes& q) {
  if (!(hi > lo) || panels < 1) return;
  const double h = (hi - lo) / panels;
  append_gauss_legendre(lo, lo + std::ldexp(h, -graded), 1, q);
  for (int j = graded; j > 0; --j)
    append_gauss_legendre(lo + std::ldexp(h, -j), lo + std::ldexp(h, 1 - j), 1, q);
  append_gauss_legendre(lo + h, hi, panels - 1, q);
}

}  // namespace puncture::detail
