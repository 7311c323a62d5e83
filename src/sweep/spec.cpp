// The sweep's spec: its checks, its size and the parameters' distributions.
#include <fmt/format.h>

#include <boost/math/distributions/lognormal.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <limits>

#include "puncture/sweep.hpp"

namespace puncture {

std::string to_token(SweepDesign design) {
  switch (design) {
    case SweepDesign::Grid:
      return "grid";
    case SweepDesign::LatinHypercube:
      return "latin-hypercube";
    case SweepDesign::Sobol:
      return "sobol";
    case SweepDesign::MonteCarlo:
      return "monte-carlo";
  }
  return "?";
}

std::string to_token(DistributionKind kind) {
  switch (kind) {
    case DistributionKind::Uniform:
      return "uniform";
    case DistributionKind::Normal:
      return "normal";
    case DistributionKind::LogNormal:
      return "lognormal";
    case DistributionKind::TruncatedNormal:
      return "truncated-normal";
  }
  return "?";
}

double Distribution::quantile(double u) const {
  namespace bm = boost::math;
  switch (kind) {
    case DistributionKind::Uniform:
      return lower + u * (upper - lower);
    case DistributionKind::Normal:
      return bm::quantile(bm::normal(mean, sd), u);
    case DistributionKind::LogNormal: {
      // The log's mean and sd from the value's: sd_log^2 = ln(1 + (sd/mean)^2).
      const double sd_log = std::sqrt(std::log1p((sd / mean) * (sd / mean)));
      return bm::quantile(bm::lognormal(std::log(mean) - 0.5 * sd_log * sd_log, sd_log), u);
    }
    case DistributionKind::TruncatedNormal: {
      const bm::normal n(mean, sd);
      const double p_lower = bm::cdf(n, lower), p_upper = bm::cdf(n, upper);
      const double x = bm::quantile(n, p_lower + u * (p_upper - p_lower));
      return std::min(std::max(x, lower), upper);  // rounding at the ends
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

std::vector<std::string> evenly_spaced_levels(double lower, double upper, int count) {
  if (!std::isfinite(lower) || !std::isfinite(upper) || count < 2 || lower > upper)
    throw InvalidInput("levels",
                       fmt::format("levels: need finite lower <= upper and a count >= 2, got "
                                   "[{}, {}] with {}",
                                   lower,
                                   upper,
                                   count));
  std::vector<std::string> levels;
  for (int k = 0; k < count; ++k) {
    // The ends exactly, the rest by the one formula, so a level never depends on the others.
    const double t = static_cast<double>(k) / (count - 1);
    const double x = k == count - 1 ? upper : lower + t * (upper - lower);
    levels.push_back(fmt::format("{}", x));
  }
  return levels;
}

namespace {

void check_distribution(const std::string& name, const Distribution& d,
                        std::vector<ValidationError>& errors) {
  const auto bad = [&](const std::string& what) {
    errors.push_back({name, fmt::format("{}: {} distribution: {}", name, to_token(d.kind), what)});
  };
  const bool finite_range = std::isfinite(d.lower) && std::isfinite(d.upper);
  const bool finite_moments = std::isfinite(d.mean) && std::isfinite(d.sd);
  switch (d.kind) {
    case DistributionKind::Uniform:
      if (!finite_range || d.lower > d.upper)
        bad(fmt::format("the range needs finite lower <= upper, got [{}, {}]", d.lower, d.upper));
      break;
    case DistributionKind::Normal:
      if (!finite_moments || d.sd <= 0.0)
        bad(fmt::format("needs a finite mean and sd > 0, got mean {} sd {}", d.mean, d.sd));
      break;
    case DistributionKind::LogNormal:
      if (!finite_moments || d.mean <= 0.0 || d.sd <= 0.0)
        bad(fmt::format(
            "needs mean > 0 and sd > 0 (of the value), got mean {} sd {}", d.mean, d.sd));
      break;
    case DistributionKind::TruncatedNormal:
      if (!finite_moments || d.sd <= 0.0)
        bad(fmt::format("needs a finite mean and sd > 0, got mean {} sd {}", d.mean, d.sd));
      else if (!finite_range || d.lower >= d.upper)
        bad(fmt::format("the range needs finite lower < upper, got [{}, {}]", d.lower, d.upper));
      else {
        const boost::math::normal n(d.mean, d.sd);
        // The quantile of a range deep in one tail loses every digit: refuse it.
        if (boost::math::cdf(n, d.upper) - boost::math::cdf(n, d.lower) < 1e-6)
          bad(fmt::format("the range [{}, {}] holds less than 1e-6 of normal({}, {})",
                          d.lower,
                          d.upper,
                          d.mean,
                          d.sd));
      }
      break;
  }
}

}  // namespace

std::vector<ValidationError> validation_errors(const SweepSpec& spec) {
  std::vector<ValidationError> errors;
  if (spec.parameters.empty())
    errors.push_back({"parameters", "parameters: a sweep needs at least one parameter"});
  for (std::size_t j = 0; j < spec.parameters.size(); ++j) {
    const SweepParameter& p = spec.parameters[j];
    if (p.name.empty()) errors.push_back({"parameters", "parameters: a parameter has no name"});
    for (std::size_t k = 0; k < j; ++k)
      if (spec.parameters[k].name == p.name)
        errors.push_back({p.name, fmt::format("{}: swept twice", p.name)});
    if (spec.design == SweepDesign::Grid) {
      if (p.levels.empty())
        errors.push_back({p.name, fmt::format("{}: a grid needs its levels", p.name)});
      for (const std::string& level : p.levels)
        if (level.empty()) errors.push_back({p.name, fmt::format("{}: a level is empty", p.name)});
    } else {
      if (!p.levels.empty())
        errors.push_back({p.name,
                          fmt::format("{}: levels belong to a grid; a {} design samples a "
                                      "distribution",
                                      p.name,
                                      to_token(spec.design))});
      check_distribution(p.name, p.distribution, errors);
    }
  }
  if (spec.design == SweepDesign::Grid) {
    if (spec.samples != 0)
      errors.push_back({"samples", "samples: a grid has the product of its levels as points"});
    double count = 1.0;
    for (const SweepParameter& p : spec.parameters) count *= static_cast<double>(p.levels.size());
    if (count > 1e12)
      errors.push_back(
          {"parameters", fmt::format("parameters: the grid has {:.3g} points (> 1e12)", count)});
  } else {
    if (spec.samples == 0)
      errors.push_back({"samples",
                        fmt::format("samples: a {} design needs a number of points >= 1",
                                    to_token(spec.design))});
    // Boost's Sobol generator has 32-bit coordinates: 2^32 - 1 points after the zero.
    if (spec.design == SweepDesign::Sobol && spec.samples >= (std::size_t{1} << 32))
      errors.push_back({"samples", "samples: a Sobol design has at most 2^32 - 1 points"});
    if (spec.design == SweepDesign::Sobol && spec.parameters.size() > 3667)
      errors.push_back({"parameters", "parameters: a Sobol design has at most 3667 parameters"});
  }
  for (double d : spec.outputs.force_at_depth_mm)
    if (!std::isfinite(d) || d < 0.0)
      errors.push_back(
          {"force_at_depth_mm",
           fmt::format("force_at_depth_mm: depths must be finite and >= 0 mm, got {}", d)});
  if (!spec.outputs.puncture && spec.outputs.force_at_depth_mm.empty())
    errors.push_back({"outputs", "outputs: nothing to compute (no puncture, no depth)"});
  return errors;
}

std::size_t point_count(const SweepSpec& spec) {
  if (spec.design != SweepDesign::Grid) return spec.samples;
  std::size_t count = spec.parameters.empty() ? 0 : 1;
  for (const SweepParameter& p : spec.parameters) count *= p.levels.size();
  return count;
}

}  // namespace puncture
