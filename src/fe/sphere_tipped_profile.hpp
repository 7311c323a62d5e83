#pragma once
// The sphere-tipped probe's profile (docs/model.md §15): a hemisphere of radius a from the pole,
// polar angle s / a, then its cylinder of the same radius above the equator (s > pi a / 2).
#include <boost/math/constants/constants.hpp>
#include <cmath>

#include "fe/rigid_profile.hpp"

namespace puncture::fe {

class SphereTippedProfile final : public RigidProfile {
 public:
  explicit SphereTippedProfile(double a)
      : a_(a), equator_(0.5 * boost::math::constants::pi<double>() * a) {}

  double radius(double s) const override { return s < equator_ ? a_ * std::sin(s / a_) : a_; }
  double radius_slope(double s) const override { return s < equator_ ? std::cos(s / a_) : 0.0; }
  double radius_curvature(double s) const override {
    return s < equator_ ? -std::sin(s / a_) / a_ : 0.0;
  }
  double height(double s) const override {
    return s < equator_ ? a_ * (1.0 - std::cos(s / a_)) : a_ + (s - equator_);
  }
  double height_slope(double s) const override { return s < equator_ ? std::sin(s / a_) : 1.0; }
  std::vector<double> curvature_breaks() const override { return {equator_}; }
  MembranePart segment_part(int segment) const override {
    return segment == 0 ? MembranePart::Tip : MembranePart::Side;
  }
  // Below the equator the distance to the sphere (centre at height a on the axis), above it to
  // the cylinder.
  double gap(double r, double y) const override {
    return y < a_ ? std::hypot(r, y - a_) - a_ : r - a_;
  }
  double closest_arclength(double r, double y) const override {
    return y < a_ ? a_ * std::atan2(r, a_ - y) : equator_ + (y - a_);
  }

 private:
  double a_;        // sphere and cylinder radius
  double equator_;  // arclength of the equator, pi a / 2
};

}  // namespace puncture::fe
