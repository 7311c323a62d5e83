#pragma once
// Equilibrium at a prescribed normalised force, for one material law: the shooting for each
// configuration of docs/model.md ("Solving at a given force").  Internal; the public entry points
// are in equilibrium.cpp and loading_curve.cpp.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "indentation/membrane_parts.hpp"
#include "puncture/equilibrium.hpp"

namespace puncture::detail {

struct ScaledSettings {
  double a;   // indenter radius / clamp radius
  double mu;  // Coulomb friction coefficient
  PartTwoEquation equation;
  IntegrationSettings integration;
  double shooting_tol;
  int max_iterations;
  int field_points;  // at least this many Part I samples in recorded solutions
};

// Part I sample: R, t, lambda1, lambda2, h.  Part II sample: R, lambda1, y.
using PartOneSample = std::array<double, 5>;
using PartTwoSample = std::array<double, 3>;

// A solution in normalised variables (lengths / A, stresses / G).
struct ScaledSolution {
  Status status = Status::NoConvergence;
  std::string message;
  Configuration configuration = Configuration::Unloaded;
  double f = 0.0;          // F / (2 pi G H A)
  double parameter = 0.0;  // the configuration's shooting parameter (see ForceSolver)
  double part_three_stretch = 1.0;
  double r_corner = 0.0;         // reference radius of the material at the corner
  double r_top = 0.0;            // reference radius where Part I starts
  double part_two_length = 0.0;  // current length of Part II
  double depth = 0.0;
  double corner_slope = 0.0;
  double tension_ratio = 1.0;  // s1 outside the corner / s1 in Part III
  double edge_s1 = 0.0;        // s1 at the inner end of Part I
  double max_i1 = 3.0;         // largest I1 in Parts I and II
  double max_i1_r = 0.0;       // ... at this reference radius
  double max_i1_radius = 0.0;  // ... and this current radius
  double residual = 0.0;       // lambda2(A) - 1
  int evaluations = 0;
  bool integrated = false;    // every part was integrated (residual and depth are defined)
  double shooting_tol = 0.0;  // the clamp tolerance it was judged against
  std::vector<PartOneSample> part_one;
  std::vector<PartTwoSample> part_two;
  bool ok() const { return status == Status::Converged; }
};

// The shooting parameter p of each configuration:
//   Stick               lambda1 at the indenter's edge (R = a, lambda2 = 1)
//   SlipWithoutPartTwo  the Part III stretch Lambda
//   SlipWithPartTwo     lambda2 where Part I leaves the indenter's side (> a / A; it can be
//                       below 1 when material from beyond the indenter's radius climbs its side)
// Both slip parameters equal the same stretch where Part II appears, so p is continuous there.
template <class Law>
class ForceSolver {
 public:
  ForceSolver(const Law& law, const ScaledSettings& settings)
      : law_(law), s_(settings), max_i1_(law.max_i1()) {}

  // Every configuration's parameter exceeds this floor: 1 for the stretches at the edge and of
  // Part III, a / A for the hoop stretch a / R at the top of Part II (R < A).
  double parameter_floor(Configuration configuration) const {
    return configuration == Configuration::SlipWithPartTwo ? s_.a : 1.0;
  }

  // Membrane held at the indenter's edge, Part III unstretched.
  ScaledSolution stick(double f) const;
  // Membrane sliding over the corner: finds whether Part II exists.
  ScaledSolution slip(double f) const;

  // The state of `configuration` at force f and parameter p, integrated once.  Its residual is
  // zero only at an equilibrium; status is Converged when it is within the shooting tolerance.
  // With `record`, the fields are sampled.
  ScaledSolution assemble(Configuration configuration, double f, double p, bool record) const;

  // Part III stretch at which Part I leaves the corner vertically (wrap angle pi/2) at force f.
  std::optional<double> part_two_onset_stretch(double f) const;
  // Clamp residual of the Part I that leaves the corner vertically with no Part II: negative
  // while Part II is absent, >= 0 once it exists.  Empty past locking.
  std::optional<double> part_two_indicator(double f) const;
  // The state where Part II appears in the slip stage (Part II of zero length); empty if it
  // never appears before the material locks.
  std::optional<ScaledSolution> part_two_onset() const;

  // Puncture in the slip stage with Part II and the crack at the corner, where I1 = i1c.  There
  // the corner's state is fixed by the capstan condition and I1 = i1c alone, whatever the force,
  // so marching Part II up from it to where R s1 = f and shooting Part I on to the clamp leaves
  // a one-parameter shooting in f.  Empty when the puncture is not of that kind (the caller then
  // searches the loading path).
  std::optional<ScaledSolution> puncture_at_corner(double i1c) const;

 private:
  struct PartOneRun {
    bool ok = false;
    bool turned_back = false;  // stopped where the meridian turned back towards the axis
    double residual = 0.0;     // lambda2(A) - 1
    double height = 0.0;
    double max_i1 = 0.0;
    double max_i1_r = 0.0;
    double max_i1_radius = 0.0;  // current radius there
  };
  PartOneRun run_part_one(double f, double r0, PartOneState x0,
                          std::vector<PartOneSample>* samples) const;
  // Clamp residual of a configuration's Part I at (f, p); empty outside the material's domain.
  std::optional<double> residual(Configuration configuration, double f, double p) const;

  struct Start {
    PartOneState state;
    double r0;     // reference radius where Part I starts
    double slope;  // slope there
    double ratio;  // capstan ratio across the corner
  };
  std::optional<Start> start(Configuration configuration, double f, double p) const;

  const Law& law_;
  ScaledSettings s_;
  double max_i1_;
};

}  // namespace puncture::detail

#include "indentation/force_solver_impl.hpp"
