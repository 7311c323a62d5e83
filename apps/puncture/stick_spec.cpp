#include "stick_spec.hpp"

#include <fmt/format.h>

#include <charconv>
#include <utility>

namespace puncture::cli {

namespace {

std::optional<double> parse_number(std::string_view text) {
  double value = 0.0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

}  // namespace

std::optional<StickCriterion> parse_stick(std::string_view text) {
  if (text == "none") return StickCriterion{StickRule::None, 0.0};
  if (text == "always") return StickCriterion{StickRule::Always, 0.0};
  if (text == "coulomb") return StickCriterion{StickRule::Coulomb, 0.0};
  const auto colon = text.find(':');
  if (colon == std::string_view::npos) return std::nullopt;
  const auto name = text.substr(0, colon);
  StickRule rule;
  if (name == "force")
    rule = StickRule::Force;
  else if (name == "depth")
    rule = StickRule::Depth;
  else if (name == "edge-tension")
    rule = StickRule::EdgeTension;
  else
    return std::nullopt;
  const auto threshold = parse_number(text.substr(colon + 1));
  if (!threshold) return std::nullopt;
  return StickCriterion{rule, *threshold};
}

std::string_view threshold_unit(StickRule rule) {
  switch (rule) {
    case StickRule::Force:
      return "N";
    case StickRule::Depth:
      return "mm";
    case StickRule::EdgeTension:
      return "N/mm";
    case StickRule::None:
    case StickRule::Always:
    case StickRule::Coulomb:
      return "";
  }
  return "";
}

}  // namespace puncture::cli
