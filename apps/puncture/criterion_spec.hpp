#pragma once
// The --criterion flag: text <-> FailureCriterion.
#include <string>
#include <string_view>
#include <vector>

#include "puncture/failure_criteria.hpp"

namespace puncture::cli {

// The accepted forms, for help and error messages.
inline constexpr std::string_view kCriterionForms =
    "i1:<I1>, max-stretch:<stretch>, energy-density:<MPa>, true-stress:<MPa> or "
    "energy-release:<N/mm>";

// Parses each NAME:VALUE (a list may hold several, from repeated flags or commas).  Appends a
// message naming --criterion to `errors` for a malformed item or an unknown name; the values'
// ranges are the library's validation_errors()'.
std::vector<FailureCriterion> parse_criteria(const std::vector<std::string>& items,
                                             std::vector<std::string>& errors);

}  // namespace puncture::cli
