// One inflated equilibrium at a given pole stretch: shooting on the pressure from the pole's
// regular start to the clamp condition lambda2(1) = L0 (the pre-stretch; 1 when mounted
// stress-free), with Boost's TOMS 748.
#include "numerics/shooting.hpp"

#include <fmt/format.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "inflation/pole_start.hpp"
#include "inflation/scaled_inflation.hpp"
#include "mechanics/free_membrane_ode.hpp"
#include "mechanics/runtime_law.hpp"
#include "numerics/interior_maximum.hpp"
#include "puncture/kinematics.hpp"

namespace puncture::detail {

namespace {

// The inflated membrane is the free membrane under the pressure alone, its state the strains
// with the volume and the energy (docs/model.md, §14).
using Layout = StrainsAndIntegrals;

template <class Law>
class InflationShooter {
 public:
  InflationShooter(const Law& law, double prestretch, const SolverOptions& options)
      : law_(law),
        flat_(prestretch),
        o_(options),
        integration_{options.integration_rel_tol, options.integration_abs_tol, options.max_steps},
        locking_i1_(law.locking_i1()) {}

  struct Run {
    bool ok = false;
    std::string why;          // when not ok
    InflationOdeState end{};  // at the clamp
    PoleStart start{};
  };

  // Integrates from the pole to the clamp at pressure P.  With `out`, also records the samples
  // and the largest I1 into it.
  Run run(double l0, double pressure, ScaledInflation* out) const {
    Run result;
    const auto start = pole_start(law_, l0, pressure, locking_i1_);
    if (!start) {
      result.why = "the pole's start failed";
      return result;
    }
    result.start = *start;
    const FreeMembraneSystem<Law, Layout> system{law_, TransverseLoad{0.0, pressure}, locking_i1_};
    IntegrationSettings integration = integration_;
    if (out) {
      out->samples.clear();
      integration.max_step = (1.0 - start->r_ref) / std::max(1, o_.field_points);
    }
    InflationOdeState x = start->x;
    InteriorMaximum<InflationOdeState> i1_max;
    result.ok = integrate_part(
        system, x, start->r_ref, 1.0, integration, [&](double r, const InflationOdeState& y) {
          if (out) {
            i1_max.observe(r, y, first_invariant(Layout::lambda1(y), Layout::lambda2(y)));
            out->samples.push_back({r, y[0], Layout::lambda1(y), Layout::lambda2(y), y[3]});
          }
          return true;
        });
    if (!result.ok) {
      result.why = "the integration could not reach the clamp (locking or a collapsed meridian)";
      return result;
    }
    result.end = x;
    if (out) {
      const auto found = refined_maximum(i1_max, system, [](double, const InflationOdeState& y) {
        return first_invariant(Layout::lambda1(y), Layout::lambda2(y));
      });
      const double pole_i1 = first_invariant(l0, l0);
      if (pole_i1 >= found.value) {
        out->max_i1 = pole_i1;
        out->max_i1_r_ref = 0.0;
        out->max_i1_radius = 0.0;
      } else {
        out->max_i1 = found.value;
        out->max_i1_r_ref = found.r;
        out->max_i1_radius = Layout::lambda2(found.state) * found.r;
      }
    }
    return result;
  }

  ScaledInflation solve(double l0, double guess) const {
    ScaledInflation sol;
    sol.pole_stretch = l0;
    int evaluations = 0;
    std::string last_failure;
    // L0 - lambda2(1) (the state holds lambda2 - 1): increases with P, from L0 - l0 < 0 at
    // P = 0.  A meridian that cannot reach the clamp has curled towards the axis (too much
    // pressure): the positive side.  Without pre-stretch, 0 - x is -x exactly.
    const double clamp_strain = flat_ - 1.0;
    auto residual = [&](double pressure) -> std::optional<double> {
      ++evaluations;
      const auto r = run(l0, pressure, nullptr);
      if (!r.ok) {
        last_failure = r.why;
        return std::nullopt;
      }
      return clamp_strain - r.end[2];
    };
    auto g = [&](double p) { return residual_or_beyond(residual, p); };

    double p = guess > 0.0 ? guess : initial_pressure(l0 - flat_);
    double value = g(p);
    double factor = guess > 0.0 ? 1.02 : 2.0;
    double lo = p, hi = p, g_lo = value, g_hi = value;
    bool bracketed = false;
    for (int k = 0; k < 200 && !bracketed; ++k) {
      if (g_hi < 0.0) {  // both ends below the root: move up
        lo = hi;
        g_lo = g_hi;
        hi = lo * factor;
        g_hi = g(hi);
      } else if (g_lo >= 0.0) {  // both above: move down
        hi = lo;
        g_hi = g_lo;
        lo = hi / factor;
        g_lo = g(lo);
      }
      bracketed = g_lo < 0.0 && g_hi >= 0.0;
      factor = std::min(factor * factor, 16.0);
    }
    sol.evaluations = evaluations;
    if (!bracketed) {
      sol.message = fmt::format("no pressure meets the clamp condition at pole stretch {:g}{}",
                                l0,
                                last_failure.empty() ? "" : " (" + last_failure + ")");
      return sol;
    }
    double pressure = hi;
    if (g_hi != 0.0) {
      std::uintmax_t iterations = static_cast<std::uintmax_t>(o_.max_shooting_iterations);
      const auto tolerance = [](double a, double b) {
        return std::abs(b - a) <= 4.0 * std::numeric_limits<double>::epsilon() * std::abs(b);
      };
      const auto bracket =
          boost::math::tools::toms748_solve(g, lo, hi, g_lo, g_hi, tolerance, iterations);
      pressure = 0.5 * (bracket.first + bracket.second);
    }
    sol.pressure = pressure;
    const auto final_run = run(l0, pressure, &sol);
    sol.evaluations = evaluations + 1;
    if (!final_run.ok) {
      sol.message = "the converged meridian could not be integrated again: " + final_run.why;
      return sol;
    }
    const auto& x = final_run.end;
    sol.residual = std::abs(x[2] - clamp_strain);
    sol.slope_rate = final_run.start.slope_rate;
    sol.pole_stress = final_run.start.pole_stress;
    sol.pole_height = x[3];
    sol.volume = x[4];
    sol.energy = x[5];
    sol.clamp_l1 = Layout::lambda1(x);
    // phi = atan2(g, t), with g = P r^2 / 2 and r = 1 at the clamp.
    sol.clamp_slope = std::atan2(TransverseLoad{0.0, pressure}.vertical(1.0), x[0]);
    // After the bracket has collapsed, what is left is the integration's noise: accepted up
    // to a hundred times the tolerance (as the indentation solver does).
    if (sol.residual <= 100.0 * o_.shooting_tol) {
      sol.status = Status::Converged;
    } else {
      sol.message = fmt::format(
          "the clamp residual {:.3g} stays above the tolerance {:.3g} at pole stretch {:g}",
          sol.residual,
          o_.shooting_tol,
          l0);
    }
    return sol;
  }

 private:
  // A first guess of P from the pole stretch's excess over the flat state's: the small-strain
  // (Föppl-Hencky) scaling P ~ excess^(3/2), capped near the neo-Hookean maximum; the bracket
  // search corrects it (a pre-stretched membrane's P ~ excess^(1/2) as well).
  static double initial_pressure(double excess) {
    return std::min(2.5 * std::pow(excess, 1.5), 1.0);
  }

  const Law& law_;
  double flat_;  // L0: the clamp's hoop stretch and the flat state's pole stretch
  SolverOptions o_;
  IntegrationSettings integration_;
  double locking_i1_;
};

}  // namespace

double reference_clamp_radius_mm(const InflationProblem& problem) {
  return problem.clamp_radius_mm / problem.prestretch;
}

double solver_pressure_scale_mpa(const InflationProblem& problem) {
  return problem.material.shear_modulus_mpa * problem.thickness_mm /
         reference_clamp_radius_mm(problem);
}

double locking_pole_stretch(const MaterialLaw& law) {
  const double i1_max = locking_first_invariant(law);
  if (!std::isfinite(i1_max)) return i1_max;
  return equibiaxial_stretch_for_first_invariant(i1_max);
}

ScaledInflation solve_inflation(const InflationProblem& problem, double l0,
                                const SolverOptions& options, double pressure_guess) {
  const MaterialLaw& law = problem.material.law;
  const double flat = problem.prestretch;
  ScaledInflation sol;
  sol.pole_stretch = l0;
  if (l0 == flat) {  // the flat membrane, unloaded (at its pre-stretch)
    sol.status = Status::Converged;
    if (options.record_fields)
      for (int k = 1; k <= std::max(1, options.field_points); ++k)
        sol.samples.push_back(
            {static_cast<double>(k) / std::max(1, options.field_points), 0.0, flat, flat, 0.0});
    return sol;
  }
  if (!(first_invariant(l0, l0) < locking_first_invariant(law))) {
    sol.status = Status::BeyondLocking;
    const auto [name, formula] = locking_limit_words(law);
    sol.message = fmt::format(
        "pole stretch {:g} is at or beyond the {} locking limit (pole stretch {:.6g}, I1 = {} = "
        "{:g})",
        l0,
        name,
        locking_pole_stretch(law),
        formula,
        locking_first_invariant(law));
    return sol;
  }
  SolverOptions o = options;
  o.record_fields = true;  // samples are cheap next to the shooting; the caller drops them
  // One shooter for every law (mechanics/runtime_law.hpp): compiled once, not once per law.
  const RuntimeLaw runtime_law(law);
  auto out = InflationShooter<RuntimeLaw>(runtime_law, flat, o).solve(l0, pressure_guess);
  if (!options.record_fields) out.samples.clear();
  return out;
}

}  // namespace puncture::detail
