#include <fmt/format.h>
#include <chrono>
#include "puncture/loading_curve.hpp"
using namespace puncture;
int main() {
  Problem p;
  auto t0 = std::chrono::steady_clock::now();
  auto c = loading_curve(p);
  auto t1 = std::chrono::steady_clock::now();
  fmt::print("status={} {} n={} time={}ms onset={} sw={}\n", to_string(c.status), c.message, c.points.size(), std::chrono::duration<double,std::milli>(t1-t0).count(), c.part_two_onset_depth_mm.value_or(-1), c.stick_slip.occurs);
  for (size_t i=0;i<c.points.size();i+=20) { auto& q=c.points[i]; fmt::print("{:.4f} {:.6f} {} L={:.4f} I1={:.3f}\n", q.depth_mm, q.force_n, to_string(q.configuration), q.part_three_stretch, q.max_first_invariant);}
  p.stick = {StickRule::Force, 0.2};
  c = loading_curve(p);
  fmt::print("status={} {} sw={} d={} {} -> {}\n", to_string(c.status), c.message, c.stick_slip.occurs, c.stick_slip.depth_mm, c.stick_slip.force_stuck_n, c.stick_slip.force_sliding_n);
}
