#pragma once
// The model of one measured force-depth record at given values of the free parameters: the
// loading curve at exactly the record's depths (less the test's contact offset) and the predicted
// puncture point.  Results are cached by the parameters that change the curve's shape: the force
// is proportional to the shear modulus (F = 2 pi G H A f(depth / A), without gas pressure and
// without a stick threshold in N or N/mm, which does not scale with G), so a step in G alone
// reuses the normalised curve, and a Jacobian column in G costs no solve.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "puncture/curve_fit.hpp"

namespace puncture::detail {

// One entry of the fit's parameter vector: a parameter shared by every test (test < 0), or one
// test's own (the contact offset).
struct FreeColumn {
  CurveParameter parameter = CurveParameter::ShearModulus;
  int test = -1;
};

struct ModelCurve {
  bool ok = false;
  std::string message;                      // why not, when !ok
  std::vector<double> force_n;              // at each measured point (in the test's order)
  std::optional<double> puncture_force_n;   // when the model punctures
  std::optional<double> puncture_depth_mm;  // in the record's frame (the offset added back)
};

class CurveModel {
 public:
  // `columns` names the entries of the parameter vectors passed to evaluate(); `test_index` is
  // this test's place among the tests (its own contact offset's column).
  CurveModel(const CurveTest& test, int test_index, std::vector<FreeColumn> columns,
             const SolverOptions& solver, bool needs_puncture);
  ModelCurve evaluate(const double* x) const;
  Problem problem_at(const double* x) const;
  double contact_offset_at(const double* x) const;
  // Whether the entry `column` of the parameter vector changes this test's model.
  bool depends_on(std::size_t column) const;
  int solves() const { return solves_; }
  const CurveTest& test() const { return test_; }

 private:
  struct Normalised {  // forces over G, or in N when G does not scale them
    bool ok = false;
    std::string message;
    std::vector<double> force;
    std::optional<double> puncture_force;
    std::optional<double> puncture_depth_mm;  // the model's depth
  };
  Normalised solve(const double* x) const;

  const CurveTest& test_;
  int test_index_;
  std::vector<FreeColumn> columns_;
  SolverOptions solver_;
  bool needs_puncture_;
  bool scales_with_g_;  // F / G does not depend on G
  mutable std::map<std::vector<double>, Normalised> cache_;
  mutable int solves_ = 0;
};

}  // namespace puncture::detail
