// Gent J_lim from one puncture force (include/puncture/calibration.hpp): JLimEstimate and
// j_lim_from_puncture_force.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <variant>

#include "bind_calibration.hpp"
#include "puncture/calibration.hpp"

namespace puncture::python::calibration {

void bind_j_lim(py::module_& m) {
  py::class_<JLimEstimate>(m, "JLimEstimate", "Gent J_lim from one puncture force")
      .def_readonly("force_n", &JLimEstimate::force_n)
      .def_readonly("j_lim", &JLimEstimate::j_lim, "Inversion")
      .def_readonly("smallest_force_n", &JLimEstimate::smallest_force_n)
      .def_readonly("largest_force_n", &JLimEstimate::largest_force_n)
      .def_readonly("neo_hookean_force_n", &JLimEstimate::neo_hookean_force_n)
      .def_readonly("min_j_lim", &JLimEstimate::min_j_lim)
      .def_readonly("max_j_lim", &JLimEstimate::max_j_lim)
      .def_readonly("puncture", &JLimEstimate::puncture, "predicted puncture at the fitted J_lim")
      .def_readonly("max_first_invariant_at_force", &JLimEstimate::max_first_invariant_at_force)
      .def_readonly("scan", &JLimEstimate::scan, "(J_lim, predicted puncture force [N])");

  m.def(
      "j_lim_from_puncture_force",
      [](const Problem& problem,
         double puncture_force_n,
         const std::optional<SolverOptions>& options) {
        if (!std::holds_alternative<Gent>(problem.material.law))
          throw py::value_error(fmt::format(
              "material: J_lim is a parameter of the Gent law; j_lim_from_puncture_force needs "
              "a Gent material, got {}",
              law_name(problem.material.law)));
        check_problem(problem, Unknown::JLim);
        require_finite(puncture_force_n, "puncture_force_n", "> 0 N", puncture_force_n > 0.0);
        JLimOptions o;
        if (options) o.solver = *options;
        JLimEstimate e;
        as_value_error([&] {
          py::gil_scoped_release release;
          e = j_lim_from_puncture_force(problem, puncture_force_n, o);  // ignores its J_lim
        });
        if (!e.j_lim.ok()) raise_solver_error(e.j_lim.status, e.j_lim.message, e.j_lim.message);
        return e;
      },
      py::arg("problem"),
      py::arg("puncture_force_n"),
      py::arg("options") = py::none(),
      "Gent J_lim from one puncture test (paper §4.1): the J_lim whose predicted puncture force\n"
      "equals puncture_force_n [N].  problem's J_lim is ignored.  Raises SolverError when no\n"
      "J_lim gives the force.");
}

}  // namespace puncture::python::calibration
