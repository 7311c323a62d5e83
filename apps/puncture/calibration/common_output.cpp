// The helpers shared by the calibration writers, and calibration_text: the report in the chosen
// format.
#include "calibration/common_output.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "finite.hpp"
#include "stick_spec.hpp"

namespace puncture::cli {

namespace calibration {

// ----- shared helpers -------------------------------------------------------------------------

std::string num_or(const std::optional<double>& x, std::string_view what,
                   std::string_view missing) {
  return x ? num(*x, what) : std::string(missing);
}

void line(std::string& out, std::string_view label, std::string_view value) {
  out += fmt::format("  {:<28}{}\n", label, value);
}

// About `shown` evenly spaced rows, always the first and the last.
std::vector<std::size_t> sampled_rows(std::size_t n, std::size_t shown) {
  if (n <= shown + 4) {
    std::vector<std::size_t> rows(n);
    for (std::size_t i = 0; i < n; ++i) rows[i] = i;
    return rows;
  }
  std::vector<std::size_t> rows;
  for (std::size_t k = 0; k < shown; ++k) rows.push_back(k * (n - 1) / (shown - 1));
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  return rows;
}

namespace {

std::string material_without(const Material& m, bool j_lim_calibrated) {
  if (j_lim_calibrated)
    return fmt::format("gent (J_lim: calibrated here), G = {:g} MPa", m.shear_modulus_mpa);
  return describe(m);
}

}  // namespace

// The physical inputs; `calibrated` ("friction" or "jlim") is left out.
void problem_lines(std::string& out, const Problem& p, std::string_view calibrated) {
  const auto& g = p.geometry;
  line(out, "clamp radius A", num(g.clamp_radius_mm, "clamp radius") + " mm");
  line(out, "indenter radius a", num(radius_mm(p.indenter), "indenter radius") + " mm");
  line(out, "thickness H", num(g.thickness_mm, "thickness") + " mm");
  line(out, "material", material_without(p.material, calibrated == "jlim"));
  if (calibrated != "friction") line(out, "friction mu'", num(p.friction, "friction"));
  line(out, "stick criterion", describe(p.stick));
  line(out, "Part II equation", to_string(p.part_two_equation));
}

std::optional<double> value_of(const Inversion& i) {
  return i.ok() ? std::optional<double>(i.value) : std::nullopt;
}

json inversion_json(const Inversion& i, std::string_view what) {
  json solutions = json::array();
  for (const double s : i.solutions) solutions.push_back(finite(s, what));
  return {{"found", i.ok()},
          {"value", value_or_null(value_of(i), what)},
          {"solutions", solutions},
          {"message", i.message},
          {"evaluations", i.evaluations}};
}

// "1.9923", or "not found: <why>"; a warning on a found value is kept.
std::string inversion_text(const Inversion& i, std::string_view what) {
  if (!i.ok()) return "not found: " + i.message;
  auto text = num(i.value, what);
  if (!i.message.empty()) text += " (" + i.message + ")";
  return text;
}

namespace {

template <class Report>
std::string render_any(const Report& r, Format format) {
  switch (format) {
    case Format::Csv:
      return csv_text(r);
    case Format::Json:
      return json_text(r);
    case Format::Summary:
      break;
  }
  return summary(r);
}

}  // namespace

}  // namespace calibration

using calibration::render_any;

std::string calibration_text(const CriticalI1Report& r, Format f) { return render_any(r, f); }
std::string calibration_text(const FrictionReport& r, Format f) { return render_any(r, f); }
std::string calibration_text(const JLimReport& r, Format f) { return render_any(r, f); }
std::string calibration_text(const UniaxialFitReport& r, Format f) { return render_any(r, f); }
std::string calibration_text(const UniaxialComparisonReport& r, Format f) {
  return render_any(r, f);
}
std::string calibration_text(const BandReport& r, Format f) { return render_any(r, f); }

}  // namespace puncture::cli
