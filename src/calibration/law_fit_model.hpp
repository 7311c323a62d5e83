#pragma once
// Every law's nominal stress in a homogeneous test as a function of a parameter vector, for the
// least-squares fit (uniaxial_fit.cpp): the parameters, their bounds (the law's validity range),
// a starting point, and the material they describe.  The stress is the library's own
// (uniaxial_stress, equibiaxial_stress of the law), so a fitted law is the law the solver uses.
//
//   law            parameters x                     bounds
//   neo-hookean    G                                G > 0
//   mooney-rivlin  G, alpha                         0 <= alpha <= 1
//   gent           G, c = 1/J_lim                   0 <= c < 1/(I1 - 3) at the largest stretch
//   yeoh           C10, C20, C30 [MPa]              C10 > 0, C20 >= 0, C30 >= 0
//   ogden          mu_1..mu_N [MPa], alpha_1..N     each term keeps its start's sign:
//                                                   mu_p alpha_p >= 0, |alpha_p| >= 1
//   arruda-boyce   G, 1/N                           0 <= 1/N < min(1, 3 / I1) (locking, N > 1)
//   gent-gent      G, c = 1/J_lim, beta             c as gent, 0 <= beta <= 1
// c = 0 (and 1/N = 0) is the neo-Hookean limit, so a fit of data without stiffening ends on
// that bound instead of running J_lim or N to infinity.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "calibration/bounded_least_squares.hpp"
#include "puncture/calibration.hpp"
#include "puncture/material.hpp"

namespace puncture::detail {

class LawFitModel {
 public:
  // Throws std::invalid_argument for Ogden exponents that are not 1 to 3 finite numbers with
  // |alpha| >= 1, or ogden_terms outside 1..3.
  LawFitModel(FitLaw law, const std::vector<UniaxialPoint>& data,
              const UniaxialFitOptions& options);

  int size() const { return static_cast<int>(names_.size()); }
  const std::vector<std::string>& names() const { return names_; }
  const std::vector<std::string>& units() const { return units_; }
  // Parameters reported as the reciprocal of the fitted one (J_lim = 1/c, N = 1/(1/N)).
  const std::vector<bool>& reciprocal() const { return reciprocal_; }
  const std::vector<Bound>& bounds() const { return bounds_; }
  // The starting points, best first: one, except for Ogden, whose exponents make the stress
  // non-convex in a way a single start often misses (with uniaxial data alone a term can
  // trade against another): each subset of terms fitted linearly at the starting exponents
  // (the others just inside mu_p = 0), by their residual.
  const std::vector<Eigen::VectorXd>& starts() const { return starts_; }

  // The law (with G = 1 for Ogden, whose mu_p are in MPa) and the modulus scaling its stress.
  // False where the parameters are not a law this can evaluate (G <= 0 for Ogden).
  bool law_at(const Eigen::VectorXd& x, MaterialLaw& law, double& scale_mpa) const;
  // The nominal stress [MPa] at stretch l, NaN where the law cannot be evaluated.
  double stress(const MaterialLaw& law, double scale_mpa, double l) const;
  // The material the parameters describe, as the solver takes it; nullopt when they are not one
  // (c = 0: no J_lim; G <= 0; a law the membrane checks refuse).
  std::optional<Material> material(const Eigen::VectorXd& x) const;

 private:
  FitLaw law_;
  StressTest test_;
  std::vector<std::string> names_, units_;
  std::vector<bool> reciprocal_;
  std::vector<Bound> bounds_;
  Eigen::VectorXd start_;
  std::vector<Eigen::VectorXd> starts_;
  int ogden_terms_ = 0;
};

// The residuals model - data of a LawFitModel, with the Jacobian by central differences
// extrapolated (Richardson) to O(h^4), one-sided next to a bound or where the law cannot be
// evaluated.
class LawResiduals {
 public:
  LawResiduals(const LawFitModel& model, const std::vector<UniaxialPoint>& data)
      : model_(model), data_(data) {}
  int values() const { return static_cast<int>(data_.size()); }
  int inputs() const { return model_.size(); }
  bool operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const;
  void df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) const;

 private:
  const LawFitModel& model_;
  const std::vector<UniaxialPoint>& data_;
};

}  // namespace puncture::detail
