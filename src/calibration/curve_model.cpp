#include "calibration/curve_model.hpp"

#include <fmt/format.h>

#include <exception>

#include "puncture/loading_curve.hpp"

namespace puncture::detail {

namespace {

// A threshold in N or N/mm does not scale with G: the normalised curve's switch moves with it.
// Nor does a gas pressure, held or sealed.
bool force_scales_with_g(const Problem& p) {
  return p.preload.pressure_mpa == 0.0 && !p.preload.gas_volume_mm3 &&
         p.stick.rule != StickRule::Force && p.stick.rule != StickRule::EdgeTension;
}

}  // namespace

CurveModel::CurveModel(const CurveTest& test, int test_index, std::vector<FreeColumn> columns,
                       const SolverOptions& solver, bool needs_puncture)
    : test_(test),
      test_index_(test_index),
      columns_(std::move(columns)),
      solver_(solver),
      needs_puncture_(needs_puncture),
      scales_with_g_(force_scales_with_g(test.problem)) {
  solver_.record_fields = false;
}

bool CurveModel::depends_on(std::size_t column) const {
  return columns_[column].test < 0 || columns_[column].test == test_index_;
}

Problem CurveModel::problem_at(const double* x) const {
  Problem p = test_.problem;
  for (std::size_t i = 0; i < columns_.size(); ++i)
    if (columns_[i].test < 0) set_value(columns_[i].parameter, p, x[i]);
  return p;
}

double CurveModel::contact_offset_at(const double* x) const {
  for (std::size_t i = 0; i < columns_.size(); ++i)
    if (columns_[i].test == test_index_ && columns_[i].parameter == CurveParameter::ContactOffset)
      return x[i];
  return test_.contact_offset_mm;
}

CurveModel::Normalised CurveModel::solve(const double* x) const {
  Normalised out;
  try {
    const Problem p = problem_at(x);
    const double offset = contact_offset_at(x);
    // The model's depths: equal depths (a machine's resolution) share one solve, the curve
    // needs increasing depths > 0; a point at a model depth <= 0 is before contact.
    std::vector<double> unique_depths;
    std::vector<long> point_to_unique;
    for (const double measured : test_.depth_mm) {
      const double d = measured - offset;
      if (!(d > 0.0)) {
        point_to_unique.push_back(-1);
        continue;
      }
      if (unique_depths.empty() || d > unique_depths.back()) unique_depths.push_back(d);
      point_to_unique.push_back(static_cast<long>(unique_depths.size()) - 1);
    }
    const double g = scales_with_g_ ? p.material.shear_modulus_mpa : 1.0;
    std::vector<double> at_depth(unique_depths.size());
    if (!unique_depths.empty() || needs_puncture_) {
      CurveOptions curve;
      curve.depths_mm = unique_depths;
      curve.locate_events = false;  // the fit reads the forces alone
      if (curve.depths_mm.empty()) curve.depths_mm = {test_.depth_mm.back()};
      ++solves_;
      const LoadingCurve lc = loading_curve(p, curve, solver_);
      if (!lc.ok()) {
        out.message = fmt::format("{}: {}", to_string(lc.status), lc.message);
        return out;
      }
      // The curve's points: one per depth, and at a stick -> slip switch two at its depth
      // (held, then sliding); a measured depth there takes the last, the sliding state.
      std::size_t k = 0;
      for (const auto& pt : lc.points) {
        while (k < unique_depths.size() && unique_depths[k] < pt.depth_mm) ++k;
        if (k < unique_depths.size() && unique_depths[k] == pt.depth_mm)
          at_depth[k] = pt.force_n / g;
      }
      if (lc.puncture.ok()) {
        out.puncture_force = lc.puncture.force_n / g;
        out.puncture_depth_mm = lc.puncture.depth_mm;
      } else if (needs_puncture_) {
        out.message = fmt::format("no puncture: {}", lc.puncture.message);
        return out;
      }
    }
    out.force.reserve(point_to_unique.size());
    for (const long u : point_to_unique)
      out.force.push_back(u < 0 ? 0.0 : at_depth[static_cast<std::size_t>(u)]);
    out.ok = true;
  } catch (const std::exception& e) {  // parameters the problem does not accept
    out.message = e.what();
  }
  return out;
}

ModelCurve CurveModel::evaluate(const double* x) const {
  std::vector<double> key(x, x + columns_.size());
  double g = test_.problem.material.shear_modulus_mpa;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (!depends_on(i)) key[i] = 0.0;  // another test's offset
    if (scales_with_g_ && columns_[i].parameter == CurveParameter::ShearModulus) {
      g = x[i];
      key[i] = 0.0;  // the normalised curve does not depend on it
    }
  }
  auto it = cache_.find(key);
  if (it == cache_.end()) {
    if (cache_.size() > 256) cache_.clear();
    it = cache_.emplace(key, solve(x)).first;
  }
  const Normalised& n = it->second;
  ModelCurve out;
  out.ok = n.ok;
  out.message = n.message;
  if (!n.ok) return out;
  const double scale = scales_with_g_ ? g : 1.0;
  out.force_n.reserve(n.force.size());
  for (const double f : n.force) out.force_n.push_back(f * scale);
  if (n.puncture_force) out.puncture_force_n = *n.puncture_force * scale;
  if (n.puncture_depth_mm) out.puncture_depth_mm = *n.puncture_depth_mm + contact_offset_at(x);
  return out;
}

}  // namespace puncture::detail
