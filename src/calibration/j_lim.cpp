// Gent's J_lim from the force of one puncture test (paper §4.1).
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "inversion.hpp"
#include "puncture/calibration.hpp"

namespace puncture {

namespace {

// J_lim = (I1c - 3)(1 + exp(u)).  The predicted force grows like 1 / (J_lim - (I1c - 3)) near
// the lower end, so the inversion runs in u and log F, where the model is close to linear.
double j_lim_of(double i1_excess, double u) { return i1_excess * (1.0 + std::exp(u)); }

}  // namespace

JLimEstimate j_lim_from_puncture_force(const Problem& problem, double puncture_force_n,
                                       const JLimOptions& options) {
  if (!std::holds_alternative<Gent>(problem.material.law))
    throw InvalidInput("material.law",
                       fmt::format("J_lim is a parameter of the Gent law; the material is {}",
                                   law_name(problem.material.law)));
  if (auto errors = validation_errors(problem, Unknown::JLim); !errors.empty())
    throw InvalidInput(std::move(errors), "invalid problem:");
  const double i1_excess = problem.critical_i1 - 3.0;
  if (!std::isfinite(puncture_force_n) || puncture_force_n <= 0.0)
    throw InvalidInput(
        "puncture_force_n",
        fmt::format("puncture force must be a finite number > 0 N, got {}", puncture_force_n));
  if (!(options.min_gap > 0.0) || !(options.max_gap > options.min_gap) ||
      !std::isfinite(options.max_gap) || options.points_per_decade < 1)
    throw std::invalid_argument(
        "J_lim scan: need 0 < min_gap < max_gap and points_per_decade >= 1");

  SolverOptions solver = options.solver;
  solver.record_fields = false;
  const auto with_j_lim = [&](double j_lim) {
    Problem q = problem;
    q.material.law = Gent{j_lim};
    return q;
  };
  // log of the predicted puncture force, as a function of u.
  const detail::Model model = [&](double u) -> std::optional<double> {
    const auto puncture = predict_puncture(with_j_lim(j_lim_of(i1_excess, u)), solver);
    if (!puncture.ok() || !(puncture.force_n > 0.0)) return std::nullopt;
    return std::log(puncture.force_n);
  };

  const double u_lo = std::log(options.min_gap);
  const double u_hi = std::log(options.max_gap);
  const int n = static_cast<int>(
      std::ceil(std::log10(options.max_gap / options.min_gap) * options.points_per_decade));
  std::vector<double> grid;
  for (int k = 0; k <= n; ++k) grid.push_back(u_lo + (u_hi - u_lo) * k / n);
  const auto samples = detail::scan(model, grid);

  JLimEstimate out;
  out.force_n = puncture_force_n;
  out.min_j_lim = j_lim_of(i1_excess, u_lo);
  out.max_j_lim = j_lim_of(i1_excess, u_hi);
  for (const auto& s : samples)
    out.scan.push_back({j_lim_of(i1_excess, s.parameter),
                        s.model ? std::optional<double>(std::exp(*s.model)) : std::nullopt});
  if (samples.back().model) out.smallest_force_n = std::exp(*samples.back().model);
  if (samples.front().model) out.largest_force_n = std::exp(*samples.front().model);
  {
    Problem neo = problem;
    neo.material.law = NeoHookean{};
    const auto p = predict_puncture(neo, solver);
    if (p.ok()) out.neo_hookean_force_n = p.force_n;
  }

  auto inv = detail::invert(model, samples, std::log(puncture_force_n), 1e-10);
  for (auto& s : inv.solutions) s = j_lim_of(i1_excess, s);
  if (inv.ok()) inv.value = inv.solutions.front();
  const auto failed = detail::failed_samples(out.scan);
  const auto failed_note =
      failed.empty() ? std::string() : fmt::format("; the solver failed at J_lim {}", failed);
  if (inv.ok() && inv.solutions.size() > 1) {
    std::string all;
    for (const double s : inv.solutions) all += fmt::format("{}{:.6g}", all.empty() ? "" : ", ", s);
    inv.message = fmt::format(
        "several J_lim give the puncture force {:.6g} N: {}; the force does not determine J_lim",
        puncture_force_n,
        all);
  } else if (!inv.ok()) {
    std::string why;
    if (out.largest_force_n > 0.0 && puncture_force_n > out.largest_force_n)
      why = fmt::format(
          "it is above {:.6g} N, the force at J_lim = {:.8g}, just above the "
          "critical I1 - 3 = {:.6g} where the Gent law would lock at the critical "
          "I1",
          out.largest_force_n,
          out.min_j_lim,
          i1_excess);
    else if (out.neo_hookean_force_n > 0.0 && puncture_force_n <= out.neo_hookean_force_n)
      why = fmt::format(
          "it is at or below {:.6g} N, the neo-Hookean force (the limit of an unbounded J_lim), "
          "the smallest any J_lim gives",
          out.neo_hookean_force_n);
    else if (out.smallest_force_n > 0.0 && puncture_force_n < out.smallest_force_n)
      why = fmt::format(
          "it lies between the neo-Hookean force {:.6g} N and {:.6g} N, the force "
          "at J_lim = {:.6g}: J_lim would be larger still, and the force barely "
          "depends on it there",
          out.neo_hookean_force_n,
          out.smallest_force_n,
          out.max_j_lim);
    else
      why = "the solver failed where the solution would be";
    inv.message = fmt::format(
        "no J_lim in [{:.8g}, {:.6g}] gives the puncture force {:.6g} N: "
        "{}{}{}",
        out.min_j_lim,
        out.max_j_lim,
        puncture_force_n,
        why,
        failed_note,
        inv.message.empty() ? "" : "; " + inv.message);
  } else if (!inv.message.empty()) {
    inv.message += failed_note;
  }
  out.j_lim = inv;

  if (out.j_lim.ok()) {
    const Problem fitted = with_j_lim(out.j_lim.value);
    out.puncture = predict_puncture(fitted, solver);
    const auto state = solve_at_force(fitted, puncture_force_n, Stage::Slip, solver);
    if (state.ok()) out.max_first_invariant_at_force = state.max_first_invariant;
  }
  return out;
}

}  // namespace puncture
