#include "calibration/band_monte_carlo.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "cli_error.hpp"
#include "progress.hpp"
#include "puncture/loading_curve.hpp"
#include "puncture/sweep.hpp"
#include "puncture/sweep_statistics.hpp"

namespace puncture::cli {

namespace {

constexpr BandParameter kParameters[4] = {BandParameter::CriticalI1,
                                          BandParameter::Friction,
                                          BandParameter::JLim,
                                          BandParameter::ShearModulus};

nlohmann::json statistics_json(const OutputStatistics& s) {
  nlohmann::json j;
  j["found"] = s.found;
  if (!s.ok()) return j;
  j["mean"] = s.mean;
  j["sd"] = s.sd;
  j["min"] = s.min;
  j["max"] = s.max;
  for (const Percentile& p : s.percentiles)
    j["percentiles"].push_back({{"probability", p.probability}, {"value", p.value}});
  j["r_squared"] = s.r_squared;
  for (const InputSensitivity& in : s.sensitivities)
    j["sensitivity"].push_back(
        {{"parameter", in.name}, {"src", in.src}, {"slope", in.coefficient}});
  return j;
}

}  // namespace

std::string monte_carlo_band_text(const MonteCarloBandRequest& r, Format format) {
  SweepSpec spec;
  spec.design = SweepDesign::MonteCarlo;
  spec.samples = r.samples;
  spec.seed = r.seed;
  std::vector<BandParameter> swept;
  std::vector<std::string> names;
  const BandParameters nominal = band_parameters(r.problem);
  for (int i = 0; i < 4; ++i) {
    const BandParameter p = kParameters[i];
    const auto& range = r.ranges.of(p);
    if (!range) continue;
    Distribution d{DistributionKind::Uniform, range->lower, range->upper};
    if (r.sd[i] && *r.sd[i] > 0.0)
      d = {DistributionKind::TruncatedNormal,
           range->lower,
           range->upper,
           nominal.value(p),
           *r.sd[i]};
    else if (!(range->upper > range->lower))
      continue;  // a zero interval: the parameter stays at its value
    swept.push_back(p);
    names.push_back(to_token(p));
    spec.parameters.push_back({to_token(p), {}, d});
  }
  if (spec.parameters.empty())
    throw InputError("calibrate band: every interval has zero width: nothing to sample");
  const auto problem_of = [&](const SweepPoint& point) {
    Problem p = r.problem;
    for (std::size_t j = 0; j < swept.size(); ++j)
      p = with_band_parameter(p, swept[j], point.values[j]);
    return p;
  };
  SweepStatistics force(names, "puncture_force_n"), depth(names, "puncture_depth_mm");
  SweepOptions options;
  options.threads = r.threads;
  options.on_row = [&](const SweepRow& row) {
    const bool found = row.ok();
    force.add(row.point.values, found ? std::optional(row.puncture->force_n) : std::nullopt);
    depth.add(row.point.values, found ? std::optional(row.puncture->depth_mm) : std::nullopt);
  };
  Progress progress("calibrate band");
  options.progress = [&progress](const SweepProgress& p) {
    progress.update(static_cast<int>(p.done), static_cast<int>(p.to_do));
  };
  const PuncturePrediction at_nominal = predict_puncture(r.problem);
  if (!at_nominal.ok())
    throw SolveError("no puncture point at the nominal parameters: " + at_nominal.message,
                     at_nominal.status);
  SweepSummary summary;
  try {
    summary = sweep(spec, problem_of, options);
  } catch (const InvalidInput& e) {
    throw InputError(fmt::format("calibrate band: a sample is not a valid problem: {}", e.what()));
  }
  const std::vector<double> probabilities = {0.025, 0.05, 0.25, 0.5, 0.75, 0.95, 0.975};
  const OutputStatistics fs = force.result(probabilities), ds = depth.result(probabilities);
  const std::size_t failed = summary.delivered - summary.converged;
  if (format == Format::Json) {
    nlohmann::json j;
    j["method"] = "monte-carlo";
    j["samples"] = r.samples;
    j["seed"] = r.seed;
    j["failed"] = failed;
    j["nominal"] = {{"force_n", at_nominal.force_n}, {"depth_mm", at_nominal.depth_mm}};
    for (std::size_t k = 0; k < swept.size(); ++k) {
      const Distribution& d = spec.parameters[k].distribution;
      j["parameters"].push_back({{"parameter", names[k]},
                                 {"distribution", to_token(d.kind)},
                                 {"lower", d.lower},
                                 {"upper", d.upper},
                                 {"nominal", nominal.value(swept[k])}});
    }
    j["force_n"] = statistics_json(fs);
    j["depth_mm"] = statistics_json(ds);
    return j.dump(2) + "\n";
  }
  if (format == Format::Csv) {
    std::string text = "output,probability,value\n";
    for (const auto* s : {&fs, &ds})
      for (const Percentile& p : s->percentiles)
        text += fmt::format("{},{},{}\n", s->output, p.probability, p.value);
    return text;
  }
  std::string text = fmt::format(
      "Puncture band by Monte Carlo: {} samples (seed {}), {} failed\n"
      "  nominal prediction  force {:.6g} N, depth {:.6g} mm\n",
      r.samples,
      r.seed,
      failed,
      at_nominal.force_n,
      at_nominal.depth_mm);
  for (std::size_t k = 0; k < swept.size(); ++k) {
    const Distribution& d = spec.parameters[k].distribution;
    text += fmt::format("  {:<18}  {} on [{:.6g}, {:.6g}]{}\n",
                        to_string(swept[k]),
                        to_token(d.kind),
                        d.lower,
                        d.upper,
                        d.kind == DistributionKind::TruncatedNormal
                            ? fmt::format(" (mean {:.6g}, sd {:.6g})", d.mean, d.sd)
                            : std::string());
  }
  for (const auto* s : {&fs, &ds}) {
    text += '\n';  // apart: GCC 12 warns falsely (-Wrestrict) on "\n" + string
    text += s->report();
  }
  return text;
}

}  // namespace puncture::cli
