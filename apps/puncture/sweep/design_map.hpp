#pragma once
// `sweep --plot FILE`: the design map of the finished sweep, drawn by
// python/puncture/sweep_plots.py (matplotlib) from the CSV: the puncture force (or the first
// force at a depth) over the first two numeric swept flags, failed points marked.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "puncture/sweep.hpp"

namespace puncture::cli {

// The --plot FILE given (checked: .png, .svg or .pdf, writable, the tools there), or nothing.
std::optional<std::string> design_map_target(const CLI::App& app);

// Draws it; PlotError when it cannot be drawn.
void draw_design_map(const std::string& csv_path, const SweepSpec& spec, const std::string& target);

}  // namespace puncture::cli
