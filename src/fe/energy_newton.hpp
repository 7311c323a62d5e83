#pragma once
// Minimises the discrete energy by Newton's method: Eigen's sparse LDL^T solves each step, a
// diagonal shift makes the step a descent direction where the Hessian is not positive definite,
// and a backtracking (Armijo) line search keeps the energy decreasing and the state admissible.
// Neither Eigen nor Boost offers a sparse second-order minimiser; their dense ones (Eigen's
// HybridNonLinearSolver, MINPACK) cost O(n^3) per step, thousands of times this one at n ~ 10^3.
#include <Eigen/SparseCholesky>
#include <string>

#include "fe/meridian_mesh.hpp"
#include "puncture/outcome.hpp"

namespace puncture::fe {

struct NewtonResult : Outcome {
  int iterations = 0;
  Assembly assembly;  // at the final state
};

inline NewtonResult minimise_energy(const MaterialLaw& law, const Mesh& mesh, Eigen::VectorXd& x,
                                    int max_iterations) {
  NewtonResult result;
  // Converged when a full Newton step moves no unknown by more than this (lengths / A; the
  // roundoff of the assembled gradient moves them by ~1e-15) ...
  constexpr double step_tol = 1e-12;
  // ... or when the energy it would still release is below rounding of the energy itself.
  constexpr double decrement_tol = 1e-15;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  bool pattern_known = false;
  for (int it = 0; it < max_iterations; ++it) {
    result.iterations = it + 1;
    result.assembly = assemble(law, mesh, x);
    Assembly& a = result.assembly;
    if (!a.admissible) {
      result.message = "the start of the Newton iteration is not an admissible state";
      return result;
    }
    if (mesh.unknowns == 0) {
      result.status = Status::Converged;
      return result;
    }
    // Newton step, with a diagonal shift until LDL^T has a positive diagonal (a descent step).
    Eigen::VectorXd step;
    double shift = 0.0;
    const double diagonal_scale = a.hessian.diagonal().cwiseAbs().maxCoeff();
    for (int attempt = 0;; ++attempt) {
      Eigen::SparseMatrix<double> h = a.hessian;
      if (shift > 0.0)
        for (int k = 0; k < h.rows(); ++k) h.coeffRef(k, k) += shift;
      if (!pattern_known) {
        solver.analyzePattern(h);
        pattern_known = true;
      }
      solver.factorize(h);
      if (solver.info() == Eigen::Success && solver.vectorD().minCoeff() > 0.0) {
        step = solver.solve(-a.gradient);
        break;
      }
      if (attempt == 30) {
        result.message = "the energy's Hessian could not be made positive definite";
        return result;
      }
      shift = shift == 0.0 ? 1e-10 * diagonal_scale : 10.0 * shift;
    }
    const double slope = a.gradient.dot(step);  // < 0: descent
    const double max_step = step.cwiseAbs().maxCoeff();
    if (shift == 0.0 && (max_step < step_tol || -slope < decrement_tol * std::max(1.0, a.energy))) {
      x += step;
      result.assembly = assemble(law, mesh, x);
      result.status = result.assembly.admissible ? Status::Converged : Status::NoConvergence;
      return result;
    }
    // Backtracking line search on the energy (Armijo).
    double t = 1.0;
    for (;;) {
      const Eigen::VectorXd trial = x + t * step;
      const double e = total_energy(law, mesh, trial);
      if (std::isfinite(e) && e <= a.energy + 1e-4 * t * slope) {
        x = trial;
        break;
      }
      // Near the minimum the energy's decrease drowns in its rounding: accept a full step that
      // does not raise it by more than that.
      if (t == 1.0 && std::isfinite(e) && shift == 0.0 &&
          e <= a.energy + 1e-14 * std::max(1.0, std::abs(a.energy))) {
        x = trial;
        break;
      }
      t *= 0.5;
      if (t < 1e-12) {
        result.message = "the line search found no lower energy along the Newton step";
        return result;
      }
    }
  }
  result.message =
      "Newton's method did not converge in " + std::to_string(max_iterations) + " iterations";
  return result;
}

}  // namespace puncture::fe
