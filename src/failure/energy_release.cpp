#include "puncture/energy_release.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

#include "failure/cut_membrane.hpp"
#include "failure/energy_release_balance.hpp"

namespace puncture {

namespace detail {

namespace {

// Integral of y dx through the nodes x (increasing): Simpson's rule on each pair of intervals
// (the parabola through three uneven nodes), the last interval of an odd count from the
// parabola through the last three nodes; the trapezoid for two nodes.
double simpson(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  if (n < 2) return 0.0;
  if (n == 2) return 0.5 * (x[1] - x[0]) * (y[0] + y[1]);
  double sum = 0.0;
  std::size_t i = 0;
  for (; i + 2 < n; i += 2) {
    const double h0 = x[i + 1] - x[i], h1 = x[i + 2] - x[i + 1], h = h0 + h1;
    if (!(h0 > 0.0 && h1 > 0.0)) {  // a repeated node (a part's boundary sampled twice)
      sum += 0.5 * (h0 * (y[i] + y[i + 1]) + h1 * (y[i + 1] + y[i + 2]));
      continue;
    }
    sum += h / 6.0 *
           ((2.0 - h1 / h0) * y[i] + h * h / (h0 * h1) * y[i + 1] + (2.0 - h0 / h1) * y[i + 2]);
  }
  if (i + 1 < n) {  // one interval left: [x_{n-2}, x_{n-1}] under the parabola through 3 nodes
    const double h0 = x[n - 2] - x[n - 3], h1 = x[n - 1] - x[n - 2];
    if (h0 > 0.0 && h1 > 0.0)
      sum += h1 / 6.0 *
             ((3.0 - h1 / (h0 + h1)) * y[n - 1] + (3.0 + h1 / h0) * y[n - 2] -
              h1 * h1 / (h0 * (h0 + h1)) * y[n - 3]);
    else
      sum += 0.5 * h1 * (y[n - 2] + y[n - 1]);
  }
  return sum;
}

// A part's rows at even steps of R (the solver samples each part so) with a multiple of 4
// intervals: Richardson's extrapolation of Simpson's rule on every row and on every other row,
// (16 S_h - S_2h) / 15 (Boole's rule).  Near the top of Part II the integrand changes fast, so
// Simpson's h^4 error is large there: on the paper's frictionless membrane at 200 intervals a
// part, 5e-6 relative, and 5e-7 extrapolated (docs/model.md §18).  Otherwise Simpson's rule.
double part_integral(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size() - 1;  // intervals
  if (n < 8 || n % 4 != 0) return simpson(x, y);
  const double h = (x[n] - x[0]) / static_cast<double>(n);
  for (std::size_t i = 1; i <= n; ++i)
    if (std::abs(x[i] - x[i - 1] - h) > 1e-9 * h) return simpson(x, y);
  double fine = y[0] + y[n], coarse = y[0] + y[n];
  for (std::size_t i = 1; i < n; ++i) {
    fine += (i % 2 ? 4.0 : 2.0) * y[i];
    if (i % 2 == 0) coarse += ((i / 2) % 2 ? 4.0 : 2.0) * y[i];
  }
  fine *= h / 3.0;
  coarse *= 2.0 * h / 3.0;
  return (16.0 * fine - coarse) / 15.0;
}

}  // namespace

double stored_energy_mj(const Problem& p, const MembraneFields& fields) {
  const double g = p.material.shear_modulus_mpa;
  double total = 0.0;
  std::vector<double> r, w;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    r.push_back(fields.reference_radius_mm[i]);
    w.push_back(
        g *
        strain_energy_density(p.material.law, fields.radial_stretch[i], fields.hoop_stretch[i]) *
        r.back());
    if (i + 1 == fields.size() || fields.part[i + 1] != fields.part[i]) {
      total += part_integral(r, w);
      r.clear();
      w.clear();
    }
  }
  return 2.0 * std::numbers::pi * p.geometry.thickness_mm * total;
}

EnergyRelease energy_release_of(const Problem& p, const MembraneFields& fields,
                                double part_three_stretch, double tearing_energy_n_per_mm) {
  const double length = reference_clamp_radius_mm(p);  // A / L0, the cut membrane's unit
  const double rod = std::get<FlatPunch>(p.indenter).radius_mm;
  const double cut = rod / part_three_stretch;
  const double energy_unit = 2.0 * std::numbers::pi * p.material.shear_modulus_mpa *
                             p.geometry.thickness_mm * length * length;
  EnergyRelease out;
  out.stored_energy_mj = stored_energy_mj(p, fields);
  out.cut_reference_radius_mm = cut;
  out.cut_energy_mj =
      tearing_energy_n_per_mm * 2.0 * std::numbers::pi * cut * p.geometry.thickness_mm;
  const auto cut_state =
      cut_membrane(p.material.law, rod / length, cut / length, p.preload.prestretch);
  if (!cut_state) {
    out.punctured_energy_mj = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  out.punctured_energy_mj = energy_unit * cut_state->energy;
  out.collar_reference_radius_mm = cut_state->collar_to * length;
  out.hole_radius_mm = cut_state->hole_radius * length;
  return out;
}

FailureAssessment energy_release_assessment(const Problem& p, const EnergyRelease& balance,
                                            const CriticalEnergyRelease& criterion) {
  FailureAssessment a;
  a.critical = criterion.tearing_energy_n_per_mm;
  a.part = MembranePart::Tip;  // the cut is Part III's edge, the corner's ring
  a.reference_radius_mm = balance.cut_reference_radius_mm;
  a.radius_mm = std::get<FlatPunch>(p.indenter).radius_mm;
  // Per unit reference area of the cut, 2 pi R_c H: its ratio to Gamma is released / cost.
  a.value = balance.released_energy_mj() /
            (2.0 * std::numbers::pi * a.reference_radius_mm * p.geometry.thickness_mm);
  return a;
}

}  // namespace detail

std::vector<std::string> energy_release_conflicts(const Problem& p) {
  std::vector<std::string> out;
  if (!sharp_flat_punch(p.indenter))
    out.push_back(
        fmt::format("needs the flat punch with a sharp corner (the cut along the corner's ring "
                    "and the cut membrane resting on the rod through the hole are its), got the {}",
                    describe(p.indenter)));
  if (p.friction != 0.0)
    out.push_back(fmt::format(
        "needs a frictionless contact, friction 0 (got {:g}): friction dissipates, so the "
        "energy released by the cut would depend on the loading path, not on the state",
        p.friction));
  if (p.stick.rule != StickRule::None)
    out.push_back(fmt::format(
        "needs the membrane free to slide from the first touch, stick rule none (got {}): a "
        "held membrane's edge is pinned by what the cut membrane's state does not define, and "
        "the switch to sliding dissipates",
        to_string(p.stick.rule)));
  if (p.preload.pressure_mpa != 0.0)
    out.push_back(fmt::format(
        "needs no gas pressure (got {:g} MPa): the gas works on the membrane and vents through "
        "the cut, which the cut membrane's state does not model",
        p.preload.pressure_mpa));
  if (p.part_two_equation != PartTwoEquation::RingBalance)
    out.push_back(
        "needs the ring-balance Part II equation: the printed Eq. (18) is not an equilibrium, so "
        "its states have no potential energy");
  return out;
}

EnergyRelease energy_release(const Problem& problem, const Equilibrium& state,
                             double tearing_energy_n_per_mm) {
  if (!(std::isfinite(tearing_energy_n_per_mm) && tearing_energy_n_per_mm > 0.0))
    throw InvalidInput("tearing_energy",
                       fmt::format("the tearing energy must be a finite number > 0 N/mm, got {}",
                                   tearing_energy_n_per_mm));
  if (const auto conflicts = energy_release_conflicts(problem); !conflicts.empty()) {
    std::vector<ValidationError> errors;
    for (const auto& c : conflicts)
      errors.push_back({"criteria", "the energy-release criterion " + c});
    throw InvalidInput(errors);
  }
  if (!state.ok() || state.fields.size() == 0)
    throw InvalidInput("state",
                       "the energy balance needs a solved state with its fields (SolverOptions::"
                       "field_points > 0)");
  return detail::energy_release_of(
      problem, state.fields, state.part_three_stretch, tearing_energy_n_per_mm);
}

}  // namespace puncture
