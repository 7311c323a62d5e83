#include "calibration/law_fit_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "mechanics/membrane_validation.hpp"

namespace puncture::detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double test_stress(StressTest test, const MaterialLaw& law, double l) {
  return test == StressTest::Uniaxial ? uniaxial_stress(law, l) : equibiaxial_stress(law, l);
}

double first_invariant_of(StressTest test, double l) {
  return test == StressTest::Uniaxial ? l * l + 2.0 / l : 2.0 * l * l + 1.0 / (l * l * l * l);
}

// Least squares of P against the columns of `basis`: the starting values of parameters the
// stress is linear in.
Eigen::VectorXd linear_fit(const Eigen::MatrixXd& basis, const std::vector<UniaxialPoint>& data) {
  Eigen::VectorXd p(static_cast<Eigen::Index>(data.size()));
  for (std::size_t i = 0; i < data.size(); ++i)
    p[static_cast<Eigen::Index>(i)] = data[i].nominal_stress_mpa;
  return basis.colPivHouseholderQr().solve(p);
}

// The least squares of P against the columns of `basis` with each coefficient of the sign of
// its exponent (mu_p alpha_p > 0) over every subset of terms whose unconstrained solution has
// those signs (at most 2^3 - 1 = 7), the others 0: every such solution, the best first.
std::vector<Eigen::VectorXd> sign_constrained_fits(const Eigen::MatrixXd& basis,
                                                   const std::vector<UniaxialPoint>& data,
                                                   const std::vector<double>& alpha) {
  const auto terms = basis.cols();
  Eigen::VectorXd p(static_cast<Eigen::Index>(data.size()));
  for (std::size_t i = 0; i < data.size(); ++i)
    p[static_cast<Eigen::Index>(i)] = data[i].nominal_stress_mpa;
  std::vector<std::pair<double, Eigen::VectorXd>> fits;
  for (int mask = 1; mask < (1 << terms); ++mask) {
    std::vector<Eigen::Index> in;
    for (Eigen::Index t = 0; t < terms; ++t)
      if (mask & (1 << t)) in.push_back(t);
    Eigen::MatrixXd a(basis.rows(), static_cast<Eigen::Index>(in.size()));
    for (std::size_t k = 0; k < in.size(); ++k)
      a.col(static_cast<Eigen::Index>(k)) = basis.col(in[k]);
    const Eigen::VectorXd c = a.colPivHouseholderQr().solve(p);
    bool feasible = c.allFinite();
    for (std::size_t k = 0; k < in.size() && feasible; ++k)
      feasible = c[static_cast<Eigen::Index>(k)] * alpha[static_cast<std::size_t>(in[k])] > 0.0;
    if (!feasible) continue;
    Eigen::VectorXd mu = Eigen::VectorXd::Zero(terms);
    for (std::size_t k = 0; k < in.size(); ++k) mu[in[k]] = c[static_cast<Eigen::Index>(k)];
    fits.emplace_back((a * c - p).squaredNorm(), mu);
  }
  std::stable_sort(
      fits.begin(), fits.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Eigen::VectorXd> out;
  for (auto& f : fits) out.push_back(std::move(f.second));
  if (out.empty()) out.push_back(Eigen::VectorXd::Zero(terms));
  return out;
}

std::vector<double> ogden_start_exponents(const UniaxialFitOptions& options) {
  if (!options.ogden_alpha_start.empty()) return options.ogden_alpha_start;
  switch (options.ogden_terms) {
    case 1:
      return {2.0};  // neo-Hookean
    case 2:
      return {3.0, -2.0};
    case 3:
      return {1.3, 5.0, -2.0};  // Ogden's (1972) exponents for Treloar's rubber
    default:
      throw std::invalid_argument(fmt::format(
          "ogden_terms: Ogden takes 1 to 3 terms (mu_p, alpha_p), got {}", options.ogden_terms));
  }
}

}  // namespace

LawFitModel::LawFitModel(FitLaw law, const std::vector<UniaxialPoint>& data,
                         const UniaxialFitOptions& options)
    : law_(law), test_(options.test) {
  const auto n = static_cast<Eigen::Index>(data.size());
  double k_max = 0.0;
  Eigen::MatrixXd neo(n, 1);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double l = data[static_cast<std::size_t>(i)].stretch;
    neo(i, 0) = test_stress(test_, NeoHookean{}, l);
    k_max = std::max(k_max, first_invariant_of(test_, l) - 3.0);
  }
  const double g_nh = linear_fit(neo, data)[0];
  const double g_scale = std::isfinite(g_nh) && g_nh > 0.0 ? g_nh : 1.0;
  // G > 0: a floor far below any modulus the data could give (the stress scale's 1e-12).
  const Bound modulus{1e-12 * g_scale, kInf, g_scale};
  // c = 1/J_lim below 1/(I1 - 3) of the largest stretch, where the data would lock.
  const double c_lock = k_max > 0.0 ? 1.0 / k_max : kInf;
  const Bound inverse_j_lim{0.0, (1.0 - 1e-6) * c_lock, std::isfinite(c_lock) ? c_lock : 1.0};
  const auto add =
      [&](std::string name, std::string unit, Bound bound, double value, bool reciprocal = false) {
        names_.push_back(std::move(name));
        units_.push_back(std::move(unit));
        bounds_.push_back(bound);
        reciprocal_.push_back(reciprocal);
        start_.conservativeResize(start_.size() + 1);
        start_[start_.size() - 1] = std::clamp(value, bound.lower, bound.upper);
      };
  switch (law) {
    case FitLaw::NeoHookean:
      add("G", "MPa", modulus, g_scale);
      break;
    case FitLaw::MooneyRivlin:
      add("G", "MPa", modulus, g_scale);
      add("alpha", "", {0.0, 1.0, 1.0}, 0.1);
      break;
    case FitLaw::Gent:
      add("G", "MPa", modulus, g_scale);
      add("J_lim", "", inverse_j_lim, 0.25 * inverse_j_lim.upper, true);
      break;
    case FitLaw::GentGent:
      add("G", "MPa", modulus, g_scale);
      add("J_lim", "", inverse_j_lim, 0.25 * inverse_j_lim.upper, true);
      add("beta", "", {0.0, 1.0, 1.0}, 0.05);
      break;
    case FitLaw::ArrudaBoyce: {
      // N > 1 and 3 N above the largest I1: 1/N < min(1, 3 / I1).
      const double n_lock = std::min(1.0, 3.0 / (3.0 + k_max));
      add("G", "MPa", modulus, g_scale);
      add("N", "", {0.0, (1.0 - 1e-6) * n_lock, n_lock}, 0.25 * n_lock, true);
      break;
    }
    case FitLaw::Yeoh: {
      // P = 2 C10 s_nh (1 + 2 (C20/C10) x + 3 (C30/C10) x^2): linear in C10, C20, C30.
      Eigen::MatrixXd basis(n, 3);
      for (Eigen::Index i = 0; i < n; ++i) {
        const double l = data[static_cast<std::size_t>(i)].stretch;
        const double x = first_invariant_of(test_, l) - 3.0;
        basis(i, 0) = 2.0 * neo(i, 0);
        basis(i, 1) = 4.0 * x * neo(i, 0);
        basis(i, 2) = 6.0 * x * x * neo(i, 0);
      }
      Eigen::VectorXd c = linear_fit(basis, data);
      if (!c.allFinite() || !(c[0] > 0.0)) c = Eigen::Vector3d(0.5 * g_scale, 0.0, 0.0);
      add("C10", "MPa", {0.5e-12 * g_scale, kInf, 0.5 * g_scale}, c[0]);
      add("C20", "MPa", {0.0, kInf, 0.5 * g_scale}, std::max(c[1], 0.0));
      add("C30", "MPa", {0.0, kInf, 0.5 * g_scale}, std::max(c[2], 0.0));
      break;
    }
    case FitLaw::Ogden: {
      const auto alpha = ogden_start_exponents(options);
      if (alpha.empty() || alpha.size() > 3)
        throw std::invalid_argument(fmt::format(
            "ogden_alpha_start: Ogden takes 1 to 3 terms (mu_p, alpha_p), got {} exponents",
            alpha.size()));
      for (const double a : alpha)
        if (!std::isfinite(a) || !(std::abs(a) >= 1.0))
          throw std::invalid_argument(fmt::format(
              "ogden_alpha_start: each exponent must be a finite number with |alpha| >= 1 (the "
              "law's condition), got {}",
              a));
      ogden_terms_ = static_cast<int>(alpha.size());
      // The mu_p at the starting exponents: linear least squares, then each on its side.
      Eigen::MatrixXd basis(n, ogden_terms_);
      for (int p = 0; p < ogden_terms_; ++p) {
        Ogden unit{std::vector<double>(alpha.size(), 0.0), alpha};
        unit.mu[static_cast<std::size_t>(p)] = 1.0;
        for (Eigen::Index i = 0; i < n; ++i)
          basis(i, p) = test_stress(test_, unit, data[static_cast<std::size_t>(i)].stretch);
      }
      const auto mus = sign_constrained_fits(basis, data, alpha);
      // A term a start leaves out begins just inside its range: at mu_p = 0 its exponent would
      // have no effect on the stress and no derivative.
      const auto inside = [&](const Eigen::VectorXd& mu, int p) {
        const double a = alpha[static_cast<std::size_t>(p)];
        const double side = a > 0.0 ? 1.0 : -1.0;
        return mu[p] * side > 0.0 ? mu[p] : side * 1e-3 * g_scale / std::abs(a);
      };
      for (int p = 0; p < ogden_terms_; ++p) {
        const double a = alpha[static_cast<std::size_t>(p)];
        add(fmt::format("mu_{}", p + 1),
            "MPa",
            a > 0.0 ? Bound{0.0, kInf, g_scale} : Bound{-kInf, 0.0, g_scale},
            inside(mus.front(), p));
      }
      for (int p = 0; p < ogden_terms_; ++p) {
        const double a = alpha[static_cast<std::size_t>(p)];
        add(fmt::format("alpha_{}", p + 1),
            "",
            a > 0.0 ? Bound{1.0, kInf, 1.0} : Bound{-kInf, -1.0, 1.0},
            a);
      }
      for (const auto& mu : mus) {
        Eigen::VectorXd x = start_;
        for (int p = 0; p < ogden_terms_; ++p) x[p] = inside(mu, p);
        starts_.push_back(x);
      }
      return;
    }
  }
  starts_.push_back(start_);
}

bool LawFitModel::law_at(const Eigen::VectorXd& x, MaterialLaw& law, double& scale_mpa) const {
  scale_mpa = x[0];
  switch (law_) {
    case FitLaw::NeoHookean:
      law = NeoHookean{};
      return true;
    case FitLaw::MooneyRivlin:
      law = MooneyRivlin{x[1]};
      return true;
    case FitLaw::Gent:
      if (x[1] > 0.0)
        law = Gent{1.0 / x[1]};
      else
        law = NeoHookean{};  // the c -> 0 limit
      return true;
    case FitLaw::GentGent:
      law = GentGent{x[1] > 0.0 ? 1.0 / x[1] : kInf, x[2]};
      return true;
    case FitLaw::ArrudaBoyce:
      if (x[1] > 0.0)
        law = ArrudaBoyce{1.0 / x[1]};
      else
        law = NeoHookean{};  // the N -> infinity limit
      return true;
    case FitLaw::Yeoh:
      scale_mpa = 2.0 * x[0];  // G = 2 C10
      law = Yeoh{x[1] / scale_mpa, x[2] / scale_mpa};
      return scale_mpa > 0.0;
    case FitLaw::Ogden: {
      Ogden ogden;
      ogden.mu.assign(x.data(), x.data() + ogden_terms_);
      ogden.alpha.assign(x.data() + ogden_terms_, x.data() + 2 * ogden_terms_);
      law = std::move(ogden);
      scale_mpa = 1.0;  // mu_p in MPa
      return true;
    }
  }
  return false;
}

double LawFitModel::stress(const MaterialLaw& law, double scale_mpa, double l) const {
  return scale_mpa * test_stress(test_, law, l);
}

std::optional<Material> LawFitModel::material(const Eigen::VectorXd& x) const {
  Material m;
  switch (law_) {
    case FitLaw::Ogden:
      try {
        m = ogden_material(std::vector<double>(x.data(), x.data() + ogden_terms_),
                           std::vector<double>(x.data() + ogden_terms_, x.data() + x.size()));
      } catch (const std::invalid_argument&) {
        return std::nullopt;
      }
      break;
    case FitLaw::Gent:
    case FitLaw::GentGent:
    case FitLaw::ArrudaBoyce:
      if (!(x[1] > 0.0)) return std::nullopt;  // no J_lim or N: the neo-Hookean limit
      [[fallthrough]];
    default:
      if (!law_at(x, m.law, m.shear_modulus_mpa)) return std::nullopt;
  }
  std::vector<ValidationError> errors;
  append_material_errors(errors, m);
  if (!errors.empty()) return std::nullopt;
  return m;
}

bool LawResiduals::operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
  MaterialLaw law;
  double scale = 0.0;
  if (!model_.law_at(x, law, scale)) return false;
  r.resize(values());
  for (std::size_t i = 0; i < data_.size(); ++i) {
    const double p = model_.stress(law, scale, data_[i].stretch);
    if (!std::isfinite(p)) return false;
    r[static_cast<Eigen::Index>(i)] = p - data_[i].nominal_stress_mpa;
  }
  return true;
}

void LawResiduals::df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) const {
  jac.setZero(values(), inputs());
  Eigen::VectorXd xp = x, r1(values()), r2(values()), r3(values()), r4(values());
  const auto at = [&](int j, double value, Eigen::VectorXd& r) {
    xp = x;
    xp[j] = value;
    return (*this)(xp, r);
  };
  for (int j = 0; j < inputs(); ++j) {
    const auto& b = model_.bounds()[static_cast<std::size_t>(j)];
    const double h = 1e-3 * std::max(std::abs(x[j]), 1e-3 * b.scale);
    const bool room_up = x[j] + h <= b.upper, room_down = x[j] - h >= b.lower;
    if (room_up && room_down && at(j, x[j] + h, r1) && at(j, x[j] - h, r2) &&
        at(j, x[j] + 0.5 * h, r3) && at(j, x[j] - 0.5 * h, r4)) {
      // Richardson: (4 D(h/2) - D(h)) / 3, D(h) = (r(x + h) - r(x - h)) / (2 h).
      jac.col(j) = (4.0 * (r3 - r4) / h - (r1 - r2) / (2.0 * h)) / 3.0;
      continue;
    }
    // One-sided, second order: (-3 r(x) + 4 r(x + s) - r(x + 2 s)) / (2 s), s = +-h/10.
    const double s = (room_up ? 1.0 : -1.0) * 0.1 * h;
    Eigen::VectorXd r0(values());
    if ((*this)(x, r0) && at(j, x[j] + s, r1) && at(j, x[j] + 2.0 * s, r2))
      jac.col(j) = (-3.0 * r0 + 4.0 * r1 - r2) / (2.0 * s);
  }
}

}  // namespace puncture::detail
