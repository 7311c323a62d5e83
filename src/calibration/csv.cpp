#include "puncture/csv.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <system_error>

#include "calibration/text_fields.hpp"

namespace puncture {

namespace {

using detail::shown;
using detail::trim;

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

double parse_number(std::string_view field, const std::string& where, int line, int column) {
  if (field.empty()) throw CsvError(fmt::format("{}: empty value", where), line, column);
  std::string_view digits = field;
  if (digits.front() == '+') digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range)
    throw CsvError(
        fmt::format("{}: '{}' is out of the range of a double", where, shown(field)), line, column);
  if (ec != std::errc() || end != digits.data() + digits.size() ||
      (field.front() == '+' && (digits.empty() || digits.front() == '-')))
    throw CsvError(fmt::format("{}: '{}' is not a number", where, shown(field)), line, column);
  if (!std::isfinite(value))
    throw CsvError(
        fmt::format("{}: '{}' is not a finite number", where, shown(field)), line, column);
  return value;
}

}  // namespace

std::optional<std::size_t> CsvTable::find(std::string_view column) const {
  for (std::size_t j = 0; j < columns.size(); ++j)
    if (columns[j] == column) return j;
  return std::nullopt;
}

std::vector<double> CsvTable::column(std::string_view name) const {
  const auto j = find(name);
  if (!j) {
    std::string header;
    for (const auto& c : columns) header += (header.empty() ? "" : ",") + c;
    throw CsvError(
        fmt::format("{}: missing column '{}' (the header has: {})", source, name, header), 1);
  }
  std::vector<double> values;
  values.reserve(rows.size());
  for (const auto& row : rows) values.push_back(row[*j]);
  return values;
}

CsvTable parse_numeric_csv(std::string_view text, std::string_view source, std::size_t min_rows) {
  CsvTable table;
  table.source = std::string(source);
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte-order mark

  int line_number = 0;
  std::size_t start = 0;
  bool have_header = false;
  while (start < text.size()) {
    auto end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const auto content = trim(line);
    if (content.empty() || content.front() == '#') continue;
    const auto at = fmt::format("{}:{}", source, line_number);
    const auto fields = split_fields(line);

    if (!have_header) {
      have_header = true;
      for (std::size_t j = 0; j < fields.size(); ++j) {
        const int column = static_cast<int>(j) + 1;
        if (fields[j].empty())
          throw CsvError(
              fmt::format("{}: header column {} has no name (the first line must be a header "
                          "of column names)",
                          at,
                          column),
              line_number,
              column);
        for (std::size_t k = 0; k < j; ++k)
          if (fields[k] == fields[j])
            throw CsvError(fmt::format("{}: header column {} repeats the name '{}' of column {}",
                                       at,
                                       column,
                                       shown(fields[j]),
                                       k + 1),
                           line_number,
                           column);
        table.columns.emplace_back(fields[j]);
      }
      // A header of numbers is data without a header.
      double ignored = 0.0;
      const auto first = fields.front();
      const auto* digits = first.data() + (first.front() == '+' ? 1 : 0);
      const auto [end_ptr, ec] = std::from_chars(digits, first.data() + first.size(), ignored);
      if (ec == std::errc() && end_ptr == first.data() + first.size())
        throw CsvError(fmt::format("{}: the first line must be a header of column names, got "
                                   "the number '{}' in column 1",
                                   at,
                                   shown(first)),
                       line_number,
                       1);
      continue;
    }

    if (fields.size() != table.columns.size())
      throw CsvError(fmt::format("{}: {} field{}, but the header has {} column{}",
                                 at,
                                 fields.size(),
                                 fields.size() == 1 ? "" : "s",
                                 table.columns.size(),
                                 table.columns.size() == 1 ? "" : "s"),
                     line_number,
                     0);
    std::vector<double> row;
    row.reserve(fields.size());
    for (std::size_t j = 0; j < fields.size(); ++j) {
      const int column = static_cast<int>(j) + 1;
      const auto where = fmt::format("{}: column {} ({})", at, column, table.columns[j]);
      row.push_back(parse_number(fields[j], where, line_number, column));
    }
    table.rows.push_back(std::move(row));
    table.line_numbers.push_back(line_number);
  }

  if (!have_header) throw CsvError(fmt::format("{}: no header line: the input is empty", source));
  if (table.rows.size() < min_rows)
    throw CsvError(fmt::format("{}: too few data rows: {} found, at least {} needed",
                               source,
                               table.rows.size(),
                               min_rows));
  return table;
}

CsvTable read_numeric_csv(const std::string& path, std::size_t min_rows) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw CsvError(fmt::format("{}: cannot open the file for reading", path));
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw CsvError(fmt::format("{}: cannot read the file", path));
  return parse_numeric_csv(text.str(), path, min_rows);
}

}  // namespace puncture
