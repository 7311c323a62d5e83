#include "calibration/curve_model.hpp"

#include <fmt/format.h>

#include <exception>

#include "puncture/loading_curve.hpp"

namespace puncture::detail {

CurveModel::CurveModel(const CurveTest& test, std::vector<CurveParameter> free,
                       const SolverOptions& solver, bool needs_puncture)
    : test_(test),
      free_(std::move(free)),
      solver_(solver),
      needs_puncture_(needs_puncture),
      scales_with_g_(test.problem.preload.pressure_mpa == 0.0 &&
                     !test.problem.preload.gas_volume_mm3) {
  solver_.record_fields = false;
  // Equal depths (a machine's resolution) share one solve: the curve needs increasing depths.
  for (const double d : test.depth_mm) {
    if (unique_depths_.empty() || d > unique_depths_.back()) unique_depths_.push_back(d);
    point_to_unique_.push_back(unique_depths_.size() - 1);
  }
}

Problem CurveModel::problem_at(const double* x) const {
  Problem p = test_.problem;
  for (std::size_t i = 0; i < free_.size(); ++i) set_value(free_[i], p, x[i]);
  return p;
}

CurveModel::Normalised CurveModel::solve(const double* x) const {
  Normalised out;
  try {
    const Problem p = problem_at(x);
    CurveOptions curve;
    curve.depths_mm = unique_depths_;
    ++solves_;
    const LoadingCurve lc = loading_curve(p, curve, solver_);
    if (!lc.ok()) {
      out.message = fmt::format("{}: {}", to_string(lc.status), lc.message);
      return out;
    }
    const double g = scales_with_g_ ? p.material.shear_modulus_mpa : 1.0;
    // The curve's points: one per depth, and at a stick -> slip switch two at its depth (held,
    // then sliding); a measured depth there takes the last, the sliding state.
    std::vector<double> at_depth(unique_depths_.size());
    std::size_t k = 0;
    for (const auto& pt : lc.points) {
      while (k < unique_depths_.size() && unique_depths_[k] < pt.depth_mm) ++k;
      if (k < unique_depths_.size() && unique_depths_[k] == pt.depth_mm)
        at_depth[k] = pt.force_n / g;
    }
    out.force.reserve(point_to_unique_.size());
    for (const auto u : point_to_unique_) out.force.push_back(at_depth[u]);
    if (lc.puncture.ok()) {
      out.puncture_force = lc.puncture.force_n / g;
      out.puncture_depth_mm = lc.puncture.depth_mm;
    } else if (needs_puncture_) {
      out.message = fmt::format("no puncture: {}", lc.puncture.message);
      return out;
    }
    out.ok = true;
  } catch (const std::exception& e) {  // parameters the problem does not accept
    out.message = e.what();
  }
  return out;
}

ModelCurve CurveModel::evaluate(const double* x) const {
  std::vector<double> key(x, x + free_.size());
  double g = test_.problem.material.shear_modulus_mpa;
  if (scales_with_g_)
    for (std::size_t i = 0; i < free_.size(); ++i)
      if (free_[i] == CurveParameter::ShearModulus) {
        g = x[i];
        key[i] = 0.0;  // the normalised curve does not depend on it
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
  out.puncture_depth_mm = n.puncture_depth_mm;
  return out;
}

}  // namespace puncture::detail
