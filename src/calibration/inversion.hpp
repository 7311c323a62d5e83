#pragma once
// Inverting a scalar model y(x) for a target: sample it on a grid first (so that several
// solutions, gaps where the solver fails and targets out of reach are all seen), then refine
// every sign change of y - target between neighbouring samples with Boost's TOMS 748.
#include <fmt/format.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "puncture/calibration.hpp"

namespace puncture::detail {

// The model at x, or empty when the solver fails there.
using Model = std::function<std::optional<double>(double)>;

inline std::vector<ScanSample> scan(const Model& model, const std::vector<double>& grid) {
  std::vector<ScanSample> samples;
  samples.reserve(grid.size());
  for (const double x : grid) samples.push_back({x, model(x)});
  return samples;
}

struct ModelFailed : std::runtime_error {
  explicit ModelFailed(double x)
      : std::runtime_error(fmt::format("the model failed at {:.10g}", x)), at(x) {}
  double at;
};

// Every x with y(x) = target between neighbouring valid samples (and at samples that hit it
// exactly), in increasing x.  `x_tol` is the absolute width at which a bracket is converged.
// A solution inside a stretch of failed samples is not seen: see failed_samples().
inline Inversion invert(const Model& model, const std::vector<ScanSample>& samples, double target,
                        double x_tol) {
  Inversion out;
  const auto residual = [&](double x) {
    ++out.evaluations;
    const auto y = model(x);
    if (!y) throw ModelFailed(x);
    return *y - target;
  };
  std::vector<std::string> failures;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto& s = samples[i];
    if (!s.model) continue;
    const double r = *s.model - target;
    if (r == 0.0) {
      out.solutions.push_back(s.parameter);
      continue;
    }
    if (i + 1 >= samples.size()) break;
    const auto& next = samples[i + 1];
    if (!next.model) continue;
    const double r_next = *next.model - target;
    if (r_next == 0.0 || (r > 0.0) == (r_next > 0.0)) continue;
    try {
      std::uintmax_t max_iter = 100;
      const auto tol = [x_tol](double a, double b) { return std::abs(b - a) <= x_tol; };
      const auto [a, b] = boost::math::tools::toms748_solve(
          residual, s.parameter, next.parameter, r, r_next, tol, max_iter);
      out.solutions.push_back(0.5 * (a + b));
    } catch (const ModelFailed& e) {
      failures.push_back(
          fmt::format("between {:.6g} and {:.6g} ({})", s.parameter, next.parameter, e.what()));
    }
  }
  if (!out.solutions.empty()) {
    out.status = Status::Converged;
    out.value = out.solutions.front();
  } else {
    // No root in the range and no failure: the target is outside what the model reaches.
    out.status = failures.empty() ? Status::NotReached : Status::NoConvergence;
  }
  if (!failures.empty()) {
    std::string all;
    for (const auto& f : failures) all += (all.empty() ? "" : "; ") + f;
    out.message = "a solution could not be refined " + all;
    if (out.ok()) out.message = "warning: " + out.message;
  }
  return out;
}

// "at 0.1, 0.2" for the samples where the model failed; empty when none did.
inline std::string failed_samples(const std::vector<ScanSample>& samples) {
  std::string out;
  for (const auto& s : samples)
    if (!s.model) out += fmt::format("{}{:.6g}", out.empty() ? "at " : ", ", s.parameter);
  return out;
}

}  // namespace puncture::detail
