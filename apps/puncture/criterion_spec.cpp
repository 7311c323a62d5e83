#include "criterion_spec.hpp"

#include <fmt/format.h>

#include <cstdlib>

#include "puncture/failure.hpp"

namespace puncture::cli {

std::vector<FailureCriterion> parse_criteria(const std::vector<std::string>& items,
                                             std::vector<std::string>& errors) {
  std::vector<FailureCriterion> out;
  for (const std::string& item : items) {
    const auto colon = item.find(':');
    const std::string name = item.substr(0, colon);
    const std::string number = colon == std::string::npos ? "" : item.substr(colon + 1);
    char* end = nullptr;
    const double value = number.empty() ? 0.0 : std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size()) {
      errors.push_back(fmt::format("--criterion: expected {}, got '{}'", kCriterionForms, item));
      continue;
    }
    try {
      out.push_back(criterion_from_name(name, value));
    } catch (const InvalidInput& e) {
      errors.push_back(fmt::format("--criterion: {}", e.errors().front().message));
    }
  }
  return out;
}

}  // namespace puncture::cli
