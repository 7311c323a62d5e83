// Joint least-squares fit of force-depth records (include/puncture/curve_fit.hpp).
//
// Two stages on Ceres' bounded Levenberg-Marquardt:
//  1. the curves alone, r = F_model - F_measured [N] (the critical I1, which only moves the
//     puncture point, held); each test's residual standard deviation s_t is its force noise;
//  2. every residual over its standard deviation: each test's curve over its s_t, a measured
//     puncture point's force and depth over sd_fraction times its value.  With one test and no
//     puncture point this changes no optimum and is not solved again.
// The covariance is (J^T J)^-1 of stage 2's weighted residuals (by the SVD of the column-scaled
// Jacobian Ceres evaluates), the 95 %
// intervals value -+ t(0.975, n - p) se.  The Jacobian is by central differences of the
// model (CurveModel caches the solves; in G, which scales the force, the difference is exact).
#include "puncture/curve_fit.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <memory>
#include <numeric>

#include "calibration/curve_model.hpp"
#include "calibration/fit_verdict.hpp"
#include "calibration/stick_threshold_profile.hpp"

namespace puncture {

namespace {

using detail::CurveModel;
using detail::FreeColumn;
using detail::ModelCurve;

// Which residuals of a test a block holds, and their weights.
struct Weights {
  double curve = 1.0;  // 1 / s
  double force = 0.0;  // 1 / sd of the puncture force
  double depth = 0.0;  // 1 / sd of the puncture depth
};

enum class Block { Curve, Puncture };

class ModelCost : public ceres::CostFunction {
 public:
  // `point`: the curve residual of that point alone (a block per point, so that a robust loss,
  // which Ceres applies to a block's whole squared norm, acts on each point); -1: every point.
  ModelCost(const CurveModel& model, Block block, const Weights& weights,
            const std::vector<ParameterBounds>& bounds, const std::vector<double>& steps,
            int point = -1)
      : model_(model),
        block_(block),
        weights_(weights),
        bounds_(bounds),
        steps_(steps),
        point_(point) {
    set_num_residuals(block == Block::Puncture ? 2
                      : point >= 0             ? 1
                                               : static_cast<int>(model.test().depth_mm.size()));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(bounds.size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const double* x = parameters[0];
    const int n = num_residuals();
    const int p = static_cast<int>(bounds_.size());
    std::vector<double> r(static_cast<std::size_t>(n));
    if (!residuals_at(x, r.data())) return false;
    std::copy(r.begin(), r.end(), residuals);
    if (!jacobians || !jacobians[0]) return true;
    std::vector<double> xs(x, x + p), up(static_cast<std::size_t>(n)),
        down(static_cast<std::size_t>(n));
    for (int j = 0; j < p; ++j) {
      const auto ju = static_cast<std::size_t>(j);
      if (!model_.depends_on(ju)) {  // another test's own parameter
        for (int i = 0; i < n; ++i) jacobians[0][i * p + j] = 0.0;
        continue;
      }
      const double h = steps_[ju] * std::max(std::abs(x[j]), scale(j));
      // Central where both sides are inside the bounds and solve; else one-sided.
      double hi = x[j] + h, lo = x[j] - h;
      if (hi > bounds_[ju].upper) hi = x[j];
      if (lo < bounds_[ju].lower) lo = x[j];
      xs[ju] = hi;
      bool ok_up = hi == x[j] ? (up = r, true) : residuals_at(xs.data(), up.data());
      xs[ju] = lo;
      bool ok_down = lo == x[j] ? (down = r, true) : residuals_at(xs.data(), down.data());
      xs[ju] = x[j];
      if (!ok_up && lo != x[j]) {
        hi = x[j];
        up = r;
        ok_up = true;
      }
      if (!ok_down && hi != x[j]) {
        lo = x[j];
        down = r;
        ok_down = true;
      }
      if (!ok_up || !ok_down || hi == lo) return false;
      for (int i = 0; i < n; ++i)
        jacobians[0][i * p + j] =
            (up[static_cast<std::size_t>(i)] - down[static_cast<std::size_t>(i)]) / (hi - lo);
    }
    return true;
  }

 private:
  // A parameter's typical size, for the step where its value is near zero (friction).
  double scale(int j) const {
    const auto& b = bounds_[static_cast<std::size_t>(j)];
    return std::min(1.0, 0.1 * (b.upper - b.lower));
  }

  bool residuals_at(const double* x, double* r) const {
    const ModelCurve m = model_.evaluate(x);
    if (!m.ok) return false;
    const auto& test = model_.test();
    if (block_ == Block::Curve) {
      if (point_ >= 0) {
        const auto i = static_cast<std::size_t>(point_);
        r[0] = weights_.curve * (m.force_n[i] - test.force_n[i]);
        return true;
      }
      for (std::size_t i = 0; i < m.force_n.size(); ++i)
        r[i] = weights_.curve * (m.force_n[i] - test.force_n[i]);
      return true;
    }
    if (!m.puncture_force_n || !m.puncture_depth_mm) return false;
    r[0] = weights_.force * (*m.puncture_force_n - test.puncture->force_n);
    r[1] = weights_.depth * (*m.puncture_depth_mm - test.puncture->depth_mm);
    return true;
  }

  const CurveModel& model_;
  Block block_;
  Weights weights_;
  const std::vector<ParameterBounds>& bounds_;
  const std::vector<double>& steps_;
  int point_;
};

struct Solved {
  bool usable = false;
  int iterations = 0;
  std::string message;
};

std::unique_ptr<ceres::LossFunction> loss_of(const CurveFitOptions& o, double weight) {
  switch (o.loss) {
    case RobustLoss::None:
      return nullptr;
    case RobustLoss::Huber:
      return std::make_unique<ceres::HuberLoss>(o.loss_scale_n * weight);
    case RobustLoss::Cauchy:
      return std::make_unique<ceres::CauchyLoss>(o.loss_scale_n * weight);
  }
  return nullptr;
}

// The Ceres problem over x: the curves (weight 1 / s) and, with `with_puncture`, the measured
// puncture points; `held` parameters stay at their values.
struct FitProblem {
  ceres::Problem problem;
  std::vector<ceres::ResidualBlockId> curve_blocks;

  // `curve_weights`: 1 / sd of each test's curve residuals.
  FitProblem(const std::vector<std::unique_ptr<CurveModel>>& models, const CurveFitOptions& o,
             const std::vector<ParameterBounds>& bounds, const std::vector<double>& steps,
             std::vector<double>& x, const std::vector<double>& curve_weights, bool with_puncture,
             const std::vector<int>& held) {
    for (std::size_t t = 0; t < models.size(); ++t) {
      const auto& m = models[t];
      Weights weights;
      weights.curve = curve_weights[t];
      if (o.loss == RobustLoss::None) {
        curve_blocks.push_back(problem.AddResidualBlock(
            new ModelCost(*m, Block::Curve, weights, bounds, steps), nullptr, x.data()));
      } else {
        for (int i = 0; i < static_cast<int>(m->test().depth_mm.size()); ++i)
          curve_blocks.push_back(
              problem.AddResidualBlock(new ModelCost(*m, Block::Curve, weights, bounds, steps, i),
                                       loss_of(o, weights.curve).release(),
                                       x.data()));
      }
      if (with_puncture && m->test().puncture) {
        Weights w = weights;
        w.force = 1.0 / (o.puncture_force_sd_fraction * m->test().puncture->force_n);
        w.depth = 1.0 / (o.puncture_depth_sd_fraction * m->test().puncture->depth_mm);
        problem.AddResidualBlock(
            new ModelCost(*m, Block::Puncture, w, bounds, steps), nullptr, x.data());
      }
    }
    if (!held.empty() && held.size() < x.size())
      problem.SetManifold(x.data(), new ceres::SubsetManifold(static_cast<int>(x.size()), held));
    for (std::size_t i = 0; i < x.size(); ++i) {
      problem.SetParameterLowerBound(x.data(), static_cast<int>(i), bounds[i].lower);
      problem.SetParameterUpperBound(x.data(), static_cast<int>(i), bounds[i].upper);
    }
  }
};

Solved run(FitProblem& fp, const CurveFitOptions& o) {
  ceres::Solver::Options options;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = o.max_iterations;
  options.function_tolerance = o.function_tolerance;
  options.parameter_tolerance = o.parameter_tolerance;
  options.gradient_tolerance = 1e-16;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &fp.problem, &summary);
  Solved out;
  out.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  out.message = summary.message;
  out.usable = summary.termination_type == ceres::CONVERGENCE;
  return out;
}

// What test would separate a parameter from the others.
std::string identifying_test(CurveParameter p) {
  switch (p) {
    case CurveParameter::ShearModulus:
      return "a shallow test (the initial stiffness) or a uniaxial test (puncture fit uniaxial)";
    case CurveParameter::JLim:
      return "a test run deeper into the stiffening (to perforation, or with a smaller clamp "
             "radius), or a uniaxial test to large stretch";
    case CurveParameter::Friction:
      return "a test with another friction (dry and lubricated) or another probe radius, or the "
             "hole size (puncture calibrate friction)";
    case CurveParameter::CriticalI1:
      return "a test run to perforation (its puncture point)";
    case CurveParameter::StickThreshold:
      return "a test that passes the stick -> slip switch";
    case CurveParameter::ContactOffset:
      return "the contact point given (--contact-depth) or a record from before the contact";
  }
  return "";
}

void check_input(const CurveFitProblem& problem, const CurveFitOptions& o) {
  std::vector<ValidationError> errors;
  if (problem.tests.empty()) errors.push_back({"tests", "the fit needs at least one test"});
  if (o.free.empty()) errors.push_back({"free", "no free parameter: nothing to fit"});
  for (std::size_t i = 0; i < o.free.size(); ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (o.free[i] == o.free[k])
        errors.push_back({"free", fmt::format("{} is named twice", to_token(o.free[i]))});
  const std::size_t p = o.free.size();
  bool any_puncture = false;
  for (const auto& t : problem.tests) {
    for (auto e : validation_errors(t.problem)) {
      e.message = fmt::format("test {}: {}", t.name, e.message);
      errors.push_back(std::move(e));
    }
    for (const auto f : o.free) try {
        if (f != CurveParameter::ContactOffset) value_of(f, t.problem);
      } catch (const InvalidInput& e) {
        errors.push_back({"free", fmt::format("test {}: {}", t.name, e.what())});
      }
    if (t.depth_mm.size() != t.force_n.size())
      errors.push_back(
          {"tests",
           fmt::format(
               "test {}: {} depths but {} forces", t.name, t.depth_mm.size(), t.force_n.size())});
    if (t.depth_mm.size() < p + 1)
      errors.push_back({"tests",
                        fmt::format("test {}: {} point{} for {} free parameter{}: at least {} "
                                    "needed (one more, for the noise)",
                                    t.name,
                                    t.depth_mm.size(),
                                    t.depth_mm.size() == 1 ? "" : "s",
                                    p,
                                    p == 1 ? "" : "s",
                                    p + 1)});
    for (std::size_t i = 0; i < t.depth_mm.size(); ++i) {
      const double d = t.depth_mm[i];
      if (!std::isfinite(d) || d <= 0.0 || (i > 0 && d < t.depth_mm[i - 1])) {
        errors.push_back({"tests",
                          fmt::format("test {}: point {}: the depth must be finite, > 0 mm and "
                                      "not decrease, got {} mm",
                                      t.name,
                                      i + 1,
                                      d)});
        break;
      }
      if (i < t.force_n.size() && !std::isfinite(t.force_n[i])) {
        errors.push_back(
            {"tests", fmt::format("test {}: point {}: the force is not finite", t.name, i + 1)});
        break;
      }
    }
    if (t.puncture) {
      any_puncture = true;
      if (!(t.puncture->force_n > 0.0) || !(t.puncture->depth_mm > 0.0) ||
          !std::isfinite(t.puncture->force_n) || !std::isfinite(t.puncture->depth_mm))
        errors.push_back(
            {"tests",
             fmt::format("test {}: the puncture point must have a force and a depth > 0", t.name)});
    }
  }
  const auto is_free = [&](CurveParameter f) {
    return std::find(o.free.begin(), o.free.end(), f) != o.free.end();
  };
  if (is_free(CurveParameter::StickThreshold)) {
    if (problem.tests.size() != 1)
      errors.push_back({"free",
                        fmt::format("stick-threshold is fitted from one test's switch, got {} "
                                    "tests (a shared threshold switches each test at another "
                                    "depth: not supported yet)",
                                    problem.tests.size())});
    if (is_free(CurveParameter::ContactOffset))
      errors.push_back({"free",
                        "stick-threshold and contact-offset cannot both be free: the offset "
                        "would move the measured depths across the switch"});
  }
  if (std::find(o.free.begin(), o.free.end(), CurveParameter::CriticalI1) != o.free.end() &&
      !any_puncture)
    errors.push_back({"free",
                      "critical-i1 is free but no test has a puncture point: only where the "
                      "membrane perforates determines it (a test run to perforation)"});
  if (o.loss != RobustLoss::None && !(o.loss_scale_n > 0.0 && std::isfinite(o.loss_scale_n)))
    errors.push_back({"loss_scale_n", "a robust loss needs a scale > 0 N"});
  if (!(o.puncture_force_sd_fraction > 0.0) || !(o.puncture_depth_sd_fraction > 0.0))
    errors.push_back({"puncture_sd_fraction", "the puncture point's sd fractions must be > 0"});
  if (!(o.relative_step > 0.0 && o.relative_step < 0.1))
    errors.push_back({"relative_step", "the difference step must be in (0, 0.1)"});
  if (o.max_iterations < 1) errors.push_back({"max_iterations", "must be >= 1"});
  if (!(o.function_tolerance > 0.0) || !(o.parameter_tolerance > 0.0))
    errors.push_back({"tolerance", "the function and parameter tolerances must be > 0"});
  for (const auto& b : o.bounds)
    if (!(b.lower < b.upper) || !std::isfinite(b.lower) || !std::isfinite(b.upper))
      errors.push_back({"bounds",
                        fmt::format("the bounds of {} must be finite with lower < upper, got "
                                    "[{}, {}]",
                                    to_token(b.parameter),
                                    b.lower,
                                    b.upper)});
  if (!errors.empty()) throw InvalidInput(std::move(errors), "invalid curve fit:");
}

}  // namespace

CurveFit fit_curves(const CurveFitProblem& problem, const CurveFitOptions& o) {
  check_input(problem, o);
  if (std::find(o.free.begin(), o.free.end(), CurveParameter::StickThreshold) != o.free.end())
    return detail::fit_with_stick_threshold_profile(problem, o);
  const Problem& first = problem.tests.front().problem;

  // The parameter vector: the shared parameters, then each test's contact offset.
  std::vector<FreeColumn> columns;
  for (const auto f : o.free)
    if (f != CurveParameter::ContactOffset) columns.push_back({f, -1});
  if (std::find(o.free.begin(), o.free.end(), CurveParameter::ContactOffset) != o.free.end())
    for (std::size_t t = 0; t < problem.tests.size(); ++t)
      columns.push_back({CurveParameter::ContactOffset, static_cast<int>(t)});
  const std::size_t p = columns.size();
  std::vector<ParameterBounds> bounds;
  std::vector<double> x, steps(p, o.relative_step);
  for (const auto& c : columns) {
    auto b = default_bounds(c.parameter, first);
    double start = 0.0;
    if (c.test >= 0) {  // the contact offset: within half the test's deepest point
      const auto& t = problem.tests[static_cast<std::size_t>(c.test)];
      const double half = 0.5 * *std::max_element(t.depth_mm.begin(), t.depth_mm.end());
      b = {c.parameter, -half, half};
      start = t.contact_offset_mm;
    } else {
      start = value_of(c.parameter, first);
    }
    for (const auto& given : o.bounds)
      if (given.parameter == c.parameter) b = given;
    bounds.push_back(b);
    x.push_back(std::clamp(start, b.lower, b.upper));
  }
  const auto index_of = [&](CurveParameter f) -> std::optional<std::size_t> {
    for (std::size_t j = 0; j < p; ++j)
      if (columns[j].parameter == f && columns[j].test < 0) return j;
    return std::nullopt;
  };
  // A column's name in messages: a test's own parameter names its test.
  const auto name_of = [&](std::size_t j) {
    const auto& c = columns[j];
    return c.test < 0 ? to_token(c.parameter)
                      : fmt::format("{} of test {}",
                                    to_token(c.parameter),
                                    problem.tests[static_cast<std::size_t>(c.test)].name);
  };
  bool any_puncture = false;
  for (const auto& t : problem.tests) any_puncture = any_puncture || t.puncture.has_value();

  std::vector<std::unique_ptr<CurveModel>> models;
  for (std::size_t t = 0; t < problem.tests.size(); ++t)
    models.push_back(std::make_unique<CurveModel>(problem.tests[t],
                                                  static_cast<int>(t),
                                                  columns,
                                                  o.solver,
                                                  problem.tests[t].puncture.has_value()));

  CurveFit fit;
  const auto solves = [&] {
    int n = 0;
    for (const auto& m : models) n += m->solves();
    return n;
  };
  const auto fail = [&](Status status, std::string message) {
    fit.status = status;
    fit.message = std::move(message);
    fit.curve_evaluations = solves();
    return fit;
  };

  // The start: the first test's values; with G free, G scaled so that the start's curves match
  // the data in the least-squares sense (the force is proportional to G).
  for (const auto& m : models) {
    const auto start = m->evaluate(x.data());
    if (!start.ok)
      return fail(Status::NoConvergence,
                  fmt::format("the model fails at the starting parameters for test {}: {}",
                              m->test().name,
                              start.message));
  }
  if (const auto g = index_of(CurveParameter::ShearModulus)) {
    double fd = 0.0, ff = 0.0;
    for (const auto& m : models) {
      const auto start = m->evaluate(x.data());
      for (std::size_t i = 0; i < start.force_n.size(); ++i) {
        fd += start.force_n[i] * m->test().force_n[i];
        ff += start.force_n[i] * start.force_n[i];
      }
    }
    if (ff > 0.0 && fd > 0.0)
      x[*g] = std::clamp(x[*g] * fd / ff, bounds[*g].lower, bounds[*g].upper);
  }

  // Stage 1: the curves.
  std::vector<int> held;
  if (const auto c = index_of(CurveParameter::CriticalI1)) held.push_back(static_cast<int>(*c));
  int points = 0;
  for (const auto& t : problem.tests) points += static_cast<int>(t.depth_mm.size());
  if (held.size() < p) {
    FitProblem stage1(
        models, o, bounds, steps, x, std::vector<double>(models.size(), 1.0), false, held);
    const auto s1 = run(stage1, o);
    fit.iterations += s1.iterations;
    if (!s1.usable)
      return fail(Status::NoConvergence,
                  "Levenberg-Marquardt did not converge on the curves: " + s1.message);
  }
  // Each test's noise: its residual sd, the degrees of freedom shared out by its points (tests
  // with other probes or load cells have other noise; one pooled sd under-covers: 82 % of 95 %
  // intervals held the truth for a 2 and a 4 mm probe fitted in G, J_lim and friction).
  double ssr = 0.0, sst = 0.0;
  const int curve_p = static_cast<int>(p - held.size());
  std::vector<double> curve_weights;
  for (const auto& m : models) {
    const auto at = m->evaluate(x.data());
    if (!at.ok) return fail(Status::NoConvergence, "the model fails at the fit: " + at.message);
    const auto& f = m->test().force_n;
    const double n_t = static_cast<double>(f.size());
    const double mean = std::accumulate(f.begin(), f.end(), 0.0) / n_t;
    double ssr_t = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      ssr_t += (at.force_n[i] - f[i]) * (at.force_n[i] - f[i]);
      sst += (f[i] - mean) * (f[i] - mean);
    }
    ssr += ssr_t;
    const double s_t = std::sqrt(ssr_t / (n_t - curve_p * n_t / points));
    if (!(s_t > 0.0) || !std::isfinite(s_t))
      return fail(Status::NoConvergence,
                  fmt::format("the model fits test {} exactly (residual sd 0): no noise to weigh "
                              "it by",
                              m->test().name));
    curve_weights.push_back(1.0 / s_t);
  }

  // Stage 2: every residual over its standard deviation (the curves' from stage 1: one step of
  // reweighting).  With one test and no puncture point the weight is a constant: the same
  // optimum.
  FitProblem stage2(models, o, bounds, steps, x, curve_weights, true, {});
  if (any_puncture || models.size() > 1) {
    const auto s2 = run(stage2, o);
    fit.iterations += s2.iterations;
    if (!s2.usable)
      return fail(Status::NoConvergence,
                  "Levenberg-Marquardt did not converge on the weighted residuals: " + s2.message);
  }

  // Residuals at the estimates.
  ssr = 0.0;
  for (std::size_t t = 0; t < models.size(); ++t) {
    const auto& test = problem.tests[t];
    const auto at = models[t]->evaluate(x.data());
    if (!at.ok) return fail(Status::NoConvergence, "the model fails at the fit: " + at.message);
    CurveTestFit tf;
    tf.name = test.name;
    tf.depth_mm = test.depth_mm;
    tf.force_n = test.force_n;
    tf.model_force_n = at.force_n;
    double sq = 0.0;
    for (std::size_t i = 0; i < at.force_n.size(); ++i) {
      tf.residual_n.push_back(at.force_n[i] - test.force_n[i]);
      sq += tf.residual_n.back() * tf.residual_n.back();
    }
    ssr += sq;
    tf.rms_residual_n = std::sqrt(sq / static_cast<double>(at.force_n.size()));
    tf.measured_puncture = test.puncture;
    if (at.puncture_force_n && at.puncture_depth_mm)
      tf.model_puncture = MeasuredPuncture{*at.puncture_depth_mm, *at.puncture_force_n};
    fit.tests.push_back(std::move(tf));
    fit.fitted_problems.push_back(models[t]->problem_at(x.data()));
  }
  fit.points = points;
  fit.residual_sd_n = std::sqrt(ssr / std::max(1, points - curve_p));
  fit.r_squared = sst > 0.0 ? 1.0 - ssr / sst : 0.0;

  // Covariance of the weighted residuals.
  int residual_count = points;
  for (const auto& t : problem.tests) residual_count += t.puncture ? 2 : 0;
  const int dof = residual_count - static_cast<int>(p);
  std::vector<double> cov(p * p, 0.0);
  bool have_cov = false;
  // (J^T J)^-1 through the SVD of the column-scaled Jacobian (ceres::Covariance inverts the
  // unscaled J^T J, whose columns differ by orders of magnitude in N/MPa and N per unit J_lim,
  // and logs to stderr through glog when it gives up).  The scaled Jacobian's smallest singular
  // value against its largest: a parameter the data do not separate from the others makes it
  // ~0, and the null direction names it.
  {
    ceres::CRSMatrix crs;
    stage2.problem.Evaluate(ceres::Problem::EvaluateOptions(), nullptr, nullptr, nullptr, &crs);
    Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
    for (int r = 0; r < crs.num_rows; ++r)
      for (int k = crs.rows[static_cast<std::size_t>(r)];
           k < crs.rows[static_cast<std::size_t>(r) + 1];
           ++k)
        jac(r, crs.cols[static_cast<std::size_t>(k)]) = crs.values[static_cast<std::size_t>(k)];
    const Eigen::VectorXd norms = jac.colwise().norm();
    for (std::size_t j = 0; j < p; ++j)
      if (!(norms[static_cast<Eigen::Index>(j)] > 0.0))
        fit.warnings.push_back(
            fmt::format("{} is not identifiable: the data do not depend on it; it would take {}",
                        name_of(j),
                        identifying_test(columns[j].parameter)));
    if ((norms.array() > 0.0).all() && norms.allFinite()) {
      const Eigen::MatrixXd scaled = jac * norms.cwiseInverse().asDiagonal();
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeThinV);
      const auto& sv = svd.singularValues();
      if (sv.minCoeff() < 1e-6 * sv.maxCoeff()) {
        Eigen::Index worst = 0;
        svd.matrixV().col(static_cast<Eigen::Index>(p) - 1).cwiseAbs().maxCoeff(&worst);
        fit.warnings.push_back(
            fmt::format("{} is not identifiable from these tests (the Jacobian is rank-deficient, "
                        "condition {:.2g}); it would take {}",
                        name_of(static_cast<std::size_t>(worst)),
                        sv.maxCoeff() / sv.minCoeff(),
                        identifying_test(columns[static_cast<std::size_t>(worst)].parameter)));
      } else {
        const Eigen::MatrixXd v = svd.matrixV();
        const Eigen::VectorXd inv_norms = norms.cwiseInverse();
        const Eigen::MatrixXd c = inv_norms.asDiagonal() * v *
                                  sv.array().square().inverse().matrix().asDiagonal() *
                                  v.transpose() * inv_norms.asDiagonal();
        for (std::size_t i = 0; i < p; ++i)
          for (std::size_t j = 0; j < p; ++j)
            cov[i * p + j] = c(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        have_cov = c.allFinite();
      }
    }
  }

  const double t_quantile = dof > 0 ? boost::math::quantile(boost::math::complement(
                                          boost::math::students_t_distribution<double>(dof), 0.025))
                                    : 0.0;
  for (std::size_t j = 0; j < p; ++j) {
    FittedCurveParameter fp;
    fp.parameter = columns[j].parameter;
    fp.name = to_token(columns[j].parameter);
    fp.unit = unit_of(columns[j].parameter, first);
    if (columns[j].test >= 0)
      fp.test = problem.tests[static_cast<std::size_t>(columns[j].test)].name;
    fp.value = x[j];
    const double span = bounds[j].upper - bounds[j].lower;
    const double tol = 1e-6 * std::max(std::abs(x[j]), 1e-3 * span);
    fp.on_bound = x[j] <= bounds[j].lower + tol || x[j] >= bounds[j].upper - tol;
    if (have_cov && cov[j * p + j] >= 0.0 && dof > 0) {
      fp.standard_error = std::sqrt(cov[j * p + j]);
      fp.ci_lower = x[j] - t_quantile * *fp.standard_error;
      fp.ci_upper = x[j] + t_quantile * *fp.standard_error;
      // Within two standard errors of zero (as fit_uniaxial): the data bound the parameter
      // no better than its own size.
      // (Not for a contact offset, whose 0 is a value like any other: the contact found right.)
      if (2.0 * *fp.standard_error >= std::abs(x[j]) &&
          columns[j].parameter != CurveParameter::ContactOffset) {
        fp.identifiable = false;
        fp.note = fmt::format(
            "not identifiable: {} +- {} is within two standard errors of 0; {} "
            "would identify it",
            x[j],
            *fp.standard_error,
            identifying_test(columns[j].parameter));
        fit.warnings.push_back(
            fmt::format("{} is not identifiable from these tests ({:.4g} +- {:.2g}); it would "
                        "take {}",
                        name_of(j),
                        x[j],
                        *fp.standard_error,
                        identifying_test(columns[j].parameter)));
      }
    } else {
      fp.identifiable = false;
      fp.note =
          "no standard error: " + identifying_test(columns[j].parameter) + " would identify it";
    }
    fit.parameters.push_back(fp);
  }
  if (have_cov) {
    fit.correlation.assign(p, std::vector<double>(p, 0.0));
    for (std::size_t i = 0; i < p; ++i)
      for (std::size_t j = 0; j < p; ++j)
        fit.correlation[i][j] = cov[i * p + j] / std::sqrt(cov[i * p + i] * cov[j * p + j]);
    for (std::size_t i = 0; i < p; ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (std::abs(fit.correlation[i][j]) > 0.99) {
          for (const auto k : {i, j}) {
            fit.parameters[k].identifiable = false;
            fit.parameters[k].note = fmt::format(
                "correlated with {} (r = {:.4f}): the data fix a combination of the two",
                name_of(k == i ? j : i),
                fit.correlation[i][j]);
          }
          fit.warnings.push_back(fmt::format(
              "{} and {} are not separately identifiable from these tests (r = {:.4f}); "
              "{} would separate them",
              name_of(i),
              name_of(j),
              fit.correlation[i][j],
              identifying_test(columns[i].parameter)));
        }
  } else {
    for (auto& fp : fit.parameters) fp.identifiable = false;
  }

  fit.curve_evaluations = solves();
  fit.status = Status::Converged;
  for (const auto& fp : fit.parameters)
    if (fp.on_bound) {
      fit.status = Status::OnBound;
      const auto& b = bounds[static_cast<std::size_t>(&fp - fit.parameters.data())];
      const bool lower = fp.value - b.lower <= b.upper - fp.value;
      const bool jlim_floor =
          fp.parameter == CurveParameter::JLim && lower && !index_of(CurveParameter::CriticalI1);
      const bool jlim_ceiling = fp.parameter == CurveParameter::JLim && !lower;
      fit.message = fmt::format(
          "{} = {:.6g} lies on a bound of its range [{:.6g}, {:.6g}]: the data want a value "
          "outside it, and the estimates are not a fit inside the model{}",
          name_of(static_cast<std::size_t>(&fp - fit.parameters.data())),
          fp.value,
          b.lower,
          b.upper,
          jlim_floor ? " (J_lim must exceed the critical I1 - 3: a record that does not reach "
                       "the puncture may want a smaller one; a lower critical I1 lowers the "
                       "bound)"
          : jlim_ceiling
              ? fmt::format(" (the records show no Gent stiffening, a neo-Hookean response: "
                            "J_lim is not identifiable from them; it would take {})",
                            identifying_test(CurveParameter::JLim))
              : std::string());
      fit.warnings.push_back(fit.message);
      return fit;
    }
  if (detail::outside_model_by_r_squared(fit, o.min_r_squared)) return fit;
  if (!fit.warnings.empty()) fit.message = fit.warnings.front();
  return fit;
}

}  // namespace puncture
