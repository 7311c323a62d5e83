// Least-squares fit of a uniaxial tensile test (paper §4.1, Fig. 11).
//
// Model: nominal stress P = G g(lambda) m(lambda; theta), g = lambda - lambda^-2 (neo-Hookean),
//   Gent:          m = 1 / (1 - c k),  k = I1 - 3 = lambda^2 + 2/lambda - 3,  c = 1 / J_lim
//   Mooney-Rivlin: m = 1 - alpha + alpha / lambda
// (the uniaxial_stress of each law; the tests check the two agree).  Ceres' Levenberg-Marquardt
// minimises sum (P_model - P_data)^2 with the analytic Jacobian inside each law's validity range
// (bounds: G > 0; Mooney-Rivlin 0 <= alpha <= 1; Gent 0 <= c < 1 / (I1 - 3) of the largest
// stretch, where the data would lock).  An unbounded fit can run off to parameters no solver
// accepts (Mooney-Rivlin alpha = -5e4 on stiffening data); a best fit on a bound is reported as
// Status::OnBound.  The standard errors are sigma sqrt(diag((J^T J)^-1)) at an interior
// optimum, sigma^2 = SSR / (n - p).
#include <ceres/ceres.h>
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "puncture/calibration.hpp"

namespace puncture {

namespace {

struct Data {
  Eigen::VectorXd stretch, stress, g, k, inv;  // lambda, P, lambda - lambda^-2, I1 - 3, 1/lambda
};

Data prepare(const std::vector<UniaxialPoint>& points) {
  const auto n = static_cast<Eigen::Index>(points.size());
  Data d{Eigen::VectorXd(n),
         Eigen::VectorXd(n),
         Eigen::VectorXd(n),
         Eigen::VectorXd(n),
         Eigen::VectorXd(n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    const double l = points[static_cast<std::size_t>(i)].stretch;
    d.stretch[i] = l;
    d.stress[i] = points[static_cast<std::size_t>(i)].nominal_stress_mpa;
    d.g[i] = l - 1.0 / (l * l);
    d.k[i] = l * l + 2.0 / l - 3.0;
    d.inv[i] = 1.0 / l;
  }
  return d;
}

int parameter_count(FitLaw law) { return law == FitLaw::NeoHookean ? 1 : 2; }

// Residuals and their Jacobian; false where Gent would lock (the minimiser then shortens the step).
struct Residuals {
  const Data& d;
  FitLaw law;
  int values() const { return static_cast<int>(d.stretch.size()); }
  int inputs() const { return parameter_count(law); }
  bool locks(double c) const { return ((1.0 - c * d.k.array()) <= 0.0).any(); }
  Eigen::ArrayXd mooney_rivlin_factor(double alpha) const {
    return (1.0 - alpha) + alpha * d.inv.array();
  }

  bool operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
    const double G = x[0];
    switch (law) {
      case FitLaw::NeoHookean:
        r = G * d.g - d.stress;
        break;
      case FitLaw::MooneyRivlin:
        r = (G * d.g.array() * mooney_rivlin_factor(x[1])).matrix() - d.stress;
        break;
      case FitLaw::Gent:
        if (locks(x[1])) return false;
        r = (G * d.g.array() / (1.0 - x[1] * d.k.array())).matrix() - d.stress;
        break;
    }
    return true;
  }

  void df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) const {
    jac.resize(values(), inputs());
    switch (law) {
      case FitLaw::NeoHookean:
        jac.col(0) = d.g;
        break;
      case FitLaw::MooneyRivlin:
        jac.col(0) = (d.g.array() * mooney_rivlin_factor(x[1])).matrix();
        jac.col(1) = (x[0] * d.g.array() * (d.inv.array() - 1.0)).matrix();
        break;
      case FitLaw::Gent: {
        const Eigen::ArrayXd denom = 1.0 - x[1] * d.k.array();
        jac.col(0) = (d.g.array() / denom).matrix();
        jac.col(1) = (x[0] * d.g.array() * d.k.array() / denom.square()).matrix();
        break;
      }
    }
  }
};

// The residuals as one Ceres residual block over the parameter block (G, alpha or c).
class StressResiduals : public ceres::CostFunction {
 public:
  explicit StressResiduals(const Residuals& residuals) : residuals_(residuals) {
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
  const Residuals& residuals_;
};

// The law's validity range as bounds of each parameter, and its scale (for "on the bound").
struct Bound {
  double lower, upper, scale;
};

std::vector<Bound> validity_bounds(const Data& d, FitLaw law, double g_scale) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  // G > 0: a floor far below any modulus the data could give (the stress scale's 1e-12).
  std::vector<Bound> bounds{{1e-12 * g_scale, inf, g_scale}};
  if (law == FitLaw::MooneyRivlin) bounds.push_back({0.0, 1.0, 1.0});
  if (law == FitLaw::Gent) {
    // c < 1/(I1 - 3) at the largest stretch, or the data's last point is at or past locking.
    const double c_lock = 1.0 / d.k.maxCoeff();
    bounds.push_back({0.0, (1.0 - 1e-6) * c_lock, c_lock});
  }
  return bounds;
}

// The index of the first parameter that ended on one of its bounds, if any.
std::optional<int> on_bound(const Eigen::VectorXd& x, const std::vector<Bound>& bounds) {
  for (int i = 0; i < static_cast<int>(bounds.size()); ++i) {
    const double tol = 1e-9 * bounds[static_cast<std::size_t>(i)].scale;
    if (x[i] <= bounds[static_cast<std::size_t>(i)].lower + tol ||
        x[i] >= bounds[static_cast<std::size_t>(i)].upper - tol)
      return i;
  }
  return std::nullopt;
}

// A starting point from linear least squares: the neo-Hookean G; for Mooney-Rivlin the exact
// optimum of P = A g + B g / lambda (linear in A = G (1 - alpha), B = G alpha); for Gent the
// linearisation P = G g + c k P, with c kept inside the domain.
Eigen::VectorXd start(const Data& d, FitLaw law) {
  const double g_nh = d.g.dot(d.stress) / d.g.squaredNorm();
  Eigen::VectorXd x(parameter_count(law));
  x[0] = g_nh;
  if (law == FitLaw::NeoHookean) return x;
  Eigen::MatrixXd a(d.g.size(), 2);
  a.col(0) = d.g;
  a.col(1) = law == FitLaw::MooneyRivlin ? Eigen::VectorXd(d.g.cwiseProduct(d.inv))
                                         : Eigen::VectorXd(d.k.cwiseProduct(d.stress));
  const Eigen::Vector2d ab = a.colPivHouseholderQr().solve(d.stress);
  if (law == FitLaw::MooneyRivlin) {
    const double G = ab[0] + ab[1];
    if (std::isfinite(G) && G > 0.0) {
      x[0] = G;
      x[1] = ab[1] / G;
    } else {
      x[1] = 0.0;
    }
    return x;
  }
  const double c_max = 1.0 / d.k.maxCoeff();
  if (std::isfinite(ab[0]) && ab[0] > 0.0 && std::isfinite(ab[1])) {
    x[0] = ab[0];
    x[1] = std::clamp(ab[1], 0.0, 0.5 * c_max);
  } else {
    x[1] = 0.0;
  }
  return x;
}

// sigma^2 (J^T J)^-1 through the SVD of the column-scaled Jacobian; empty when J is singular.
std::optional<Eigen::MatrixXd> covariance(const Eigen::MatrixXd& jac, double sigma2) {
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
};

// One Ceres Levenberg-Marquardt run from x within the bounds, with parameter `held` (if any)
// kept at its value.
bool run_levenberg_marquardt(const Residuals& functor, const std::vector<Bound>& bounds,
                             Eigen::VectorXd& x, std::optional<int> held, int max_iterations,
                             LeastSquares& out) {
  ceres::Problem problem;
  problem.AddResidualBlock(new StressResiduals(functor), nullptr, x.data());
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
LeastSquares least_squares_in_range(const Residuals& functor, const std::vector<Bound>& bounds,
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

// More than two standard errors from zero.
bool determined(double value, const std::optional<double>& se) {
  return se && 2.0 * *se < std::abs(value);
}

// Why the best fit on a bound says the law does not describe the data inside its range.
std::string on_bound_message(FitLaw law, int index, const Eigen::VectorXd& x,
                             const std::vector<Bound>& bounds) {
  const auto& b = bounds[static_cast<std::size_t>(index)];
  const bool lower = x[index] - b.lower <= b.upper - x[index];
  const auto where =
      fmt::format("the best {} fit lies on a bound of the law's validity range: ", to_string(law));
  if (index == 0)
    return where + fmt::format("G = {:.4g} MPa, its floor; the data do not describe a {} material",
                               x[0],
                               to_string(law));
  if (law == FitLaw::MooneyRivlin)
    return where + (lower ? fmt::format("alpha = 0 (G = {:.4g} MPa): the data stiffen with the "
                                        "stretch more than neo-Hookean, which no Mooney-Rivlin "
                                        "material does (fit the gent law)",
                                        x[0])
                          : fmt::format("alpha = 1 (G = {:.4g} MPa): the data soften with the "
                                        "stretch more than any Mooney-Rivlin material",
                                        x[0]));
  return where +
         (lower ? fmt::format("1/J_lim = 0, neo-Hookean (G = {:.4g} MPa): the data show no Gent "
                              "stiffening (fit the neo-hookean law, or calibrate J_lim from a "
                              "puncture test)",
                              x[0])
                : fmt::format("J_lim = {:.4g}, the largest I1 - 3 of the data: they stiffen "
                              "faster than a Gent material can, locking at the last point",
                              1.0 / b.scale));
}

}  // namespace

std::string to_string(FitLaw law) {
  switch (law) {
    case FitLaw::Gent:
      return "gent";
    case FitLaw::NeoHookean:
      return "neo-hookean";
    case FitLaw::MooneyRivlin:
      return "mooney-rivlin";
  }
  return "gent";
}

std::vector<UniaxialPoint> uniaxial_points(const std::vector<double>& force_n,
                                           const std::vector<double>& displacement_mm,
                                           const SpecimenGeometry& specimen) {
  for (const auto& [name, value] : {std::pair{"specimen width", specimen.width_mm},
                                    std::pair{"specimen thickness", specimen.thickness_mm},
                                    std::pair{"gauge length", specimen.gauge_length_mm}})
    if (!std::isfinite(value) || value <= 0.0)
      throw std::invalid_argument(
          fmt::format("{} must be a finite number > 0 mm, got {}", name, value));
  if (force_n.size() != displacement_mm.size())
    throw std::invalid_argument("forces and displacements must have the same number of points");
  const double area = specimen.width_mm * specimen.thickness_mm;
  std::vector<UniaxialPoint> points;
  for (std::size_t i = 0; i < force_n.size(); ++i)
    points.push_back({1.0 + displacement_mm[i] / specimen.gauge_length_mm, force_n[i] / area});
  return points;
}

std::vector<UniaxialPoint> uniaxial_points_from_table(
    const CsvTable& table, const std::optional<SpecimenGeometry>& specimen) {
  const bool stress_form = table.has("stretch") && table.has("nominal_stress_mpa");
  const bool force_form = table.has("force_n") && table.has("displacement_mm");
  if (!stress_form && !force_form) {
    std::string header;
    for (const auto& c : table.columns) header += (header.empty() ? "" : ",") + c;
    throw CsvError(fmt::format("{}: a uniaxial test needs the columns stretch,nominal_stress_mpa "
                               "or force_n,displacement_mm; the header has: {}",
                               table.source,
                               header),
                   1);
  }
  if (stress_form && force_form)
    throw CsvError(fmt::format("{}: give either stretch,nominal_stress_mpa or "
                               "force_n,displacement_mm, not both",
                               table.source),
                   1);
  std::vector<UniaxialPoint> points;
  if (stress_form) {
    if (specimen)
      throw std::invalid_argument(
          "the specimen's width, thickness and gauge length apply only to force_n,displacement_mm "
          "data; this table already has stretch,nominal_stress_mpa");
    const auto stretch = table.column("stretch");
    const auto stress = table.column("nominal_stress_mpa");
    for (std::size_t i = 0; i < stretch.size(); ++i) points.push_back({stretch[i], stress[i]});
  } else {
    if (!specimen)
      throw std::invalid_argument(
          "force_n,displacement_mm data need the specimen's width, thickness and gauge length");
    points = uniaxial_points(table.column("force_n"), table.column("displacement_mm"), *specimen);
  }
  const auto column = *table.find(stress_form ? "stretch" : "displacement_mm") + 1;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!(points[i].stretch > 0.0) || !std::isfinite(points[i].nominal_stress_mpa))
      throw CsvError(
          fmt::format("{}:{}: column {} ({}): the stretch must be > 0{}",
                      table.source,
                      table.line_numbers[i],
                      column,
                      stress_form ? "stretch" : "displacement_mm",
                      stress_form ? "" : " (the displacement above minus the gauge length)"),
          table.line_numbers[i],
          static_cast<int>(column));
  return points;
}

UniaxialFit fit_uniaxial(const std::vector<UniaxialPoint>& points, FitLaw law,
                         const UniaxialFitOptions& options) {
  const int p = parameter_count(law);
  if (static_cast<int>(points.size()) <= p)
    throw std::invalid_argument(fmt::format(
        "a {} fit has {} parameter{} and needs at least {} points (one more, for the residual's "
        "variance), got {}",
        to_string(law),
        p,
        p == 1 ? "" : "s",
        p + 1,
        points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i].stretch) || points[i].stretch <= 0.0)
      throw std::invalid_argument(fmt::format(
          "point {}: the stretch must be a finite number > 0, got {}", i + 1, points[i].stretch));
    if (!std::isfinite(points[i].nominal_stress_mpa))
      throw std::invalid_argument(
          fmt::format("point {}: the stress must be a finite number", i + 1));
  }
  const Data d = prepare(points);
  if (!(d.g.squaredNorm() > 0.0))
    throw std::invalid_argument("every point is at stretch 1: the data carry no information");
  if (!(d.g.dot(d.stress) > 0.0))
    throw std::invalid_argument(
        "the stresses do not grow with the stretch: no positive shear modulus fits them");

  Residuals functor{d, law};
  Eigen::VectorXd x = start(d, law);
  const auto bounds = validity_bounds(d, law, x[0]);
  for (int i = 0; i < x.size(); ++i)
    x[i] = std::clamp(
        x[i], bounds[static_cast<std::size_t>(i)].lower, bounds[static_cast<std::size_t>(i)].upper);
  const auto solved = least_squares_in_range(functor, bounds, x, options.max_iterations);

  UniaxialFit fit;
  fit.law = law;
  fit.points = static_cast<int>(points.size());
  fit.iterations = solved.iterations;
  if (!solved.converged || !x.allFinite()) {
    fit.status = Status::NoConvergence;
    fit.message = "Levenberg-Marquardt did not converge: " + solved.message;
    return fit;
  }
  fit.status = solved.on_bound ? Status::OnBound : Status::Converged;
  if (solved.on_bound) fit.message = on_bound_message(law, *solved.on_bound, x, bounds);

  Eigen::VectorXd r(d.stress.size());
  functor(x, r);
  Eigen::MatrixXd jac;
  functor.df(x, jac);
  const double ssr = r.squaredNorm();
  const double n = static_cast<double>(points.size());
  fit.rms_residual_mpa = std::sqrt(ssr / n);
  fit.residual_sd_mpa = std::sqrt(ssr / (n - p));
  fit.max_i1_minus_3 = d.k.maxCoeff();
  fit.fitted_stress_mpa.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    fit.fitted_stress_mpa[i] = r[static_cast<Eigen::Index>(i)] + points[i].nominal_stress_mpa;

  const auto cov = covariance(jac, fit.residual_sd_mpa * fit.residual_sd_mpa);
  const auto se = [&](int i) -> std::optional<double> {
    if (!cov) return std::nullopt;
    const double v = (*cov)(i, i);
    if (!(v >= 0.0) || !std::isfinite(v)) return std::nullopt;
    return std::sqrt(v);
  };
  const auto singular_note = std::string(
      "the Jacobian is singular: the data cannot separate the "
      "parameters");

  FittedParameter g{"G", "MPa", x[0], se(0), false, ""};
  g.identifiable = determined(x[0], g.standard_error) && x[0] > 0.0;
  if (!g.standard_error)
    g.note = singular_note;
  else if (!(x[0] > 0.0))
    g.note = "not positive: the law does not describe these data";
  else if (!g.identifiable)
    g.note = "not identifiable: the value is within two standard errors of zero";
  fit.parameters.push_back(g);

  Material material;
  material.shear_modulus_mpa = x[0];
  bool material_valid = x[0] > 0.0;
  switch (law) {
    case FitLaw::NeoHookean:
      material.law = NeoHookean{};
      break;
    case FitLaw::MooneyRivlin: {
      FittedParameter a{"alpha", "", x[1], se(1), false, ""};
      const bool in_range = x[1] >= 0.0 && x[1] < 1.0;
      a.identifiable = determined(x[1], a.standard_error);
      if (!a.standard_error)
        a.note = singular_note;
      else if (!a.identifiable)
        a.note = "not identifiable: within two standard errors of alpha = 0 (neo-Hookean)";
      if (!in_range) {
        a.note += std::string(a.note.empty() ? "" : "; ") +
                  "outside the law's range [0, 1): not a Mooney-Rivlin material the solver "
                  "accepts";
        material_valid = false;
      }
      fit.parameters.push_back(a);
      material.law = MooneyRivlin{x[1]};
      break;
    }
    case FitLaw::Gent: {
      const double c = x[1];
      const auto se_c = se(1);
      fit.inverse_j_lim = c;
      fit.inverse_j_lim_se = se_c;
      fit.stiffening_at_largest_stretch = 1.0 / (1.0 - c * fit.max_i1_minus_3);
      if (se_c && c + 2.0 * *se_c > 0.0) fit.j_lim_lower_bound = 1.0 / (c + 2.0 * *se_c);
      FittedParameter j{"J_lim", "", std::nullopt, std::nullopt, false, ""};
      const auto bound = fit.j_lim_lower_bound
                             ? fmt::format(
                                   "; the data only say J_lim > {:.4g} (two standard "
                                   "errors)",
                                   *fit.j_lim_lower_bound)
                             : std::string();
      const auto reach = fmt::format(
          "the data reach I1 - 3 = {:.4g}, where the fitted stress is {:.3g} % above "
          "neo-Hookean",
          fit.max_i1_minus_3,
          100.0 * (*fit.stiffening_at_largest_stretch - 1.0));
      if (c > 0.0) {
        j.value = 1.0 / c;
        if (se_c) j.standard_error = *se_c / (c * c);  // delta method: se_J / J = se_c / c
        j.identifiable = determined(c, se_c);
        if (!se_c)
          j.note = singular_note;
        else if (!j.identifiable)
          j.note = fmt::format(
              "not identifiable: 1/J_lim = {:.3g} +- {:.3g} is within two standard errors of "
              "neo-Hookean (0); {}{}",
              c,
              *se_c,
              reach,
              bound);
        material.law = Gent{1.0 / c};
      } else {
        j.note = fmt::format(
            "not identifiable: the data show no Gent stiffening (best fit 1/J_lim = {:.3g}{}, "
            "neo-Hookean is 0); {}{}",
            c,
            se_c ? fmt::format(" +- {:.3g}", *se_c) : std::string(),
            reach,
            bound);
        material_valid = false;
      }
      fit.parameters.push_back(j);
      break;
    }
  }
  if (material_valid) fit.material = material;
  return fit;
}

}  // namespace puncture
