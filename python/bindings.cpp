// The compiled part of the Python package `puncture` (python/puncture/__init__.py re-exports it).
#include "bindings.hpp"

PYBIND11_MODULE(_puncture, m) {
  m.doc() =
      "Membrane puncture by a rigid probe (flat punch, sphere-tipped, ball, cone): the C++ "
      "solver.  Units: mm, N, "
      "MPa.  Use the package `puncture`, which re-exports everything here.";
  m.attr("__version__") = PUNCTURE_VERSION;
  puncture::python::bind_enums(m);
  puncture::python::bind_problem(m);
  puncture::python::bind_material_presets(m);
  puncture::python::bind_results(m);
  puncture::python::bind_solve(m);
  puncture::python::bind_calibration(m);
  puncture::python::bind_inflation(m);
  puncture::python::bind_verification(m);
  puncture::python::bind_sweep(m);
  puncture::python::bind_failure(m);
}
