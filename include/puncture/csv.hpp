#pragma once
// A strict reader of numeric CSV tables (measurements for the calibrations).
//
// Format: the first non-comment line is a header of column names; every following line is one
// row with as many comma-separated fields as the header, each a finite decimal number
// ("1.5", "-2e-3", "+4").  Fields may be padded with spaces.  Blank lines and lines whose first
// non-blank character is '#' are skipped; a UTF-8 byte-order mark and CRLF line ends are
// accepted.  Anything else (a missing or repeated column name, a wrong number of fields, an
// empty, non-numeric, out-of-range, NaN or infinite value, too few rows) is an error that
// names the line and the column.
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace puncture {

// What is wrong with a CSV input, and where.  what() holds the full message,
// e.g. "data.csv:7: column 2 (nominal_stress_mpa): 'abc' is not a number".
class CsvError : public std::runtime_error {
 public:
  CsvError(const std::string& message, int line = 0, int column = 0)
      : std::runtime_error(message), line_(line), column_(column) {}
  int line() const { return line_; }      // 1-based line of the input; 0 when not about one
  int column() const { return column_; }  // 1-based column; 0 when not about one

 private:
  int line_;
  int column_;
};

struct CsvTable {
  std::string source;                     // the name used in messages (e.g. the file name)
  std::vector<std::string> columns;       // header names, in order
  std::vector<std::vector<double>> rows;  // rows[i][j]: data row i, column j
  std::vector<int> line_numbers;          // input line of each data row (1-based)

  std::optional<std::size_t> find(std::string_view column) const;
  bool has(std::string_view column) const { return find(column).has_value(); }
  // The values of one column; CsvError naming the column and the header when it is missing.
  std::vector<double> column(std::string_view name) const;
};

// Parses CSV text.  `source` names the input in messages; `min_rows` is the fewest data rows
// accepted.  Throws CsvError.
CsvTable parse_numeric_csv(std::string_view text, std::string_view source,
                           std::size_t min_rows = 1);

// Reads and parses a file (CsvError also when it cannot be read).
CsvTable read_numeric_csv(const std::string& path, std::size_t min_rows = 1);

}  // namespace puncture
