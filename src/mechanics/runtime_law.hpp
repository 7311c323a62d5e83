#pragma once
// The material law as one type for the indentation solver (indentation/dispatch.hpp): each
// evaluation calls the law's function through a pointer, so the shooting and the contact models are
// compiled once rather than once per law (seven times: most of the library's build time).  Each
// law's arithmetic is the one of its own type, so no number changes; the indirect call costs
// at most a few per cent of a solve.
#include <type_traits>
#include <variant>

#include "puncture/material.hpp"
#include "puncture/membrane_stress.hpp"

namespace puncture::detail {

class RuntimeLaw {
 public:
  // The law's functions are looked up once here; an evaluation is then one indirect call.  A
  // std::visit at each evaluation instead made solves 5-12 % slower than with the law's own
  // type; the pointer -2 to +4 % (bench/ratios.py, two alternated runs).
  explicit RuntimeLaw(const MaterialLaw& law)
      : law_(&law),
        object_(std::visit([](const auto& l) -> const void* { return &l; }, law)),
        stress_(
            std::visit([](const auto& l) { return &stress_of<std::decay_t<decltype(l)>>; }, law)),
        energy_(
            std::visit([](const auto& l) { return &energy_of<std::decay_t<decltype(l)>>; }, law)),
        locking_i1_(std::visit([](const auto& l) { return l.locking_i1(); }, law)) {}

  double locking_i1() const { return locking_i1_; }
  const MaterialLaw& variant() const { return *law_; }
  MembraneStress stress(double l1, double l2) const { return stress_(object_, l1, l2); }
  double energy(double l1, double l2, double i1) const { return energy_(object_, l1, l2, i1); }

 private:
  template <class Law>
  static MembraneStress stress_of(const void* law, double l1, double l2) {
    return puncture::membrane_stress(*static_cast<const Law*>(law), l1, l2);
  }
  template <class Law>
  static double energy_of(const void* law, double l1, double l2, double i1) {
    return puncture::strain_energy_density(*static_cast<const Law*>(law), l1, l2, i1);
  }

  const MaterialLaw* law_;
  const void* object_;  // the alternative held by *law_
  MembraneStress (*stress_)(const void*, double, double);
  double (*energy_)(const void*, double, double, double);
  double locking_i1_;
};

// Found by argument-dependent lookup from the solver's templates, before the generic ones.
inline MembraneStress membrane_stress(const RuntimeLaw& law, double l1, double l2) {
  return law.stress(l1, l2);
}

inline double strain_energy_density(const RuntimeLaw& law, double l1, double l2, double i1) {
  return law.energy(l1, l2, i1);
}

}  // namespace puncture::detail
