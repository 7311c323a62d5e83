#pragma once
// Fields of the data files the calibrations read (csv.cpp, force_depth_record.cpp).
#include <cstddef>
#include <string>
#include <string_view>

namespace puncture::detail {

// `s` without the leading and trailing characters in `blanks`.
inline std::string_view trim(std::string_view s, std::string_view blanks = " \t") {
  const auto first = s.find_first_not_of(blanks);
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(blanks);
  return s.substr(first, last - first + 1);
}

// A field as quoted in a message: too long a field is cut, so one bad cell cannot flood the
// terminal.
inline std::string shown(std::string_view field) {
  constexpr std::size_t kMax = 40;
  if (field.size() <= kMax) return std::string(field);
  return std::string(field.substr(0, kMax)) + "...";
}

}  // namespace puncture::detail
