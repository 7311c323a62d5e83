#include "json_helpers.hpp"

namespace puncture::cli {

std::string dump(const json& j) { return j.dump(2) + "\n"; }

json rows_json(const Table& table) {
  json rows = json::array();
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    json row = json::object();
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      const auto& cell = table.rows[r][c];
      if (const auto* text = std::get_if<std::string>(&cell))
        row[table.columns[c]] = *text;
      else if (const auto* count = std::get_if<int>(&cell))
        row[table.columns[c]] = *count;
      else if (is_missing(cell))
        row[table.columns[c]] = nullptr;
      else
        row[table.columns[c]] = checked_number(table, r, c);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace puncture::cli
