// A testing machine's force-depth record (include/puncture/force_depth_record.hpp).
#include "puncture/force_depth_record.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "calibration/text_fields.hpp"

namespace puncture {

namespace {

using detail::shown;

// A field without its blanks and quotes.
std::string_view trim_quoted(std::string_view s) { return detail::trim(s, " \t\""); }

std::vector<std::string_view> split(std::string_view line, char separator) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const auto at = line.find(separator, start);
    // A tab-separated line keeps its tabs out of the fields' trimming only between fields.
    fields.push_back(trim_quoted(line.substr(start, at - start)));
    if (at == std::string_view::npos) break;
    start = at + 1;
  }
  return fields;
}

// A finite decimal number ("1.5", "-2e-3", "+4", with a decimal comma "1,5"); empty otherwise.
std::optional<double> number(std::string_view field, bool decimal_comma) {
  if (field.empty()) return std::nullopt;
  std::string text(field);
  if (decimal_comma) std::replace(text.begin(), text.end(), ',', '.');
  std::string_view digits = text;
  if (digits.front() == '+') digits.remove_prefix(1);
  if (digits.empty() || digits.front() == '+' || (field.front() == '+' && digits.front() == '-'))
    return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

struct Line {
  int number = 0;
  std::string_view text;
};

std::vector<Line> content_lines(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::vector<Line> lines;
  int number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    auto end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos || line[first] == '#') continue;
    lines.push_back({number, line});
  }
  return lines;
}

std::size_t column_of(const ColumnChoice& choice, const char* what,
                      const std::vector<std::string_view>& header, bool has_header,
                      std::size_t fields, const std::string& where) {
  if (choice.index > 0) {
    const auto j = static_cast<std::size_t>(choice.index - 1);
    if (j >= fields)
      throw CsvError(fmt::format("{}: the {} column {} does not exist: the line has {} field{}",
                                 where,
                                 what,
                                 choice.index,
                                 fields,
                                 fields == 1 ? "" : "s"),
                     0,
                     choice.index);
    return j;
  }
  if (!has_header)
    throw CsvError(
        fmt::format("{}: the {} column is chosen by name ('{}') but the record has no "
                    "header: choose it by its position (1, 2, ...)",
                    where,
                    what,
                    choice.name));
  for (std::size_t j = 0; j < header.size(); ++j)
    if (header[j] == choice.name) return j;
  std::string names;
  for (const auto& h : header) names += (names.empty() ? "" : ", ") + std::string(h);
  throw CsvError(
      fmt::format(
          "{}: missing {} column '{}' (the header has: {})", where, what, choice.name, names),
      0,
      0);
}

}  // namespace

std::optional<DepthUnit> depth_unit_from_token(std::string_view token) {
  if (token == "mm") return DepthUnit::Millimetre;
  if (token == "m") return DepthUnit::Metre;
  if (token == "in") return DepthUnit::Inch;
  return std::nullopt;
}

std::optional<ForceUnit> force_unit_from_token(std::string_view token) {
  if (token == "N") return ForceUnit::Newton;
  if (token == "kN") return ForceUnit::Kilonewton;
  if (token == "lbf") return ForceUnit::PoundForce;
  if (token == "gf") return ForceUnit::GramForce;
  return std::nullopt;
}

double millimetres_per(DepthUnit unit) {
  switch (unit) {
    case DepthUnit::Millimetre:
      return 1.0;
    case DepthUnit::Metre:
      return 1000.0;
    case DepthUnit::Inch:
      return 25.4;  // exact
  }
  return 1.0;
}

double newtons_per(ForceUnit unit) {
  switch (unit) {
    case ForceUnit::Newton:
      return 1.0;
    case ForceUnit::Kilonewton:
      return 1000.0;
    case ForceUnit::PoundForce:
      return 4.4482216152605;  // exact: 0.45359237 kg x 9.80665 m/s^2
    case ForceUnit::GramForce:
      return 9.80665e-3;  // exact
  }
  return 1.0;
}

ForceDepthRecord parse_force_depth_record(std::string_view text, std::string_view source,
                                          const RecordFormat& format) {
  if (format.separator != 0 && format.separator != ',' && format.separator != ';' &&
      format.separator != '\t')
    throw std::invalid_argument("the separator must be ',', ';' or a tab");
  if (format.decimal_comma == Tristate::Yes && format.separator == ',')
    throw std::invalid_argument("a decimal comma needs a ';' or tab separator");
  if (format.baseline_points < 2 || format.sustained_points < 1 ||
      !(format.contact_sigmas >= 0.0) || !(format.contact_noise_n >= 0.0) ||
      !(format.drop_fraction > 0.0 && format.drop_fraction < 1.0))
    throw std::invalid_argument(
        "the contact rule needs >= 2 baseline points, >= 1 sustained point, sigmas and noise "
        ">= 0, and the drop fraction in (0, 1)");
  if (format.contact_depth && !std::isfinite(*format.contact_depth))
    throw std::invalid_argument("the contact depth must be a finite number");

  ForceDepthRecord out;
  out.source = std::string(source);
  const auto lines = content_lines(text);
  if (lines.empty()) throw CsvError(fmt::format("{}: the record is empty", source));

  // Separator and decimal mark from the first data line (the line after a header).
  char sep = format.separator;
  const auto& probe = lines.size() > 1 ? lines[1].text : lines[0].text;
  if (sep == 0)
    sep = probe.find('\t') != std::string_view::npos  ? '\t'
          : probe.find(';') != std::string_view::npos ? ';'
                                                      : ',';
  out.separator = sep;
  out.decimal_comma = format.decimal_comma == Tristate::Yes ||
                      (format.decimal_comma == Tristate::Auto && sep != ',');

  const auto first_fields = split(lines[0].text, sep);
  bool has_header = format.header == Tristate::Yes;
  if (format.header == Tristate::Auto)
    has_header = std::any_of(first_fields.begin(), first_fields.end(), [&](auto f) {
      return !number(f, out.decimal_comma);
    });
  out.header = has_header;
  const std::string head_where = fmt::format("{}:{}", source, lines[0].number);
  const std::size_t width = first_fields.size();
  std::size_t jd = 0, jf = 0;
  try {
    jd = column_of(format.depth, "depth", first_fields, has_header, width, head_where);
    jf = column_of(format.force, "force", first_fields, has_header, width, head_where);
  } catch (const CsvError& e) {
    throw CsvError(e.what(), lines[0].number, e.column());
  }
  const auto name_of = [&](std::size_t j) {
    return has_header ? fmt::format("column {} ({})", j + 1, first_fields[j])
                      : fmt::format("column {}", j + 1);
  };

  std::vector<double> depth, force;
  std::vector<int> line_numbers;
  for (std::size_t k = has_header ? 1 : 0; k < lines.size(); ++k) {
    const auto fields = split(lines[k].text, sep);
    const auto at = fmt::format("{}:{}", source, lines[k].number);
    for (const auto j : {jd, jf}) {
      if (j >= fields.size())
        throw CsvError(fmt::format("{}: {} is missing: the line has {} field{}",
                                   at,
                                   name_of(j),
                                   fields.size(),
                                   fields.size() == 1 ? "" : "s"),
                       lines[k].number,
                       static_cast<int>(j + 1));
      if (!number(fields[j], out.decimal_comma))
        throw CsvError(fmt::format("{}: {}: '{}' is not a number{}",
                                   at,
                                   name_of(j),
                                   shown(fields[j]),
                                   fields[j].empty() ? " (empty)" : ""),
                       lines[k].number,
                       static_cast<int>(j + 1));
    }
    depth.push_back(*number(fields[jd], out.decimal_comma) * millimetres_per(format.depth_unit));
    force.push_back(*number(fields[jf], out.decimal_comma) * newtons_per(format.force_unit));
    line_numbers.push_back(lines[k].number);
  }
  out.rows = static_cast<int>(depth.size());
  const std::size_t n = depth.size();

  // Perforation: the first force below (1 - drop) of the largest before it, once that has
  // reached a tenth of the record's largest (the baseline's noise is no perforation).
  std::size_t end = n;  // one past the last kept point
  if (format.cut_at_perforation && n > 0) {
    const double significant = 0.1 * *std::max_element(force.begin(), force.end());
    std::size_t peak = 0;
    for (std::size_t i = 1; i < n; ++i) {
      if (force[i] < (1.0 - format.drop_fraction) * force[peak] && force[peak] > significant &&
          force[peak] > 0.0) {
        end = peak + 1;
        out.perforation_line = line_numbers[peak];
        break;
      }
      if (force[i] >= force[peak]) peak = i;
    }
  }

  // Contact.
  std::size_t begin = 0;  // the contact point's index
  if (format.contact_depth) {
    out.contact_depth_mm = *format.contact_depth * millimetres_per(format.depth_unit);
  } else {
    const auto b = static_cast<std::size_t>(format.baseline_points);
    const auto k = static_cast<std::size_t>(format.sustained_points);
    if (end < b + k)
      throw CsvError(
          fmt::format("{}: {} points before the perforation: finding the contact "
                      "point needs at least {} (baseline {} + sustained rise {}); "
                      "give the contact depth instead",
                      source,
                      end,
                      b + k,
                      b,
                      k));
    const double mean = std::accumulate(force.begin(), force.begin() + static_cast<long>(b), 0.0) /
                        static_cast<double>(b);
    double var = 0.0;
    for (std::size_t i = 0; i < b; ++i) var += (force[i] - mean) * (force[i] - mean);
    const double sd = std::sqrt(var / static_cast<double>(b - 1));
    const double threshold = mean + std::max(format.contact_sigmas * sd, format.contact_noise_n);
    std::optional<std::size_t> rise;
    for (std::size_t i = b; i + k <= end && !rise; ++i) {
      bool above = true;
      for (std::size_t j = i; j < i + k && above; ++j) above = force[j] > threshold;
      if (above) rise = i;
    }
    if (!rise)
      throw CsvError(
          fmt::format("{}: no contact found: the force never rises above {:.6g} N "
                      "(the first {} forces' mean + {} sd) for {} points; give the "
                      "contact depth",
                      source,
                      threshold,
                      b,
                      format.contact_sigmas,
                      k));
    begin = *rise - 1;
    out.contact_depth_mm = depth[begin];
    out.contact_found = true;
  }

  for (std::size_t i = 0; i < end; ++i) {
    if (i > 0 && depth[i] < depth[i - 1])
      throw CsvError(fmt::format("{}:{}: {}: the depth decreases ({} after {}): the depth must "
                                 "not decrease up to the perforation",
                                 source,
                                 line_numbers[i],
                                 name_of(jd),
                                 depth[i] / millimetres_per(format.depth_unit),
                                 depth[i - 1] / millimetres_per(format.depth_unit)),
                     line_numbers[i],
                     static_cast<int>(jd + 1));
    const double d = depth[i] - out.contact_depth_mm;
    if (i < begin || !(d > 0.0)) continue;
    out.depth_mm.push_back(d);
    out.force_n.push_back(force[i]);
    out.line_numbers.push_back(line_numbers[i]);
  }
  if (end < n && !out.depth_mm.empty()) {
    out.perforation_depth_mm = out.depth_mm.back();
    out.perforation_force_n = out.force_n.back();
  }
  if (out.depth_mm.size() < 2)
    throw CsvError(
        fmt::format("{}: {} point{} past the contact point (depth {:.6g} mm){}: a "
                    "curve needs at least 2",
                    source,
                    out.depth_mm.size(),
                    out.depth_mm.size() == 1 ? "" : "s",
                    out.contact_depth_mm,
                    end < n ? " before the perforation" : ""));
  return out;
}

ForceDepthRecord read_force_depth_record(const std::string& path, const RecordFormat& format) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw CsvError(fmt::format("{}: cannot open the file for reading", path));
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw CsvError(fmt::format("{}: cannot read the file", path));
  return parse_force_depth_record(text.str(), path, format);
}

}  // namespace puncture
