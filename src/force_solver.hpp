#pragma once
// Equilibrium at a prescribed normalised force, for one material law: the shooting for each
// configuration of docs/model.md ("Solving at a given force").  Internal; the public entry points
// are in equilibrium.cpp.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "membrane_parts.hpp"
#include "puncture/equilibrium.hpp"

namespace puncture::detail {

struct ScaledSettings {
  double a;   // indenter radius / clamp radius
  double mu;  // Coulomb friction coefficient
  PartTwoEquation equation;
  IntegrationSettings integration;
  double shooting_tol;
  int max_iterations;
};

// Part I sample: R, t, lambda1, lambda2, h.  Part II sample: R, lambda1, y.
using PartOneSample = std::array<double, 5>;
using PartTwoSample = std::array<double, 3>;

// A solution in normalised variables (lengths / A, stresses / G).
struct ScaledSolution {
  Status status = Status::NoConvergence;
  std::string message;
  Configuration configuration = Configuration::Unloaded;
  double f = 0.0;               // F / (2 pi G H A)
  double part_three_stretch = 1.0;
  double r_corner = 0.0;        // reference radius of the material at the corner
  double r_top = 0.0;           // reference radius where Part I starts
  double part_two_length = 0.0; // current length of Part II
  double depth = 0.0;
  double corner_slope = 0.0;
  double tension_ratio = 1.0;   // s1 outside the corner / s1 in Part III
  double edge_s1 = 0.0;         // s1 at the inner end of Part I
  double max_i1 = 3.0;
  double max_i1_r = 0.0;
  double residual = 0.0;
  int evaluations = 0;
  std::vector<PartOneSample> part_one;
  std::vector<PartTwoSample> part_two;
  bool ok() const { return status == Status::Converged; }
};

template <class Law>
class ForceSolver {
 public:
  ForceSolver(const Law& law, const ScaledSettings& settings)
      : law_(law), s_(settings), max_i1_(law.max_i1()) {}

  // Membrane held at the indenter's edge, Part III unstretched.
  ScaledSolution stick(double f) const;
  // Membrane sliding over the corner: finds whether Part II exists.
  ScaledSolution slip(double f) const;

  // Part III stretch at which Part I leaves the corner vertically (wrap angle pi/2): below it, at
  // force f, Part II exists.
  std::optional<double> part_two_onset_stretch(double f) const;
  // Clamp residual of the Part I that leaves the corner vertically with no Part II: negative
  // while Part II is absent, >= 0 once it exists.  Empty past locking.
  std::optional<double> part_two_indicator(double f) const;

 private:
  struct PartOneRun {
    bool ok = false;
    bool turned_back = false;  // stopped where the meridian turned back towards the axis
    double residual = 0.0;     // lambda2(A) - 1
    double height = 0.0;
    double max_i1 = 0.0;
    double max_i1_r = 0.0;
  };
  PartOneRun run_part_one(double f, double r0, PartOneState x0,
                          std::vector<PartOneSample>* samples) const;

  // Start of Part I for each configuration's shooting parameter; empty when the parameter is
  // outside the domain (the material would lock).
  std::optional<PartOneState> stick_start(double f, double edge_l1) const;
  std::optional<PartOneState> slip_start(double f, double l3_stretch, double* slope,
                                         double* ratio) const;
  std::optional<PartOneState> side_start(double f, double top_l2) const;

  ScaledSolution finish_part_two(double f, double top_l2, ScaledSolution sol) const;

  const Law& law_;
  ScaledSettings s_;
  double max_i1_;
};

}  // namespace puncture::detail

#include "force_solver_impl.hpp"
