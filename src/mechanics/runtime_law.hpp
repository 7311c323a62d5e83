#pragma once
// The material law as one type for the indentation solver (indentation/dispatch.hpp): each
// evaluation picks the law by a switch on the variant, so the shooting and the contact models are
// compiled once rather than once per law (seven times: most of the library's build time).  Each
// law's arithmetic is the one of its own type, so no number changes; the switch costs a few
// per cent of a solve (bench/solver_bench.cpp).
#include <variant>

#include "puncture/material.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

class RuntimeLaw {
 public:
  explicit RuntimeLaw(const MaterialLaw& law) : law_(&law) {}

  double locking_i1() const {
    return std::visit([](const auto& l) { return l.locking_i1(); }, *law_);
  }
  const MaterialLaw& variant() const { return *law_; }

 private:
  const MaterialLaw* law_;
};

// Found by argument-dependent lookup from the solver's templates, before the generic ones.
inline MembraneStress membrane_stress(const RuntimeLaw& law, double l1, double l2) {
  return std::visit([&](const auto& l) { return puncture::membrane_stress(l, l1, l2); },
                    law.variant());
}

inline double strain_energy_density(const RuntimeLaw& law, double l1, double l2, double i1) {
  return std::visit(
      [&](const auto& l) { return puncture::strain_energy_density(l, l1, l2, i1); },
      law.variant());
}

}  // namespace puncture::detail
