#pragma once
// The standard tests --test sets up: the probe and the opening each standard fixes, and the
// outputs it reports, taken from the loading curve to puncture.
#include <optional>

#include "puncture/loading_curve.hpp"

namespace puncture::cli {

// ASTM F1306, slow-rate penetration resistance of flexible barrier films: a hemispherical probe
// of 3.2 mm diameter pushed through a film clamped over an opening of 34.9 mm diameter.
inline constexpr const char* kAstmF1306 = "astm-f1306";
inline constexpr double kAstmF1306TipRadiusMm = 1.6;
inline constexpr double kAstmF1306OpeningRadiusMm = 17.45;

// The standard's three outputs.
struct AstmF1306Outputs {
  double maximum_force_n = 0.0;     // the largest force up to perforation [N]
  double penetration_mm = 0.0;      // probe penetration to perforation [mm]
  std::optional<double> energy_mj;  // energy to perforation [mJ = N mm]
};

// From a converged curve with its puncture found: the largest force over the puncture and the
// curve's points up to its depth, the puncture's depth and energy.
AstmF1306Outputs astm_f1306_outputs(const LoadingCurve& curve);

}  // namespace puncture::cli
