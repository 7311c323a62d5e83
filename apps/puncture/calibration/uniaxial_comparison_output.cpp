// Writers of `puncture fit uniaxial --compare`: the laws ranked by AIC (summary and CSV: one row
// per law), and every fit in full (JSON, which the --plot figure reads).
#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "calibration/common_output.hpp"
#include "finite.hpp"
#include "json_helpers.hpp"
#include "tables.hpp"

namespace puncture::cli::calibration {

namespace {

// The lowest AIC of the ranking, the reference of delta AIC.
std::optional<double> best_aic(const UniaxialComparisonReport& r) {
  for (const auto& f : r.fits)
    if (f.information && f.status != Status::NoConvergence) return f.information->aic;
  return std::nullopt;
}

Table ranking_rows(const UniaxialComparisonReport& r) {
  Table t{{"rank",
           "law",
           "status",
           "n",
           "k",
           "rss_mpa2",
           "aic",
           "delta_aic",
           "aicc",
           "bic",
           "rms_residual_mpa"},
          {}};
  const auto best = best_aic(r);
  const auto none = std::optional<double>();
  for (std::size_t i = 0; i < r.fits.size(); ++i) {
    const auto& f = r.fits[i];
    const auto& c = f.information;
    const bool ranked = c && f.status != Status::NoConvergence;
    t.rows.push_back({static_cast<int>(i + 1),
                      to_string(f.law),
                      to_string(f.status),
                      f.points,
                      c ? Cell(c->parameters) : Cell(none),
                      c ? c->rss_mpa2 : none,
                      ranked ? c->aic : none,
                      ranked && best ? c->aic - *best : none,
                      ranked ? c->aicc : none,
                      ranked ? c->bic : none,
                      f.status != Status::NoConvergence ? f.rms_residual_mpa : none});
  }
  return t;
}

}  // namespace

std::string summary(const UniaxialComparisonReport& r) {
  std::string out = "Inputs\n";
  line(out, "data", fmt::format("{}: {} points", r.source, r.data.size()));
  line(out, "test", fmt::format("{} (nominal stress)", to_string(r.test)));
  out +=
      "Laws ranked by AIC = n ln(RSS/n) + 2k (k: the law's parameters + the variance; lowest\n"
      "first; a difference above ~10 is decisive, below 2 is none; AICc for small n, BIC =\n"
      "n ln(RSS/n) + k ln n)\n";
  text_table(out, ranking_rows(r), all_rows(ranking_rows(r)));
  for (const auto& f : r.fits) {
    out += fmt::format("{} ({}{})\n",
                       to_string(f.law),
                       to_string(f.status),
                       f.message.empty() ? "" : ": " + f.message);
    if (f.status == Status::NoConvergence) continue;
    for (const auto& p : f.parameters) {
      line(out, p.name, parameter_text(p));
      if (!p.note.empty()) line(out, "", p.note);
    }
    statistics_lines(out, f);
    if (f.material) line(out, "for the model", model_flags(f));
  }
  return out;
}

std::string csv_text(const UniaxialComparisonReport& r) { return csv(ranking_rows(r)); }

std::string json_text(const UniaxialComparisonReport& r) {
  json fits = json::array();
  for (const auto& f : r.fits) {
    json one = fit_json(f);
    one["status"] = to_string(f.status);
    one["message"] = f.message;
    json fitted = json::array();
    for (const double p : f.fitted_stress_mpa) fitted.push_back(finite(p, "fitted stress"));
    one["fitted_stress_mpa"] = fitted;
    fits.push_back(one);
  }
  json points = json::array();
  for (const auto& p : r.data)
    points.push_back({{"stretch", finite(p.stretch, "stretch")},
                      {"nominal_stress_mpa", finite(p.nominal_stress_mpa, "stress")}});
  return dump({{"inputs",
                {{"source", r.source},
                 {"points", r.data.size()},
                 {"test", to_string(r.test)},
                 {"specimen", specimen_json(r.specimen)}}},
               {"ranking", rows_json(ranking_rows(r))},
               {"fits", fits},
               {"points", points}});
}

}  // namespace puncture::cli::calibration
