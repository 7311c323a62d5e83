#pragma once
// --plot FILE and the figures subcommand: the CLI writes its JSON to a temporary file and runs
// the Python package's plotting script (python/puncture/plot_cli.py, matplotlib) on it.
// The interpreter is the one CMake chose (Debian's /usr/bin/python3 by default), or
// $PUNCTURE_PYTHON; the script is $PUNCTURE_PLOT_SCRIPT, else the installed copy found from the
// executable's location (<prefix>/bin/../<libdir>/puncture/python/puncture/plot_cli.py), else
// the source tree's (the executable in the build tree).
#include <stdexcept>
#include <string>

namespace puncture::cli {

// The figure could not be drawn: no Python, no matplotlib, or the script failed (exit code 3).
struct PlotError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
inline constexpr int kExitPlotFailure = 3;

// The interpreter and the script that draw the figures.
std::string plot_python();
std::string plot_script();

// Fails early, before any computation: InputError when `path` (a --plot FILE) does not end in
// .png, .svg or .pdf or cannot be created; PlotError when the interpreter or the script is missing.
void check_plot_target(const std::string& path);
// PlotError when the interpreter or the script is missing.
void check_plot_tools();

// Runs the script: `kind` is "curve", "state" or "figures", `json` the CLI's JSON output for it,
// `target` the image file (or, for figures, the directory).  Throws PlotError on failure (the
// script prints its reason on stderr).
void run_plot_script(const std::string& kind, const std::string& json, const std::string& target);

}  // namespace puncture::cli
