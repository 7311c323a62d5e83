#pragma once
// Pseudo-arclength continuation of a curve G(y) = 0, G: R^(n+1) -> R^n (Keller): a predictor
// along the unit tangent, then Newton on the bordered system [G(y); t.W(y - y0) - ds] = 0, whose
// matrix [J; t^T W] stays regular through a turning point of any one coordinate (where [J] with
// that coordinate held fixed is singular).  The Jacobian is taken by central differences; the
// arc length is measured in a diagonal metric W (coordinates weighted by 1 / scale^2, zero to
// leave one out).  Step control: a step whose corrector fails, or whose tangent turns by more
// than kMaxTurn, is halved (down to min_step); one that converges in few iterations grows.
// docs/model.md §8.1, "Following a fold".
#include <Eigen/Dense>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <optional>

namespace puncture::detail {

struct ArclengthSettings {
  double initial_step = 1e-2;  // arc length, in the metric's units
  double min_step = 1e-8;
  double max_step = 1e-1;
  int max_iterations = 12;        // Newton iterations of one corrector
  int fast_iterations = 3;        // a corrector this quick lets the next step grow ...
  double growth = 1.5;            // ... by this factor
  double tolerance = 1e-11;       // on every scaled residual (System::scaled)
  double difference_step = 1e-7;  // forward differences, relative to System::scale
};

// One point of the curve: y, the unit tangent there (in the metric, oriented along the
// continuation) and the arc length from the start.
struct ArcPoint {
  Eigen::VectorXd y;
  Eigen::VectorXd tangent;
  double arclength = 0.0;
  int iterations = 0;  // the corrector's Newton iterations
};

// The cosine of the angle between successive tangents below which a step is refused (it may
// have jumped to another branch, or cut across a tight turn).
inline constexpr double kMaxTurn = 0.9;

// System: `int unknowns() const` (n + 1), `std::optional<Eigen::VectorXd> residual(const
// Eigen::VectorXd& y) const` (G, n values; empty outside the model), `Eigen::VectorXd
// residual_scale() const` (n: each equation's convergence scale), `Eigen::VectorXd scale()
// const` (n + 1: each unknown's scale for differences), `Eigen::VectorXd metric() const` (n + 1:
// the arc length's weights).
template <class System>
class PseudoArclength {
 public:
  PseudoArclength(const System& system, ArclengthSettings settings)
      : system_(system), settings_(settings), step_(settings.initial_step) {}

  double step() const { return step_; }

  // The Jacobian of G at y (g: the residual there), by central differences (forward ones moved
  // the tangent's zero, hence a fold's force, by half a difference step); empty where an
  // evaluation fails.
  std::optional<Eigen::MatrixXd> jacobian(const Eigen::VectorXd& y,
                                          const Eigen::VectorXd& g) const {
    const Eigen::VectorXd scale = system_.scale();
    Eigen::MatrixXd j(g.size(), y.size());
    for (int k = 0; k < y.size(); ++k) {
      Eigen::VectorXd hi = y, lo = y;
      const double h = settings_.difference_step * scale[k];
      hi[k] += h;
      lo[k] -= h;
      const auto g_hi = system_.residual(hi), g_lo = system_.residual(lo);
      if (!g_hi || !g_lo) return std::nullopt;
      j.col(k) = (*g_hi - *g_lo) / (2.0 * h);
    }
    return j;
  }

  // The unit tangent at y (Jacobian j) oriented along `previous` (t^T W previous > 0).
  Eigen::VectorXd tangent(const Eigen::MatrixXd& j, const Eigen::VectorXd& previous) const {
    const Eigen::VectorXd w = system_.metric();
    Eigen::MatrixXd a(j.rows() + 1, j.cols());
    a.topRows(j.rows()) = j;
    a.row(j.rows()) = (w.array() * previous.array()).matrix().transpose();
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(j.rows() + 1);
    rhs[j.rows()] = 1.0;
    Eigen::VectorXd t = a.fullPivLu().solve(rhs);
    return t / std::sqrt(t.dot((w.array() * t.array()).matrix()));
  }

  // The point of the curve at arc length `ds` from `from` along its tangent (the bordered
  // Newton corrector), with its tangent; empty if Newton does not converge.
  std::optional<ArcPoint> correct(const ArcPoint& from, double ds) const {
    const Eigen::VectorXd w = system_.metric(), r_scale = system_.residual_scale();
    const Eigen::VectorXd wt = (w.array() * from.tangent.array()).matrix();
    Eigen::VectorXd y = from.y + ds * from.tangent;
    for (int it = 1; it <= settings_.max_iterations; ++it) {
      const auto g = system_.residual(y);
      if (!g || !g->allFinite()) return std::nullopt;
      const double arc = wt.dot(y - from.y) - ds;
      const bool converged = (g->array().abs() / r_scale.array()).maxCoeff() <= settings_.tolerance;
      const auto j = jacobian(y, *g);
      if (!j) return std::nullopt;
      if (converged && it > 1) {
        ArcPoint out;
        out.y = y;
        out.tangent = tangent(*j, from.tangent);
        out.arclength = from.arclength + ds;
        out.iterations = it - 1;
        return out;
      }
      Eigen::MatrixXd a(j->rows() + 1, j->cols());
      a.topRows(j->rows()) = *j;
      a.row(j->rows()) = wt.transpose();
      Eigen::VectorXd rhs(g->size() + 1);
      rhs.head(g->size()) = -*g;
      rhs[g->size()] = -arc;
      y += a.fullPivLu().solve(rhs);
    }
    return std::nullopt;
  }

  // One accepted step from `from`, with the step control: halved on failure or on too sharp a
  // turn, grown after a quick corrector.  Empty when the step falls below min_step.
  std::optional<ArcPoint> advance(const ArcPoint& from) {
    const Eigen::VectorXd w = system_.metric();
    while (step_ >= settings_.min_step) {
      auto next = correct(from, step_);
      if (next && next->tangent.dot((w.array() * from.tangent.array()).matrix()) >= kMaxTurn) {
        if (next->iterations <= settings_.fast_iterations)
          step_ = std::min(settings_.max_step, step_ * settings_.growth);
        return next;
      }
      step_ *= 0.5;
    }
    return std::nullopt;
  }

  // Where coordinate k turns back between `a` and the next point `b` (its tangent component
  // changing sign): TOMS 748 on that component along the arc from a; the point there.  Empty if
  // the components do not differ in sign or a corrector fails.
  std::optional<ArcPoint> turning_point(const ArcPoint& a, const ArcPoint& b, int k) const {
    const double ta = a.tangent[k], tb = b.tangent[k];
    if (!(ta * tb < 0.0)) return std::nullopt;
    std::optional<ArcPoint> best;
    bool failed = false;
    auto component = [&](double s) {
      if (s <= 0.0) return ta;
      auto p = correct(a, s);
      if (!p) {
        failed = true;
        return 0.0;
      }
      const double t = p->tangent[k];
      if (!best || std::abs(t) < std::abs(best->tangent[k])) best = std::move(*p);
      return t;
    };
    std::uintmax_t iterations = 60;
    boost::math::tools::toms748_solve(component,
                                      0.0,
                                      b.arclength - a.arclength,
                                      ta,
                                      tb,
                                      boost::math::tools::eps_tolerance<double>(40),
                                      iterations);
    if (failed || !best) return std::nullopt;
    return best;
  }

 private:
  const System& system_;
  ArclengthSettings settings_;
  double step_;
};

}  // namespace puncture::detail
