// The band of the predicted puncture over intervals of the calibrated parameters.
#include "puncture/puncture_band.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "puncture/loading_curve.hpp"

namespace puncture {

namespace {

constexpr BandParameter kAll[] = {BandParameter::CriticalI1,
                                  BandParameter::Friction,
                                  BandParameter::JLim,
                                  BandParameter::ShearModulus};

// Two predictions closer than this, relative, are the same: each puncture force and depth is
// converged to ~1e-8 relative (SolverOptions' defaults), so a difference below 1e-7 is noise.
constexpr double kSameRel = 1e-7;

void set(BandParameters& b, BandParameter p, double value) {
  switch (p) {
    case BandParameter::CriticalI1:
      b.critical_i1 = value;
      return;
    case BandParameter::Friction:
      b.friction = value;
      return;
    case BandParameter::JLim:
      b.j_lim = value;
      return;
    case BandParameter::ShearModulus:
      b.shear_modulus_mpa = value;
      return;
  }
}

Problem with(Problem q, const BandParameters& b) {
  q.critical_i1 = b.critical_i1;
  q.friction = b.friction;
  if (b.j_lim) q.material.law = Gent{*b.j_lim};
  q.material.shear_modulus_mpa = b.shear_modulus_mpa;
  return q;
}

}  // namespace

Problem with_band_parameter(Problem problem, BandParameter parameter, double value) {
  BandParameters b = band_parameters(problem);
  set(b, parameter, value);
  return with(problem, b);
}

namespace {

std::string describe(const BandParameters& b) {
  std::string out =
      fmt::format("critical I1 = {:.6g}, friction mu' = {:.6g}", b.critical_i1, b.friction);
  if (b.j_lim) out += fmt::format(", J_lim = {:.6g}", *b.j_lim);
  return out + fmt::format(", G = {:.6g} MPa", b.shear_modulus_mpa);
}

std::string joined(const std::vector<ValidationError>& errors) {
  std::string all;
  for (const auto& e : errors) all += (all.empty() ? "" : "; ") + e.message;
  return all;
}

BandEvaluation evaluate(const Problem& base, const BandParameters& b, const SolverOptions& solver) {
  BandEvaluation e;
  e.parameters = b;
  const auto p = predict_puncture(with(base, b), solver);
  e.status = p.status;
  e.message = p.message;
  if (p.ok()) {
    e.force_n = p.force_n;
    e.depth_mm = p.depth_mm;
    e.part_three_stretch = p.part_three_stretch;
    e.crack_location = p.crack_location;
  }
  return e;
}

// +1, -1, or 0 when |to - from| is within the solver's accuracy.
int direction(double from, double to) {
  const double scale = std::max(std::abs(from), std::abs(to));
  if (std::abs(to - from) <= kSameRel * scale) return 0;
  return to > from ? 1 : -1;
}

// The samples' values are monotone (up to the solver's accuracy), all found.
template <class Get>
bool monotone(const std::vector<BandEvaluation>& samples, Get get) {
  int seen = 0;
  for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
    if (!samples[i].ok() || !samples[i + 1].ok()) return false;
    const int d = direction(get(samples[i]), get(samples[i + 1]));
    if (d == 0) continue;
    if (seen != 0 && d != seen) return false;
    seen = d;
  }
  return samples.empty() || samples.back().ok();
}

std::vector<double> grid(const ParameterRange& r, double nominal, int n) {
  std::vector<double> out;
  for (int k = 0; k < n; ++k) out.push_back(r.lower + (r.upper - r.lower) * k / (n - 1));
  out.back() = r.upper;
  // The nominal value is a sample; a grid point within round-off of it becomes it.
  for (double& x : out)
    if (std::abs(x - nominal) <= 1e-12 * (r.upper - r.lower)) x = nominal;
  if (nominal > r.lower && nominal < r.upper) out.push_back(nominal);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

std::string to_token(BandParameter parameter) {
  switch (parameter) {
    case BandParameter::CriticalI1:
      return "critical_i1";
    case BandParameter::Friction:
      return "friction";
    case BandParameter::JLim:
      return "j_lim";
    case BandParameter::ShearModulus:
      break;
  }
  return "shear_modulus_mpa";
}

std::string to_string(BandParameter parameter) {
  switch (parameter) {
    case BandParameter::CriticalI1:
      return "critical I1";
    case BandParameter::Friction:
      return "friction mu'";
    case BandParameter::JLim:
      return "J_lim";
    case BandParameter::ShearModulus:
      break;
  }
  return "G";
}

int documented_force_direction(BandParameter parameter) {
  return parameter == BandParameter::JLim ? -1 : 1;
}

int documented_depth_direction(BandParameter parameter) {
  switch (parameter) {
    case BandParameter::CriticalI1:
    case BandParameter::Friction:
      return 1;
    case BandParameter::JLim:
      return -1;
    case BandParameter::ShearModulus:
      break;
  }
  return 0;
}

ParameterRange plus_minus(double mean, double sd, double k) {
  return {mean - k * sd, mean + k * sd};
}

const std::optional<ParameterRange>& BandRanges::of(BandParameter parameter) const {
  switch (parameter) {
    case BandParameter::CriticalI1:
      return critical_i1;
    case BandParameter::Friction:
      return friction;
    case BandParameter::JLim:
      return j_lim;
    case BandParameter::ShearModulus:
      break;
  }
  return shear_modulus_mpa;
}

std::optional<ParameterRange>& BandRanges::of(BandParameter parameter) {
  return const_cast<std::optional<ParameterRange>&>(std::as_const(*this).of(parameter));
}

BandParameters band_parameters(const Problem& p) {
  BandParameters out;
  out.critical_i1 = p.critical_i1;
  out.friction = p.friction;
  if (const auto* gent = std::get_if<Gent>(&p.material.law)) out.j_lim = gent->j_lim;
  out.shear_modulus_mpa = p.material.shear_modulus_mpa;
  return out;
}

double BandParameters::value(BandParameter parameter) const {
  switch (parameter) {
    case BandParameter::CriticalI1:
      return critical_i1;
    case BandParameter::Friction:
      return friction;
    case BandParameter::JLim:
      return j_lim.value_or(0.0);
    case BandParameter::ShearModulus:
      break;
  }
  return shear_modulus_mpa;
}

PunctureBand puncture_band(const Problem& problem, const BandRanges& ranges,
                           const BandOptions& options) {
  validate(problem);
  if (options.samples_per_range < 2)
    throw std::invalid_argument(
        fmt::format("band: samples per range must be at least 2 (the ends), got {}",
                    options.samples_per_range));
  if (ranges.j_lim && !std::holds_alternative<Gent>(problem.material.law))
    throw std::invalid_argument(
        fmt::format("J_lim range: J_lim is a parameter of the Gent law; the material is {}",
                    law_name(problem.material.law)));

  const BandParameters nominal = band_parameters(problem);
  std::vector<BandParameter> varied;
  for (const auto p : kAll) {
    const auto& r = ranges.of(p);
    if (!r) continue;
    const double x = nominal.value(p);
    if (!std::isfinite(r->lower) || !std::isfinite(r->upper) || r->lower > r->upper)
      throw std::invalid_argument(
          fmt::format("{} range: needs finite ends with lower <= upper, got [{}, {}]",
                      to_string(p),
                      r->lower,
                      r->upper));
    if (x < r->lower || x > r->upper)
      throw std::invalid_argument(
          fmt::format("{} range: [{:.6g}, {:.6g}] does not contain the problem's value {:.6g}",
                      to_string(p),
                      r->lower,
                      r->upper,
                      x));
    for (const auto& [end, value] : {std::pair{"lower", r->lower}, std::pair{"upper", r->upper}}) {
      BandParameters b = nominal;
      set(b, p, value);
      if (const auto errors = validation_errors(with(problem, b)); !errors.empty())
        throw std::invalid_argument(
            fmt::format("{} range: the {} end {:.6g} is not a valid problem: {}",
                        to_string(p),
                        end,
                        value,
                        joined(errors)));
    }
    varied.push_back(p);
  }

  // Every corner: bit i of the index chooses the upper end of varied[i].
  std::vector<BandParameters> corner_parameters;
  for (std::size_t mask = 0; mask < (std::size_t{1} << varied.size()); ++mask) {
    BandParameters b = nominal;
    for (std::size_t i = 0; i < varied.size(); ++i) {
      const auto& r = *ranges.of(varied[i]);
      set(b, varied[i], (mask >> i) & 1U ? r.upper : r.lower);
    }
    if (const auto errors = validation_errors(with(problem, b)); !errors.empty())
      throw std::invalid_argument(fmt::format(
          "the corner {} of the ranges is not a valid problem: {}", describe(b), joined(errors)));
    corner_parameters.push_back(b);
  }

  SolverOptions solver = options.solver;
  solver.record_fields = false;
  PunctureBand out;
  out.nominal = evaluate(problem, nominal, solver);
  if (!out.nominal.ok())
    out.warnings.push_back("no puncture point at the nominal parameters: " + out.nominal.message);
  int failed = out.nominal.ok() ? 0 : 1;

  for (const auto p : varied) {
    const auto& r = *ranges.of(p);
    ParameterSensitivity s;
    s.parameter = p;
    s.nominal = nominal.value(p);
    s.range = r;
    for (const double x : grid(r, s.nominal, options.samples_per_range)) {
      if (x == s.nominal) {  // already evaluated, and reported when it failed
        s.samples.push_back(out.nominal);
        continue;
      }
      BandParameters b = nominal;
      set(b, p, x);
      s.samples.push_back(evaluate(problem, b, solver));
      if (!s.samples.back().ok()) {
        ++failed;
        out.warnings.push_back(fmt::format("{} = {:.6g} (others nominal): no puncture point: {}",
                                           to_string(p),
                                           x,
                                           s.samples.back().message));
      }
    }
    s.at_lower = s.samples.front();
    s.at_upper = s.samples.back();
    if (s.at_lower.ok() && s.at_upper.ok()) {
      s.force_change_n = s.at_upper.force_n - s.at_lower.force_n;
      s.depth_change_mm = s.at_upper.depth_mm - s.at_lower.depth_mm;
      s.force_direction = direction(s.at_lower.force_n, s.at_upper.force_n);
      s.depth_direction = direction(s.at_lower.depth_mm, s.at_upper.depth_mm);
    }
    s.force_monotone = monotone(s.samples, [](const BandEvaluation& e) { return e.force_n; });
    s.depth_monotone = monotone(s.samples, [](const BandEvaluation& e) { return e.depth_mm; });
    if (s.at_lower.ok() && s.at_upper.ok()) {
      if (!s.force_monotone || !s.depth_monotone)
        out.warnings.push_back(fmt::format(
            "the puncture {} is not monotone in {} over [{:.6g}, {:.6g}]: the corners may not "
            "bound the band",
            !s.force_monotone ? "force" : "depth",
            to_string(p),
            r.lower,
            r.upper));
      if (*s.force_direction != 0 && *s.force_direction != documented_force_direction(p))
        out.warnings.push_back(
            fmt::format("the puncture force {} with {}, against the documented "
                        "direction",
                        *s.force_direction > 0 ? "rises" : "falls",
                        to_string(p)));
    }
    out.sensitivities.push_back(std::move(s));
  }

  // The first-order variance shares and the dominant parameter.
  double sum_sq = 0.0;
  bool all_changes = true;
  for (const auto& s : out.sensitivities) {
    if (!s.force_change_n) {
      all_changes = false;
      continue;
    }
    sum_sq += *s.force_change_n * *s.force_change_n;
  }
  {
    double largest = -1.0;
    for (const auto& s : out.sensitivities)
      if (s.force_change_n && std::abs(*s.force_change_n) > largest) {
        largest = std::abs(*s.force_change_n);
        out.dominant = s.parameter;
      }
    if (largest <= 0.0) out.dominant.reset();
  }
  if (all_changes && !out.sensitivities.empty()) {
    out.force_half_range_rss_n = 0.5 * std::sqrt(sum_sq);
    if (sum_sq > 0.0)
      for (auto& s : out.sensitivities)
        s.force_variance_share = *s.force_change_n * *s.force_change_n / sum_sq;
  }

  // The corners, and the band over them and the nominal point.
  for (const auto& b : corner_parameters) {
    out.corners.push_back(evaluate(problem, b, solver));
    if (!out.corners.back().ok()) {
      ++failed;
      out.warnings.push_back(
          fmt::format("corner {}: no puncture point: {}", describe(b), out.corners.back().message));
    }
  }
  const auto include = [](std::optional<double>& lo, std::optional<double>& hi, double x) {
    if (!lo || x < *lo) lo = x;
    if (!hi || x > *hi) hi = x;
  };
  if (out.nominal.ok()) {
    include(out.force_min_n, out.force_max_n, out.nominal.force_n);
    include(out.depth_min_mm, out.depth_max_mm, out.nominal.depth_mm);
  }
  for (std::size_t i = 0; i < out.corners.size(); ++i) {
    const auto& c = out.corners[i];
    if (!c.ok()) continue;
    if (!out.force_min_corner || c.force_n < out.corners[*out.force_min_corner].force_n)
      out.force_min_corner = i;
    if (!out.force_max_corner || c.force_n > out.corners[*out.force_max_corner].force_n)
      out.force_max_corner = i;
    if (!out.depth_min_corner || c.depth_mm < out.corners[*out.depth_min_corner].depth_mm)
      out.depth_min_corner = i;
    if (!out.depth_max_corner || c.depth_mm > out.corners[*out.depth_max_corner].depth_mm)
      out.depth_max_corner = i;
    include(out.force_min_n, out.force_max_n, c.force_n);
    include(out.depth_min_mm, out.depth_max_mm, c.depth_mm);
  }
  const bool complete = failed == 0;
  out.status = complete ? Status::Converged : Status::Incomplete;
  if (!complete)
    out.message = fmt::format("{} evaluation{} found no puncture point (see the warnings)",
                              failed,
                              failed == 1 ? "" : "s");

  // The corners the documented directions give for the least and the largest force.
  bool consistent = complete;
  for (const auto& s : out.sensitivities)
    consistent =
        consistent && s.force_monotone && s.force_direction &&
        (*s.force_direction == 0 || *s.force_direction == documented_force_direction(s.parameter));
  if (consistent && !varied.empty()) {
    std::size_t low = 0, high = 0;
    for (std::size_t i = 0; i < varied.size(); ++i) {
      if (documented_force_direction(varied[i]) > 0)
        high |= std::size_t{1} << i;
      else
        low |= std::size_t{1} << i;
    }
    // Ties (a zero-width interval, or a parameter without effect) may pick another corner with
    // the same force: compare forces, not indices.
    const auto same = [&](std::size_t a, std::size_t b) {
      return direction(out.corners[a].force_n, out.corners[b].force_n) == 0;
    };
    consistent = same(low, *out.force_min_corner) && same(high, *out.force_max_corner);
    if (!consistent)
      out.warnings.push_back(
          "the extreme force corners are not those the documented directions give: the force "
          "is not monotone in each parameter over the whole box");
  }
  out.consistent_with_documented_directions = consistent;
  return out;
}

}  // namespace puncture
