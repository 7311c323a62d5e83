#pragma once
// The --stick flag: text <-> StickCriterion.
#include <optional>
#include <string>
#include <string_view>

#include "puncture/problem.hpp"

namespace puncture::cli {

// The accepted forms, for help and error messages.
inline constexpr std::string_view kStickForms =
    "none, always, force:<N>, depth:<mm>, edge-tension:<N/mm> or coulomb";

// Parses none | always | coulomb | force:<N> | depth:<mm> | edge-tension:<N/mm>; empty when
// malformed. The threshold's range (finite, > 0) is checked by the library's validation_errors().
std::optional<StickCriterion> parse_stick(std::string_view text);

// Unit of the rule's threshold: "N", "mm", "N/mm", or "" for none / always.
std::string_view threshold_unit(StickRule rule);

}  // namespace puncture::cli
