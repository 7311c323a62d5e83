#pragma once
// The model of one measured force-depth record at given values of the free parameters: the
// loading curve at exactly the record's depths and the predicted puncture point.  Results are
// cached by the parameters that change the curve's shape: the force is proportional to the
// shear modulus (F = 2 pi G H A f(depth / A), without gas pressure), so a step in G alone
// reuses the normalised curve, and a Jacobian column in G costs no solve.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "puncture/curve_fit.hpp"

namespace puncture::detail {

struct ModelCurve {
  bool ok = false;
  std::string message;                     // why not, when !ok
  std::vector<double> force_n;             // at each measured point (in the test's order)
  std::optional<double> puncture_force_n;  // when the model punctures
  std::optional<double> puncture_depth_mm;
};

class CurveModel {
 public:
  // `free` names the entries of the parameter vectors passed to evaluate().
  CurveModel(const CurveTest& test, std::vector<CurveParameter> free, const SolverOptions& solver,
             bool needs_puncture);
  ModelCurve evaluate(const double* x) const;
  Problem problem_at(const double* x) const;
  int solves() const { return solves_; }
  const CurveTest& test() const { return test_; }

 private:
  struct Normalised {  // forces over G, or in N when G does not scale them
    bool ok = false;
    std::string message;
    std::vector<double> force;
    std::optional<double> puncture_force;
    std::optional<double> puncture_depth_mm;
  };
  Normalised solve(const double* x) const;

  const CurveTest& test_;
  std::vector<CurveParameter> free_;
  SolverOptions solver_;
  bool needs_puncture_;
  bool scales_with_g_;                 // no pressure: F / G does not depend on G
  std::vector<double> unique_depths_;  // strictly increasing
  std::vector<std::size_t> point_to_unique_;
  mutable std::map<std::vector<double>, Normalised> cache_;
  mutable int solves_ = 0;
};

}  // namespace puncture::detail
