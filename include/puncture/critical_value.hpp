#pragma once
// The critical value of any failure criterion from the same inflation tests as the critical I1
// (calibration.hpp, critical_i1_from_inflation): each test's burst state, the membrane inflated
// until its pole stretch is the mark's, gives the criterion's measure where it is largest.
#include <optional>
#include <vector>

#include "puncture/calibration.hpp"
#include "puncture/failure.hpp"

namespace puncture {

struct CriticalValueEstimate : Outcome {  // NoConvergence when an inflated state was not found
  FailureCriterion criterion;             // the criterion, with the mean as its critical value
  std::vector<double> stretches;          // per test: burst radius / initial radius (pole)
  std::vector<double> pole_values;        // per test: the measure at the equibiaxial pole
  std::vector<double> values;             // per test: the measure where it is largest
  // Per test: where that is, its reference radius over the clamp radius (0 = the pole).
  std::vector<double> radius_fractions;
  bool from_membrane = false;  // the membrane's law was solved (else the pole's measure)
  double mean = 0.0;           // mean of the per-test values: the critical value (its unit)
  std::optional<double> standard_deviation;  // sample standard deviation (n - 1); needs 2 tests
  std::optional<double> standard_error;      // of the mean, sd / sqrt(n)
};

// The critical value of `criterion`'s measure (its own critical value is ignored) for the
// membrane of `material` (G sets the MPa of the energy density and the true stress).  With
// `pole_only` each test's value is the pole's closed form at the mark's stretch (the paper's
// estimate: it assumes the burst starts at the pole); else the largest over the inflated
// membrane's fields (sampled at SolverOptions' field_points), never below the pole's.  Throws
// as critical_i1_from_inflation.
CriticalValueEstimate critical_value_from_inflation(const std::vector<BurstTest>& tests,
                                                    const FailureCriterion& criterion,
                                                    const Material& material, bool pole_only);

}  // namespace puncture
