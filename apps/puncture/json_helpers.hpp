#pragma once
// Pieces of JSON that several writers share.  Every number is checked finite (SolveError naming
// it otherwise).
#include <nlohmann/json.hpp>
#include <string>

#include "tables.hpp"

namespace puncture::cli {

using json = nlohmann::ordered_json;

// The complete text: indented by 2, with a final newline.
std::string dump(const json& j);

// One object per row, keyed by the column names; a missing number is null.
json rows_json(const Table& table);

}  // namespace puncture::cli
