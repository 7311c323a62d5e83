#include "puncture/failure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "failure/energy_release_balance.hpp"
#include "puncture/energy_release.hpp"

namespace puncture {

namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace

std::vector<FailureCriterion> failure_criteria(const Problem& problem) {
  if (!problem.criteria.empty()) return problem.criteria;
  return {CriticalFirstInvariant{problem.critical_i1}};
}

FailureCriterion failure_criterion(const Problem& problem) {
  return failure_criteria(problem).front();
}

std::string describe(const FailureCriterion& criterion) {
  return std::visit(
      Overloaded{
          [](const CriticalFirstInvariant& c) {
            return fmt::format("critical I1 = {:g}", c.critical_i1);
          },
          [](const MaxPrincipalStretch& c) {
            return fmt::format("maximum principal stretch = {:g}", c.critical_stretch);
          },
          [](const CriticalEnergyDensity& c) {
            return fmt::format("critical strain-energy density = {:g} MPa", c.critical_mpa);
          },
          [](const CriticalTrueStress& c) {
            return fmt::format("critical true stress = {:g} MPa", c.critical_mpa);
          },
          [](const CriticalEnergyRelease& c) {
            return fmt::format("tearing energy = {:g} N/mm", c.tearing_energy_n_per_mm);
          },
      },
      criterion);
}

std::string criterion_name(const FailureCriterion& criterion) {
  return criterion_names()[criterion.index()];
}

std::vector<std::string> criterion_names() {
  return {"i1", "max-stretch", "energy-density", "true-stress", "energy-release"};
}

FailureCriterion criterion_from_name(const std::string& name, double value) {
  if (name == "i1") return CriticalFirstInvariant{value};
  if (name == "max-stretch") return MaxPrincipalStretch{value};
  if (name == "energy-density") return CriticalEnergyDensity{value};
  if (name == "true-stress") return CriticalTrueStress{value};
  if (name == "energy-release") return CriticalEnergyRelease{value};
  throw InvalidInput("criterion",
                     fmt::format("unknown failure criterion '{}' (one of i1, max-stretch, "
                                 "energy-density, true-stress, energy-release)",
                                 name));
}

std::string measure_name(const FailureCriterion& criterion) {
  static const char* const names[] = {"I1",
                                      "largest principal stretch",
                                      "strain-energy density",
                                      "largest principal true stress",
                                      "energy released per unit area of the cut"};
  return names[criterion.index()];
}

std::string criterion_unit(const FailureCriterion& criterion) {
  static const char* const units[] = {"", "", "MPa", "MPa", "N/mm"};
  return units[criterion.index()];
}

bool has_local_measure(const FailureCriterion& criterion) {
  return !std::holds_alternative<CriticalEnergyRelease>(criterion);
}

double critical_value(const FailureCriterion& criterion) {
  return std::visit(Overloaded{
                        [](const CriticalFirstInvariant& c) { return c.critical_i1; },
                        [](const MaxPrincipalStretch& c) { return c.critical_stretch; },
                        [](const CriticalEnergyDensity& c) { return c.critical_mpa; },
                        [](const CriticalTrueStress& c) { return c.critical_mpa; },
                        [](const CriticalEnergyRelease& c) { return c.tearing_energy_n_per_mm; },
                    },
                    criterion);
}

double measure_at(const FailureCriterion& criterion, const Material& material, double l1,
                  double l2) {
  const double g = material.shear_modulus_mpa;
  return std::visit(Overloaded{
                        [&](const CriticalFirstInvariant&) { return first_invariant(l1, l2); },
                        [&](const MaxPrincipalStretch&) {
                          return std::max({l1, l2, 1.0 / (l1 * l2)});
                        },
                        [&](const CriticalEnergyDensity&) {
                          return g * strain_energy_density(material.law, l1, l2);
                        },
                        [&](const CriticalTrueStress&) {
                          // sigma_i = t_i / h: the line tension t1 = H s1 / lambda2 over the
                          // thickness h = H / (lambda1 lambda2) is lambda1 s1 (and t2 / h = lambda2
                          // s2).
                          const MembraneStress st = membrane_stress(material.law, l1, l2);
                          return g * std::max(l1 * st.s1, l2 * st.s2);
                        },
                        [&](const CriticalEnergyRelease&) -> double {
                          throw InvalidInput("criterion",
                                             "the energy-release criterion is a balance over the "
                                             "whole membrane: it has no local measure");
                        },
                    },
                    criterion);
}

std::string to_string(MembranePart part) {
  switch (part) {
    case MembranePart::Free:
      return "Part I (free)";
    case MembranePart::Side:
      return "Part II (on the indenter's side)";
    case MembranePart::Tip:
      return "Part III (under the indenter's tip)";
  }
  return "unknown part";
}

FailureAssessment assess_fields(const FailureCriterion& criterion, const MembraneFields& fields,
                                const Material& material) {
  FailureAssessment a;
  a.critical = critical_value(criterion);
  a.value = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const double v =
        measure_at(criterion, material, fields.radial_stretch[i], fields.hoop_stretch[i]);
    // ">=": of equal values (the homogeneous Part III) the outermost row, as the largest I1's
    // place in Part III is its edge.
    if (std::isnan(a.value) || v >= a.value) {
      a.value = v;
      a.part = fields.part[i];
      a.reference_radius_mm = fields.reference_radius_mm[i];
      a.radius_mm = fields.radius_mm[i];
    }
  }
  return a;
}

FailureAssessment assess(const FailureCriterion& criterion, const Equilibrium& state,
                         const Problem& problem) {
  const auto* energy = std::get_if<CriticalEnergyRelease>(&criterion);
  if (!energy) return assess(criterion, state, problem.material);
  return detail::energy_release_assessment(
      problem, energy_release(problem, state, energy->tearing_energy_n_per_mm), *energy);
}

FailureAssessment assess(const FailureCriterion& criterion, const Equilibrium& state,
                         const Material& material) {
  if (!has_local_measure(criterion))
    throw InvalidInput("criterion",
                       "the energy-release criterion is assessed on the problem (assess(criterion, "
                       "state, problem)): it needs the membrane's geometry");
  if (const auto* c = std::get_if<CriticalFirstInvariant>(&criterion))
    return FailureAssessment{state.max_first_invariant,
                             c->critical_i1,
                             state.max_first_invariant_part,
                             state.max_first_invariant_reference_radius_mm,
                             state.max_first_invariant_radius_mm};
  return assess_fields(criterion, state.fields, material);
}

}  // namespace puncture
