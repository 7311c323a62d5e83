#pragma once
// `puncture figures --out DIR`: the paper's analytical figures (Liu et al. 2018, Figs. 11-13),
// its inflated balloons (Fig. 14) and a comparison of probes, for the membrane given by the
// flags: the data are computed here, drawn by the plotting script.
#include <CLI/CLI.hpp>
#include <string>

#include "commands.hpp"
#include "puncture/problem.hpp"

namespace puncture::cli {

struct FiguresFlags {
  std::string out_dir;
};
void add_figures_options(CLI::App& figures, FiguresFlags& flags);

// Every figure's data as JSON: "inputs", "fig11", "fig12a", "fig12b", "fig13", "fig14", "probes".
// The base problem's indenter radius and friction are replaced by each figure's own; Fig. 14 uses
// the base's pressure (3e-4 MPa without one, "pressure_assumed").
std::string figures_json(const Problem& base, const CurveFlags& curve);

// Computes the data, writes DIR/figures-data.json and draws the figures (PNG and SVG) into DIR;
// returns the text to print: the files written.
std::string run_figures(const Problem& base, const CurveFlags& curve, const FiguresFlags& flags);

}  // namespace puncture::cli
