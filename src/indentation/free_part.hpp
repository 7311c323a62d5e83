#pragma once
// The free membrane (Part I) from where it leaves the indenter to the clamp: integrated once for
// a given start, with the clamp residual, the height climbed and the largest I1 along the way.
// The contact model (indentation/contact/) supplies the start; the shooting varies it.  Part I is
// the free membrane (mechanics/free_membrane_ode.hpp) under the indenter's force and the gas
// pressure (if any), its state the stretches.
#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

#include "indentation/scaled_solution.hpp"
#include "mechanics/free_membrane_ode.hpp"
#include "numerics/even_samples.hpp"
#include "numerics/interior_maximum.hpp"

namespace puncture::detail {

// Clamp residual given to a Part I whose meridian turns back towards the axis (t < 0, hoop
// compression) before the clamp: the hoop stretch falls short, so the residual is negative.
inline constexpr double kTurnedBack = -1.0;

// Where and how Part I starts: its state at the reference radius r0, with the slope there and the
// capstan ratio across the corner (infinite for a membrane held at the edge).
struct FreeStart {
  PartOneState state;
  double r0;     // reference radius where Part I starts
  double slope;  // slope there
  double ratio;  // capstan ratio across the corner
};

struct FreePartRun {
  bool ok = false;
  bool turned_back = false;  // stopped where the meridian turned back towards the axis
  double residual = 0.0;     // lambda2 - L0 at the clamp
  double height = 0.0;
  double max_i1 = 0.0;
  double max_i1_r = 0.0;
  double max_i1_radius = 0.0;  // current radius there
  double wrinkle_r = -1.0;     // the first reference radius with compressive hoop stress (-1: none)
  double wrinkle_radius = -1.0;
};

// Whether the hoop stress s2 is compressive: for every law here (invariant-based, W1 + lambda1^2
// W2 > 0) s2 has the sign of lambda1^2 lambda2^4 - 1 (docs/model.md §17), a check of two
// products instead of a stress evaluation.
inline bool hoop_compressive(double l1, double l2) {
  const double l2_squared = l2 * l2;
  return l1 * l1 * l2_squared * l2_squared < 1.0;
}

template <class Law>
class FreePart {
 public:
  FreePart(const Law& law, const ShootingSettings& settings)
      : law_(law), s_(settings), locking_i1_(law.locking_i1()) {}

  const Law& law() const { return law_; }
  const ShootingSettings& settings() const { return s_; }
  double locking_i1() const { return locking_i1_; }
  // The clamp's hoop stretch L0, also the stretch of material held where it touched.
  double prestretch() const { return s_.prestretch; }
  // The gas pressure P under the membrane (0: none).
  double pressure() const { return s_.pressure; }

  // Part I at force f from `start` to the clamp; with `samples`, the solution is sampled.
  // Without `find_maximum` the largest I1 is left out (the shooting's residuals need only the
  // clamp: its search between the steps costs about a third of an integration).
  FreePartRun run(double f, const FreeStart& start, std::vector<PartOneSample>* samples,
                  bool find_maximum = true) const {
    FreePartRun run;
    PartOneState x = start.state;
    const double r0 = start.r0;
    if (samples) samples->clear();
    // The gas pressure pushes against the indenter's force: R s1 sin(phi) = f - P r^2 / 2.
    const FreeMembraneSystem<Law, Stretches> system{
        law_, TransverseLoad{f, -s_.pressure}, locking_i1_};
    double last_l2 = x[2];
    InteriorMaximum<PartOneState> i1_max;
    Knots<PartOneState> knots;
    run.ok =
        integrate_part(system, x, r0, 1.0, s_.integration, [&](double r, const PartOneState& y) {
          if (find_maximum) {
            i1_max.observe(r, y, first_invariant(y[1], y[2]));
            if (run.wrinkle_r < 0.0 && hoop_compressive(y[1], y[2])) {
              run.wrinkle_r = r;
              run.wrinkle_radius = y[2] * r;
            }
          }
          if (samples) knots.add(r, y);
          last_l2 = y[2];
          // The meridian turned back towards the axis: hoop stretch too small.  Under a gas
          // pressure the falling meridian may overhang its clamp (t < 0) as an inflated dome
          // does, so it is integrated on; one that curls onto the axis fails on the way and
          // counts as turned back below.
          if (y[0] < 0.0 && s_.pressure == 0.0) {
            run.turned_back = true;
            return false;
          }
          return true;
        });
    // A Part I that fails (locks) on its way with the hoop stretch already below the clamp's has
    // collapsed towards the axis: it belongs to the negative side of the clamp residual as well.
    if (!run.ok && last_l2 < s_.prestretch) run.turned_back = true;
    if (samples)
      for (const auto& [r, y] :
           even_samples(system, knots, std::max(1, s_.field_points), s_.integration))
        samples->push_back({r, y[0], y[1], y[2], y[3]});
    if (run.ok && find_maximum) {
      const auto found = refined_maximum(i1_max, system, [](double, const PartOneState& y) {
        return first_invariant(y[1], y[2]);
      });
      run.max_i1 = found.value;
      run.max_i1_r = found.r;
      run.max_i1_radius = found.state[2] * found.r;  // r = lambda2 R
    }
    run.residual = run.turned_back ? kTurnedBack : x[2] - s_.prestretch;
    run.height = x[3];
    return run;
  }

  // The clamp residual from `start`; empty when Part I can be integrated neither to the clamp
  // nor to where it turns back (the material locks on the way).
  std::optional<double> residual(double f, const std::optional<FreeStart>& start) const {
    if (!start) return std::nullopt;
    const auto r = run(f, *start, nullptr, false);
    return r.ok || r.turned_back ? std::optional<double>(r.residual) : std::nullopt;
  }

 private:
  const Law& law_;
  ShootingSettings s_;
  double locking_i1_;
};

}  // namespace puncture::detail
