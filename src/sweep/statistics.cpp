// Statistics of one output over a sweep: moments, percentiles, histogram, and the standardised
// regression coefficients of a least-squares linear fit on the inputs.
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "puncture/sweep_statistics.hpp"

namespace puncture {

SweepStatistics::SweepStatistics(std::vector<std::string> input_names, std::string output_name)
    : names_(std::move(input_names)), output_(std::move(output_name)) {
  const std::size_t d = names_.size();
  shift_.assign(d, 0.0);
  sum_x_.assign(d, 0.0);
  sum_xx_.assign(d * d, 0.0);
  sum_xy_.assign(d, 0.0);
  numeric_.assign(d, true);
}

void SweepStatistics::add(const std::vector<double>& x, std::optional<double> y) {
  const std::size_t d = names_.size();
  if (x.size() != d)
    throw InvalidInput("inputs", fmt::format("inputs: {} values for {} inputs", x.size(), d));
  if (y && !std::isfinite(*y))
    throw InvalidInput("output", fmt::format("output: {} is not a finite number", *y));
  ++points_;
  if (!y) return;
  if (values_.empty()) {
    for (std::size_t j = 0; j < d; ++j) shift_[j] = std::isfinite(x[j]) ? x[j] : 0.0;
    shift_y_ = *y;
  }
  values_.push_back(*y);
  const double dy = *y - shift_y_;
  sum_y_ += dy;
  sum_yy_ += dy * dy;
  for (std::size_t j = 0; j < d; ++j) {
    if (!std::isfinite(x[j])) numeric_[j] = false;
    const double dj = x[j] - shift_[j];
    sum_x_[j] += dj;
    sum_xy_[j] += dj * dy;
    for (std::size_t k = 0; k < d; ++k) sum_xx_[j * d + k] += dj * (x[k] - shift_[k]);
  }
}

namespace {

// Linear interpolation between the order statistics: position p (n - 1).
double percentile_of_sorted(const std::vector<double>& sorted, double p) {
  const double position = p * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double t = position - static_cast<double>(below);
  return sorted[below] + t * (sorted[above] - sorted[below]);
}

Histogram histogram_of_sorted(const std::vector<double>& sorted, int bins) {
  Histogram h;
  const double lo = sorted.front(), hi = sorted.back();
  for (int k = 0; k <= bins; ++k)
    h.edges.push_back(k == bins ? hi : lo + (hi - lo) * static_cast<double>(k) / bins);
  h.counts.assign(static_cast<std::size_t>(bins), 0);
  for (const double v : sorted) {
    auto k = hi > lo ? static_cast<std::size_t>((v - lo) / (hi - lo) * bins) : 0;
    ++h.counts[std::min(k, h.counts.size() - 1)];
  }
  return h;
}

}  // namespace

OutputStatistics SweepStatistics::result(const std::vector<double>& probabilities, int bins) const {
  for (const double p : probabilities)
    if (!(p >= 0.0 && p <= 1.0))
      throw InvalidInput("probabilities", fmt::format("probabilities: {} is not in [0, 1]", p));
  if (bins < 1) throw InvalidInput("bins", fmt::format("bins: {} is not >= 1", bins));
  OutputStatistics s;
  s.output = output_;
  s.points = points_;
  s.found = values_.size();
  if (s.found < 2) {
    s.status = Status::Incomplete;
    s.message =
        fmt::format("{}: found at {} of {} points; statistics need 2", output_, s.found, s.points);
    return s;
  }
  s.status = Status::Converged;
  std::vector<double> sorted = values_;
  std::sort(sorted.begin(), sorted.end());
  const double n = static_cast<double>(s.found);
  s.min = sorted.front();
  s.max = sorted.back();
  const double mean_dy = sum_y_ / n;
  const double syy = sum_yy_ - n * mean_dy * mean_dy;  // sum (y - mean)^2
  s.mean = shift_y_ + mean_dy;
  s.sd = std::sqrt(std::max(0.0, syy) / (n - 1.0));
  for (const double p : probabilities)
    s.percentiles.push_back({p, percentile_of_sorted(sorted, p)});
  s.histogram = histogram_of_sorted(sorted, bins);

  // The fit on the inputs that are numbers and vary: centred normal equations.
  const std::size_t d = names_.size();
  std::vector<std::size_t> used;
  std::vector<double> sxx_diag(d);
  for (std::size_t j = 0; j < d; ++j) {
    sxx_diag[j] = sum_xx_[j * d + j] - sum_x_[j] * sum_x_[j] / n;
    if (numeric_[j] && sxx_diag[j] > 1e-300) used.push_back(j);
  }
  if (used.empty() || s.found <= used.size() + 1 || !(syy > 0.0)) return s;
  const auto m = static_cast<Eigen::Index>(used.size());
  Eigen::MatrixXd a(m, m);
  Eigen::VectorXd b(m);
  for (Eigen::Index r = 0; r < m; ++r) {
    const std::size_t j = used[static_cast<std::size_t>(r)];
    b(r) = sum_xy_[j] - sum_x_[j] * sum_y_ / n;
    for (Eigen::Index c = 0; c < m; ++c) {
      const std::size_t k = used[static_cast<std::size_t>(c)];
      a(r, c) = sum_xx_[j * d + k] - sum_x_[j] * sum_x_[k] / n;
    }
  }
  // Scaled to unit diagonal: the inputs' units differ by orders of magnitude.
  const Eigen::VectorXd scale = a.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd corr = scale.asDiagonal() * a * scale.asDiagonal();
  const Eigen::VectorXd coefficients =
      scale.asDiagonal() * corr.completeOrthogonalDecomposition().solve(scale.asDiagonal() * b);
  s.r_squared = std::min(1.0, coefficients.dot(b) / syy);
  for (Eigen::Index r = 0; r < m; ++r) {
    const std::size_t j = used[static_cast<std::size_t>(r)];
    s.sensitivities.push_back(
        {names_[j], coefficients(r), coefficients(r) * std::sqrt(sxx_diag[j] / syy)});
  }
  std::stable_sort(s.sensitivities.begin(),
                   s.sensitivities.end(),
                   [](const auto& x, const auto& y) { return std::abs(x.src) > std::abs(y.src); });
  return s;
}

std::string OutputStatistics::report() const {
  std::string text = fmt::format("{}: found at {} of {} points", output, found, points);
  if (!ok()) return text + fmt::format(" ({})\n", message);
  text += fmt::format("\n  mean {:.6g}, sd {:.6g}, min {:.6g}, max {:.6g}\n", mean, sd, min, max);
  for (const Percentile& p : percentiles)
    text += fmt::format("  {:>5.4g} % percentile  {:.6g}\n", 100.0 * p.probability, p.value);
  if (!sensitivities.empty()) {
    text += fmt::format(
        "  sensitivity (linear fit, R^2 = {:.4f}; SRC^2 ~ share of the variance):\n", r_squared);
    for (const InputSensitivity& in : sensitivities)
      text += fmt::format("    {:<24} SRC {:+.4f}  SRC^2 {:.4f}  slope {:.6g}\n",
                          in.name,
                          in.src,
                          in.src * in.src,
                          in.coefficient);
  }
  text += "  histogram:\n";
  const std::size_t most = *std::max_element(histogram.counts.begin(), histogram.counts.end());
  for (std::size_t k = 0; k < histogram.counts.size(); ++k)
    text += fmt::format("    [{:>10.5g}, {:>10.5g}{} {:>8} {}\n",
                        histogram.edges[k],
                        histogram.edges[k + 1],
                        k + 1 == histogram.counts.size() ? "]" : ")",
                        histogram.counts[k],
                        std::string(most > 0 ? 40 * histogram.counts[k] / most : 0, '#'));
  return text;
}

}  // namespace puncture
