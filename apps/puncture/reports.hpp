#pragma once
// What each subcommand computed, handed to the summary, CSV and JSON writers.
#include <optional>
#include <string>

#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "puncture/problem.hpp"
#include "puncture/verification.hpp"
#include "standard_test.hpp"

namespace puncture::cli {

struct CurveReport {
  Problem problem;
  int points_requested = 0;
  double max_depth_mm = 0.0;                   // 0: to puncture
  LoadingCurve curve;                          // converged
  std::optional<AstmF1306Outputs> astm_f1306;  // with --test astm-f1306
};

struct StateReport {
  Problem problem;
  std::optional<double> requested_force_n;  // exactly one of these is set
  std::optional<double> requested_depth_mm;
  std::string stage_choice;  // how the stage was chosen, in words
  Equilibrium state;         // converged
};

struct PunctureReport {
  Problem problem;
  PuncturePrediction puncture;                 // found
  std::optional<AstmF1306Outputs> astm_f1306;  // with --test astm-f1306
};

struct VerifyReport {
  Problem problem;
  VerificationReport verification;
};

}  // namespace puncture::cli
