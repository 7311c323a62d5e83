#pragma once
// `puncture sweep SPEC.toml`: the spec file.
//
//   design = "latin-hypercube"   # grid, latin-hypercube, sobol or monte-carlo
//   samples = 200                # points (not for a grid)
//   seed = 1                     # latin-hypercube and monte-carlo
//   puncture = true              # the puncture point (default true)
//   force-at-depth = [10, 20]    # and/or the force at these depths [mm]
//   [problem]                    # fixed flags, as in --config
//   friction = 0.5
//   [parameters]                 # swept flags, each one of:
//   thickness = { range = [0.15, 0.25] }                       # uniform (grid: + levels = N)
//   indenter = { values = ["flat", "sphere-tipped"] }          # grid levels
//   critical-i1 = { distribution = "normal", mean = 95.2, sd = 3 }
//   shear-modulus = { distribution = "lognormal", mean = 0.06, sd = 0.006 }
//   friction = { distribution = "truncated-normal", mean = 0.18, sd = 0.05, range = [0, 0.5] }
//
// Keys of [problem] and [parameters] are the problem's long flag names (those of
// add_problem_options), so every flag can be fixed or swept.
//
// The reader is Debian's toml11 (libtoml11-dev), shared with the project's other TOML readers:
// CLI11's --config reader flattens a file into flag values and keeps no line of its values,
// while the spec has nested tables, arrays of numbers or words, and errors must name the line.
#include <string>
#include <utility>
#include <vector>

#include "puncture/sweep.hpp"

namespace puncture::cli {

struct SweepFile {
  SweepSpec spec;
  // [problem]: the flag (long name, no dashes) and its value as text.
  std::vector<std::pair<std::string, std::string>> fixed;
};

// Reads and checks the spec (the spec's own rules and the flag names).  Throws InputError
// naming the file, the line and the key.
SweepFile read_sweep_file(const std::string& path);

// The long names of the problem's flags (without "--"), in their order of registration.
std::vector<std::string> problem_flag_names();

}  // namespace puncture::cli
