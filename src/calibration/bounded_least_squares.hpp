#pragma once
// Bounded nonlinear least squares for the material fits: Ceres' Levenberg-Marquardt inside
// box bounds (each law's validity range), with an active-set step for an optimum on a bound,
// and the covariance sigma^2 (J^T J)^-1.  `Functor` is a residual model with
//   int values(), int inputs(), bool operator()(const VectorXd& x, VectorXd& r) (false where
//   the law cannot be evaluated: the step is shortened), void df(const VectorXd& x, MatrixXd& J).
#include <ceres/ceres.h>
#include <glog/logging.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace puncture::detail {

// The residuals as one Ceres residual block over the parameter block (the law's parameters).
template <class Functor>
class StressResiduals : public ceres::CostFunction {
 public:
  explicit StressResiduals(const Functor& residuals) : residuals_(residuals) {
    set_num_residuals(residuals.values());
    mutable_parameter_block_sizes()->push_back(residuals.inputs());
  }
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(parameters[0], residuals_.inputs());
    Eigen::VectorXd r(residuals_.values());
    if (!residuals_(x, r)) return false;
    Eigen::Map<Eigen::VectorXd>(residuals, residuals_.values()) = r;
    if (jacobians && jacobians[0]) {
      Eigen::MatrixXd jac;
      residuals_.df(x, jac);
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          jacobians[0], residuals_.values(), residuals_.inputs()) = jac;
    }
    return true;
  }

 private:
  const Functor& residuals_;
};

// The law's validity range as bounds of each parameter, and its scale (for "on the bound").
struct Bound {
  double lower, upper, scale;
};

// The index of the first parameter that ended on one of its bounds, if any.
inline std::optional<int> on_bound(const Eigen::VectorXd& x, const std::vector<Bound>& bounds) {
  for (int i = 0; i < static_cast<int>(bounds.size()); ++i) {
    const double tol = 1e-9 * bounds[static_cast<std::size_t>(i)].scale;
    if (x[i] <= bounds[static_cast<std::size_t>(i)].lower + tol ||
        x[i] >= bounds[static_cast<std::size_t>(i)].upper - tol)
      return i;
  }
  return std::nullopt;
}

// sigma^2 (J^T J)^-1 through the SVD of the column-scaled Jacobian; empty when J is singular.
inline std::optional<Eigen::MatrixXd> covariance(const Eigen::MatrixXd& jac, double sigma2) {
  const Eigen::VectorXd norms = jac.colwise().norm();
  if ((norms.array() == 0.0).any() || !norms.allFinite()) return std::nullopt;
  const Eigen::MatrixXd scaled = jac * norms.cwiseInverse().asDiagonal();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeThinV);
  const auto& s = svd.singularValues();
  if (!(s.minCoeff() > 1e-10 * s.maxCoeff())) return std::nullopt;
  const Eigen::MatrixXd v = svd.matrixV();
  const Eigen::MatrixXd inv_scaled =
      v * s.array().square().inverse().matrix().asDiagonal() * v.transpose();
  return sigma2 * norms.cwiseInverse().asDiagonal() * inv_scaled *
         norms.cwiseInverse().asDiagonal();
}

struct LeastSquares {
  bool converged = false;
  int iterations = 0;
  std::string message;          // Ceres' stop reason
  std::optional<int> on_bound;  // the parameter held on its bound at the optimum
  std::vector<int> held;        // least_squares_with_active_set: every parameter held there
};

// One Ceres Levenberg-Marquardt run from x within the bounds, with parameter `held` (if any)
// kept at its value.
template <class Functor>
bool run_levenberg_marquardt(const Functor& functor, const std::vector<Bound>& bounds,
                             Eigen::VectorXd& x, std::optional<int> held, int max_iterations,
                             LeastSquares& out) {
  ceres::Problem problem;
  problem.AddResidualBlock(new StressResiduals<Functor>(functor), nullptr, x.data());
  if (held) {
    if (x.size() == 1) return true;  // nothing left to fit
    problem.SetManifold(x.data(), new ceres::SubsetManifold(static_cast<int>(x.size()), {*held}));
  }
  for (int i = 0; i < x.size(); ++i) {
    problem.SetParameterLowerBound(x.data(), i, bounds[static_cast<std::size_t>(i)].lower);
    if (std::isfinite(bounds[static_cast<std::size_t>(i)].upper))
      problem.SetParameterUpperBound(x.data(), i, bounds[static_cast<std::size_t>(i)].upper);
  }
  ceres::Solver::Options options;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = max_iterations;
  // Stop on the step only (relative 1e-14): the cost is flat at the optimum, so a test on its
  // decrease stops early (1e-8 short of the optimum in 1/J_lim on a noisy test).
  options.function_tolerance = 1e-30;
  options.parameter_tolerance = 1e-14;
  options.gradient_tolerance = 1e-30;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  out.iterations += summary.num_successful_steps + summary.num_unsuccessful_steps;
  out.message = summary.message;
  return summary.termination_type == ceres::CONVERGENCE;
}

// The least-squares optimum inside the bounds (an active-set method over Ceres' bounded
// Levenberg-Marquardt).  Ceres' projected steps creep along an active bound and stop short of
// the optimum on it, so a run that ends on a bound is followed by one on that face (the
// parameter held at its bound); the bound is kept when the cost rises into the range there
// (the Karush-Kuhn-Tucker sign of the gradient), else the search starts again just inside.
template <class Functor>
LeastSquares least_squares_in_range(const Functor& functor, const std::vector<Bound>& bounds,
                                    Eigen::VectorXd& x, int max_iterations) {
  LeastSquares out;
  for (int round = 0; round < 3; ++round) {
    if (!run_levenberg_marquardt(functor, bounds, x, std::nullopt, max_iterations, out)) return out;
    const auto i = on_bound(x, bounds);
    if (!i) {
      out.converged = true;
      return out;
    }
    const auto& b = bounds[static_cast<std::size_t>(*i)];
    const bool lower = x[*i] - b.lower <= b.upper - x[*i];
    x[*i] = lower ? b.lower : b.upper;
    if (!run_levenberg_marquardt(functor, bounds, x, i, max_iterations, out)) return out;
    Eigen::VectorXd r(functor.values());
    Eigen::MatrixXd jac;
    functor(x, r);
    functor.df(x, jac);
    const double slope = jac.col(*i).dot(r);  // half the cost's derivative along parameter i
    if (lower ? slope >= 0.0 : slope <= 0.0) {
      out.converged = true;
      out.on_bound = i;
      return out;
    }
    x[*i] += (lower ? 1e-3 : -1e-3) * b.scale;
  }
  out.message = "the optimum moves on and off a bound of the law's range";
  return out;
}

// Ceres reports a rejected step it could not compute (a Jacobian spanning many orders of
// magnitude, as Ogden's lambda^alpha with a large alpha) through glog, to stderr; the library
// never prints, and the step is rejected and reported anyway.  Raises glog's threshold above
// ERROR for the scope (a process-wide flag: another thread's glog messages are held back
// meanwhile too).
class QuietGlog {
 public:
  QuietGlog() : saved_(FLAGS_minloglevel) { FLAGS_minloglevel = google::GLOG_FATAL; }
  ~QuietGlog() { FLAGS_minloglevel = saved_; }
  QuietGlog(const QuietGlog&) = delete;
  QuietGlog& operator=(const QuietGlog&) = delete;

 private:
  int saved_;
};

// One Ceres Levenberg-Marquardt run from x within the bounds with the parameters `held` kept
// at their values (true when it converged; also when nothing is left to fit).
template <class Functor>
bool run_holding(const Functor& functor, const std::vector<Bound>& bounds, Eigen::VectorXd& x,
                 const std::vector<int>& held, int max_iterations, LeastSquares& out) {
  if (static_cast<Eigen::Index>(held.size()) == x.size()) return true;
  ceres::Problem problem;
  problem.AddResidualBlock(new StressResiduals<Functor>(functor), nullptr, x.data());
  if (!held.empty())
    problem.SetManifold(x.data(), new ceres::SubsetManifold(static_cast<int>(x.size()), held));
  for (int i = 0; i < x.size(); ++i) {
    const auto& b = bounds[static_cast<std::size_t>(i)];
    if (std::isfinite(b.lower)) problem.SetParameterLowerBound(x.data(), i, b.lower);
    if (std::isfinite(b.upper)) problem.SetParameterUpperBound(x.data(), i, b.upper);
  }
  ceres::Solver::Options options;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = max_iterations;
  options.function_tolerance = 1e-30;  // stop on the step only, as run_levenberg_marquardt
  options.parameter_tolerance = 1e-14;
  options.gradient_tolerance = 1e-30;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  const Eigen::VectorXd x0 = x;
  {
    const QuietGlog quiet;
    ceres::Solve(options, &problem, &summary);
  }
  out.iterations += summary.num_successful_steps + summary.num_unsuccessful_steps;
  out.message = summary.message;
  if (summary.termination_type == ceres::FAILURE) x = x0;  // Ceres may leave a rejected trial
  return summary.termination_type == ceres::CONVERGENCE;
}

// The least-squares optimum inside the bounds for several parameters at once (an active-set
// method): the parameters a run leaves on a bound (within 1e-9 of its scale) are held where
// they are, the rest fitted again (Ceres' projected steps crawl along an active bound, often
// until the iteration limit); at an optimum of the free ones a held parameter is released where
// the cost falls into the range (the Karush-Kuhn-Tucker sign of the gradient J_i . r).  Neither
// moves a parameter: next to a bound a tiny change can change the stress a lot (Ogden's
// mu_p lambda^alpha_p with a large alpha_p).  on_bound: the first parameter held at the end.
template <class Functor>
LeastSquares least_squares_with_active_set(const Functor& functor, const std::vector<Bound>& bounds,
                                           Eigen::VectorXd& x, int max_iterations) {
  LeastSquares out;
  std::vector<int> held;
  const auto at_bound = [&](int i) {
    const auto& b = bounds[static_cast<std::size_t>(i)];
    const double tol = 1e-9 * b.scale;
    if (x[i] <= b.lower + tol) return -1;
    if (x[i] >= b.upper - tol) return 1;
    return 0;
  };
  for (int round = 0; round < 4 * static_cast<int>(x.size()) + 4; ++round) {
    const bool converged = run_holding(functor, bounds, x, held, max_iterations, out);
    bool newly_held = false;
    for (int i = 0; i < x.size(); ++i) {
      if (std::find(held.begin(), held.end(), i) != held.end()) continue;
      if (at_bound(i) != 0) {
        held.push_back(i);
        newly_held = true;
      }
    }
    if (newly_held) continue;  // fit the others with these held
    if (!converged) return out;
    Eigen::VectorXd r(functor.values());
    Eigen::MatrixXd jac;
    if (!functor(x, r)) return out;
    functor.df(x, jac);
    std::vector<int> kept;
    for (const int i : held) {
      const double slope = jac.col(i).dot(r);  // half the cost's derivative along parameter i
      const bool lower = at_bound(i) < 0;
      if (lower ? slope >= 0.0 : slope <= 0.0) kept.push_back(i);
    }
    if (kept.size() == held.size()) {
      out.converged = true;
      if (!held.empty()) out.on_bound = held.front();
      out.held = held;
      return out;
    }
    held = kept;
  }
  out.message = "the optimum moves on and off the bounds of the law's range";
  return out;
}

}  // namespace puncture::detail
