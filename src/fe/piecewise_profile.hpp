#pragma once
// A probe's profile made of pieces of constant curvature (straight lines and circular arcs)
// joined end to end, parameterised by the arclength from the pole: the filleted flat punch
// (face, fillet, side), the cone (tip sphere, cone, shank) and the ball (sphere, then the rod
// above it).  Along a piece the tangent's angle to the clamp plane is phi(s) = phi0 + k (s - s0),
// so (rho', height') = (cos phi, sin phi) and rho'' = -k sin phi.  A joint is a curvature break
// (k jumps) or a convex kink (phi jumps too: the cone's edge onto the shank).  The membrane may
// lie on the profile up to `contact_end()` only: past it (the cone's shank, the ball's upper
// half) the model has no answer (docs/model.md §15.1).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "fe/rigid_profile.hpp"

namespace puncture::fe {

class PiecewiseProfile final : public RigidProfile {
 public:
  // A piece: its curvature k (0: straight), the tangent angle phi0 where it starts, its length,
  // and the part the membrane on it is reported as.
  struct Piece {
    double curvature = 0.0;
    double start_angle = 0.0;
    double length = 0.0;
    MembranePart part = MembranePart::Tip;
  };

  // Pieces from the pole (r = 0, height 0), the last one unbounded (extended past its length);
  // the contact may not pass the arclength `contact_end`, where `beyond` says what follows.
  PiecewiseProfile(const std::vector<Piece>& pieces, double contact_end, std::string beyond)
      : end_(contact_end), beyond_(std::move(beyond)) {
    double s = 0.0, r = 0.0, y = 0.0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      Placed p{pieces[k], s, r, y};
      if (k + 1 == pieces.size()) p.piece.length = std::numeric_limits<double>::infinity();
      placed_.push_back(p);
      if (k + 1 == pieces.size()) break;
      s += pieces[k].length;
      r = radius_on(p, s);
      y = height_on(p, s);
    }
  }

  double radius(double s) const override { return radius_on(at(s), s); }
  double radius_slope(double s) const override { return std::cos(angle(at(s), s)); }
  double radius_curvature(double s) const override {
    const Placed& p = at(s);
    return -p.piece.curvature * std::sin(angle(p, s));
  }
  double height(double s) const override { return height_on(at(s), s); }
  double height_slope(double s) const override { return std::sin(angle(at(s), s)); }
  std::vector<double> curvature_breaks() const override {
    std::vector<double> breaks;
    for (std::size_t k = 1; k < placed_.size(); ++k) breaks.push_back(placed_[k].s0);
    return breaks;
  }
  MembranePart segment_part(int segment) const override { return placed_[segment].piece.part; }
  double contact_end() const override { return end_; }
  std::string beyond_contact_end() const override { return beyond_; }
  double rise_start() const override {
    const Piece& first = placed_.front().piece;
    return first.curvature == 0.0 && first.start_angle == 0.0 ? first.length : 0.0;
  }

  // Signed distance to the nearest piece (each clamped to its ends), signed by that piece's
  // outward normal there: exact for a convex body (outside a convex kink both normals agree).
  double gap(double r, double y) const override {
    double distance = std::numeric_limits<double>::infinity(), sign = 1.0;
    for (const Placed& p : placed_) {
      const double s = closest_on(p, r, y);
      const double dr = r - radius_on(p, s), dy = y - height_on(p, s);
      const double d = std::hypot(dr, dy);
      if (d < distance) {
        distance = d;
        const double phi = angle(p, s);
        sign = std::sin(phi) * dr - std::cos(phi) * dy < 0.0 ? -1.0 : 1.0;
      }
    }
    return sign * distance;
  }
  double closest_arclength(double r, double y) const override {
    double distance = std::numeric_limits<double>::infinity(), best = 0.0;
    for (const Placed& p : placed_) {
      const double s = closest_on(p, r, y);
      const double d = std::hypot(r - radius_on(p, s), y - height_on(p, s));
      if (d < distance) distance = d, best = s;
    }
    return best;
  }

 private:
  struct Placed {
    Piece piece;
    double s0, r0, y0;  // where it starts: arclength, radius, height
  };

  const Placed& at(double s) const {
    std::size_t k = 0;
    while (k + 1 < placed_.size() && s >= placed_[k + 1].s0) ++k;
    return placed_[k];
  }
  static double angle(const Placed& p, double s) {
    return p.piece.start_angle + p.piece.curvature * (s - p.s0);
  }
  static double radius_on(const Placed& p, double s) {
    const double k = p.piece.curvature, phi0 = p.piece.start_angle;
    return k == 0.0 ? p.r0 + std::cos(phi0) * (s - p.s0)
                    : p.r0 + (std::sin(angle(p, s)) - std::sin(phi0)) / k;
  }
  static double height_on(const Placed& p, double s) {
    const double k = p.piece.curvature, phi0 = p.piece.start_angle;
    return k == 0.0 ? p.y0 + std::sin(phi0) * (s - p.s0)
                    : p.y0 - (std::cos(angle(p, s)) - std::cos(phi0)) / k;
  }
  // The arclength of the piece's point closest to (r, y), clamped to the piece.
  static double closest_on(const Placed& p, double r, double y) {
    const double k = p.piece.curvature, phi0 = p.piece.start_angle;
    double s;
    if (k == 0.0) {
      s = p.s0 + (r - p.r0) * std::cos(phi0) + (y - p.y0) * std::sin(phi0);
    } else {  // the arc's centre, and the angle of the point seen from it
      const double cr = p.r0 - std::sin(phi0) / k, cy = p.y0 + std::cos(phi0) / k;
      s = p.s0 + (std::atan2(r - cr, cy - y) - phi0) / k;
    }
    return std::clamp(s, p.s0, p.s0 + p.piece.length);
  }

  std::vector<Placed> placed_;
  double end_;
  std::string beyond_;
};

}  // namespace puncture::fe
