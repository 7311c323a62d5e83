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
#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "calibration/bounded_least_squares.hpp"
#include "calibration/law_fit_model.hpp"
#include "puncture/calibration.hpp"

namespace puncture {

namespace {

using detail::Bound;
using detail::covariance;
using detail::least_squares_in_range;
using detail::on_bound;

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

// The closed-form laws' parameters; LawFitModel's for the others (Ogden: 2 per term).
int parameter_count(FitLaw law) {
  switch (law) {
    case FitLaw::NeoHookean:
      return 1;
    case FitLaw::Yeoh:
    case FitLaw::GentGent:
      return 3;
    case FitLaw::Ogden:  // 2 N, counted by the caller
    default:
      return 2;
  }
}

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
      default:  // the other laws are LawFitModel's
        return false;
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
      default:
        break;
    }
  }
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

// More than two standard errors from zero.
bool determined(double value, const std::optional<double>& se) {
  return se && 2.0 * *se < std::abs(value);
}

int ogden_term_count(const UniaxialFitOptions& options) {
  return options.ogden_alpha_start.empty() ? options.ogden_terms
                                           : static_cast<int>(options.ogden_alpha_start.size());
}

// The correlations of the reported parameters (a reciprocal one turns the sign of its row and
// column) and the information criteria (none for an exact fit).
void add_statistics(UniaxialFit& fit, const Eigen::MatrixXd& jac,
                    const std::optional<Eigen::MatrixXd>& cov, const std::vector<bool>& reciprocal,
                    double ssr) {
  const auto p = jac.cols();
  if (cov && (cov->diagonal().array() > 0.0).all() && cov->allFinite()) {
    fit.correlation.assign(static_cast<std::size_t>(p),
                           std::vector<double>(static_cast<std::size_t>(p)));
    for (Eigen::Index i = 0; i < p; ++i)
      for (Eigen::Index j = 0; j < p; ++j) {
        const double sign = (reciprocal[static_cast<std::size_t>(i)] ? -1.0 : 1.0) *
                            (reciprocal[static_cast<std::size_t>(j)] ? -1.0 : 1.0);
        fit.correlation[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
            i == j ? 1.0 : sign * (*cov)(i, j) / std::sqrt((*cov)(i, i) * (*cov)(j, j));
      }
  }
  if (std::isfinite(ssr) && ssr > 0.0)
    fit.information = information_criteria(fit.points, static_cast<int>(p), ssr);
}

// Why the best fit on a bound of LawFitModel's range says the law does not describe the data
// inside it.
std::string law_model_bound_message(FitLaw law, const detail::LawFitModel& model, int index,
                                    const Eigen::VectorXd& x) {
  const auto& b = model.bounds()[static_cast<std::size_t>(index)];
  const bool lower = x[index] - b.lower <= b.upper - x[index];
  const auto& name = model.names()[static_cast<std::size_t>(index)];
  const auto where =
      fmt::format("the best {} fit lies on a bound of the law's validity range: ", to_string(law));
  if (model.reciprocal()[static_cast<std::size_t>(index)])
    return where + (lower ? fmt::format("1/{} = 0, the neo-Hookean limit: the data show no "
                                        "stiffening this law can describe (fit neo-hookean)",
                                        name)
                          : fmt::format("1/{} = {:.4g}, where the data's largest stretch locks "
                                        "the law: they stiffen faster than it can",
                                        name,
                                        x[index]));
  return where + fmt::format("{} = {:.4g}{}{}, the {} end of its range",
                             name,
                             x[index],
                             model.units()[static_cast<std::size_t>(index)].empty() ? "" : " ",
                             model.units()[static_cast<std::size_t>(index)],
                             lower ? "lower" : "upper");
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
    case FitLaw::Yeoh:
      return "yeoh";
    case FitLaw::Ogden:
      return "ogden";
    case FitLaw::ArrudaBoyce:
      return "arruda-boyce";
    case FitLaw::GentGent:
      return "gent-gent";
  }
  return "gent";
}

std::string to_string(StressTest test) {
  return test == StressTest::Uniaxial ? "uniaxial" : "equibiaxial";
}

std::vector<FitLaw> all_fit_laws() {
  return {FitLaw::Gent,
          FitLaw::NeoHookean,
          FitLaw::MooneyRivlin,
          FitLaw::Yeoh,
          FitLaw::Ogden,
          FitLaw::ArrudaBoyce,
          FitLaw::GentGent};
}

FitLaw fit_law_of(const std::string& name) {
  std::string names;
  for (const auto law : all_fit_laws()) {
    if (to_string(law) == name) return law;
    names += (names.empty() ? "" : ", ") + to_string(law);
  }
  throw InvalidInput("law", fmt::format("unknown law '{}'; the laws are {}", name, names));
}

InformationCriteria information_criteria(int points, int law_parameters, double rss_mpa2) {
  if (points < 1 || law_parameters < 0)
    throw std::invalid_argument(fmt::format(
        "information criteria need n >= 1 points and p >= 0 parameters, got n = {}, p = {}",
        points,
        law_parameters));
  if (!std::isfinite(rss_mpa2) || !(rss_mpa2 > 0.0))
    throw std::invalid_argument(fmt::format(
        "information criteria need a sum of squared residuals > 0 (ln 0 for an exact fit), got {}",
        rss_mpa2));
  InformationCriteria c;
  c.points = points;
  c.parameters = law_parameters + 1;  // and the variance
  c.rss_mpa2 = rss_mpa2;
  const double n = points, k = c.parameters;
  const double fit_term = n * std::log(rss_mpa2 / n);
  c.aic = fit_term + 2.0 * k;
  if (n - k - 1.0 > 0.0) c.aicc = c.aic + 2.0 * k * (k + 1.0) / (n - k - 1.0);
  c.bic = fit_term + k * std::log(n);
  return c;
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

namespace {

// The laws with closed-form stresses and Jacobians in a uniaxial test (Residuals above).
UniaxialFit fit_closed_form(const std::vector<UniaxialPoint>& points, FitLaw law,
                            const UniaxialFitOptions& options) {
  const int p = parameter_count(law);
  const Data d = prepare(points);
  Residuals functor{d, law};
  Eigen::VectorXd x = start(d, law);
  const auto bounds = validity_bounds(d, law, x[0]);
  for (int i = 0; i < x.size(); ++i)
    x[i] = std::clamp(
        x[i], bounds[static_cast<std::size_t>(i)].lower, bounds[static_cast<std::size_t>(i)].upper);
  const auto solved = least_squares_in_range(functor, bounds, x, options.max_iterations);

  UniaxialFit fit;
  fit.law = law;
  fit.test = StressTest::Uniaxial;
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
    default:
      break;
  }
  if (material_valid) fit.material = material;
  add_statistics(fit, jac, cov, {false, law == FitLaw::Gent}, ssr);
  return fit;
}

// Any law through LawFitModel: the library's stresses and a difference Jacobian.
UniaxialFit fit_law_model(const std::vector<UniaxialPoint>& points, FitLaw law,
                          const UniaxialFitOptions& options) {
  const detail::LawFitModel model(law, points, options);
  const detail::LawResiduals functor(model, points);
  // From each start; the lowest cost of the runs that converge (the first start's run when
  // none does).
  Eigen::VectorXd x;
  detail::LeastSquares solved;
  double best_cost = std::numeric_limits<double>::infinity();
  int iterations = 0;
  for (const auto& start : model.starts()) {
    Eigen::VectorXd xs = start;
    auto run =
        detail::least_squares_with_active_set(functor, model.bounds(), xs, options.max_iterations);
    iterations += run.iterations;
    Eigen::VectorXd rs(functor.values());
    const double cost = run.converged && xs.allFinite() && functor(xs, rs)
                            ? rs.squaredNorm()
                            : std::numeric_limits<double>::infinity();
    if (x.size() == 0 || cost < best_cost) {
      x = xs;
      solved = run;
      best_cost = cost;
    }
  }
  solved.iterations = iterations;

  UniaxialFit fit;
  fit.law = law;
  fit.test = options.test;
  fit.points = static_cast<int>(points.size());
  fit.iterations = solved.iterations;
  Eigen::VectorXd r(functor.values());
  if (!solved.converged || !x.allFinite() || !functor(x, r)) {
    fit.status = Status::NoConvergence;
    fit.message = "Levenberg-Marquardt did not converge: " + solved.message;
    return fit;
  }
  fit.status = solved.on_bound ? Status::OnBound : Status::Converged;
  if (solved.on_bound) fit.message = law_model_bound_message(law, model, *solved.on_bound, x);
  Eigen::MatrixXd jac;
  functor.df(x, jac);
  const double ssr = r.squaredNorm();
  const double n = static_cast<double>(points.size());
  const int p = model.size();
  fit.rms_residual_mpa = std::sqrt(ssr / n);
  fit.residual_sd_mpa = std::sqrt(ssr / (n - p));
  for (const auto& point : points)
    fit.max_i1_minus_3 =
        std::max(fit.max_i1_minus_3,
                 options.test == StressTest::Uniaxial
                     ? point.stretch * point.stretch + 2.0 / point.stretch - 3.0
                     : 2.0 * point.stretch * point.stretch + std::pow(point.stretch, -4.0) - 3.0);
  fit.fitted_stress_mpa.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    fit.fitted_stress_mpa[i] = r[static_cast<Eigen::Index>(i)] + points[i].nominal_stress_mpa;

  // The covariance of the parameters free at the optimum (those held on a bound have none: a
  // held Ogden mu_p = 0 also leaves its alpha_p without effect, a zero column).
  std::vector<Eigen::Index> free;
  for (int i = 0; i < p; ++i)
    if (std::find(solved.held.begin(), solved.held.end(), i) == solved.held.end())
      free.push_back(i);
  std::optional<Eigen::MatrixXd> cov;
  if (!free.empty()) {
    Eigen::MatrixXd jac_free(jac.rows(), static_cast<Eigen::Index>(free.size()));
    for (std::size_t k = 0; k < free.size(); ++k)
      jac_free.col(static_cast<Eigen::Index>(k)) = jac.col(free[k]);
    if (const auto c = covariance(jac_free, fit.residual_sd_mpa * fit.residual_sd_mpa)) {
      cov = Eigen::MatrixXd::Constant(p, p, std::numeric_limits<double>::quiet_NaN());
      for (std::size_t a = 0; a < free.size(); ++a)
        for (std::size_t b = 0; b < free.size(); ++b)
          (*cov)(free[a], free[b]) =
              (*c)(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
    }
  }
  for (int i = 0; i < p; ++i) {
    const auto name = model.names()[static_cast<std::size_t>(i)];
    const bool held = std::find(solved.held.begin(), solved.held.end(), i) != solved.held.end();
    FittedParameter fp{
        name, model.units()[static_cast<std::size_t>(i)], x[i], std::nullopt, false, ""};
    std::optional<double> se;
    if (cov && (*cov)(i, i) >= 0.0 && std::isfinite((*cov)(i, i))) se = std::sqrt((*cov)(i, i));
    const bool reciprocal = model.reciprocal()[static_cast<std::size_t>(i)];
    fp.identifiable = determined(x[i], se);
    if (reciprocal) {
      // Fitted as c = 1/value: the value exists for c > 0, its error by the delta method.
      if (x[i] > 0.0) {
        fp.value = 1.0 / x[i];
        if (se) fp.standard_error = *se / (x[i] * x[i]);
      } else {
        fp.value = std::nullopt;
      }
      if (!fp.identifiable)
        fp.note = fmt::format(
            "not identifiable: 1/{} = {:.3g}{} is within two standard errors of the neo-Hookean "
            "limit 0",
            name,
            x[i],
            se ? fmt::format(" +- {:.3g}", *se) : std::string());
    } else {
      fp.standard_error = se;
      if (!fp.identifiable)
        fp.note = se ? "not identifiable: the value is within two standard errors of zero"
                     : "the Jacobian is singular: the data cannot separate the parameters";
    }
    if (held) fp.note = "held on its bound at the optimum (no standard error): see the message";
    if (law == FitLaw::Gent && i == 1) {
      fit.inverse_j_lim = x[1];
      fit.inverse_j_lim_se = se;
      if (se && x[1] + 2.0 * *se > 0.0) fit.j_lim_lower_bound = 1.0 / (x[1] + 2.0 * *se);
    }
    fit.parameters.push_back(fp);
  }
  fit.material = model.material(x);
  add_statistics(fit, jac, cov, model.reciprocal(), ssr);
  return fit;
}

}  // namespace

UniaxialFit fit_uniaxial(const std::vector<UniaxialPoint>& points, FitLaw law,
                         const UniaxialFitOptions& options) {
  const int p = law == FitLaw::Ogden ? 2 * ogden_term_count(options) : parameter_count(law);
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
  if (options.max_iterations < 1)
    throw std::invalid_argument(
        fmt::format("max_iterations must be >= 1, got {}", options.max_iterations));
  const Data d = prepare(points);
  if (!(d.g.squaredNorm() > 0.0))
    throw std::invalid_argument("every point is at stretch 1: the data carry no information");
  if (!(d.g.dot(d.stress) > 0.0))
    throw std::invalid_argument(
        "the stresses do not grow with the stretch: no positive shear modulus fits them");
  const bool closed_form =
      options.test == StressTest::Uniaxial &&
      (law == FitLaw::Gent || law == FitLaw::NeoHookean || law == FitLaw::MooneyRivlin);
  return closed_form ? fit_closed_form(points, law, options) : fit_law_model(points, law, options);
}

std::vector<UniaxialFit> compare_uniaxial_fits(const std::vector<UniaxialPoint>& data,
                                               const std::vector<FitLaw>& laws,
                                               const UniaxialFitOptions& options) {
  if (laws.empty()) throw std::invalid_argument("laws: give at least one law to compare");
  std::vector<UniaxialFit> fits;
  for (const auto law : laws) fits.push_back(fit_uniaxial(data, law, options));
  // A converged or on-bound fit with an AIC first, by AIC; the rest keep their order.
  std::stable_sort(fits.begin(), fits.end(), [](const UniaxialFit& a, const UniaxialFit& b) {
    const bool ra = a.information && a.status != Status::NoConvergence;
    const bool rb = b.information && b.status != Status::NoConvergence;
    if (ra != rb) return ra;
    return ra && a.information->aic < b.information->aic;
  });
  return fits;
}

}  // namespace puncture
