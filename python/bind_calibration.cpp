// The calibrations (include/puncture/calibration.hpp) and the puncture band
// (include/puncture/puncture_band.hpp).  As in the CLI: invalid input raises ValueError with the
// CLI's messages (naming the argument instead of the flag); a target the model cannot reach, a
// fit that does not converge or a band without a nominal puncture raises puncture.SolverError
// with the message the CLI prints before its exit code 2.  Vectors are numpy arrays, missing
// values None.  The GIL is released while the C++ code runs.
//
// This file: the helpers the calibrations share (bind_calibration.hpp), Inversion and ScanSample,
// and bind_calibration, which registers each calibration (bind_critical_i1.cpp, bind_friction.cpp,
// bind_j_lim.cpp, bind_uniaxial_fit.cpp, bind_band.cpp).
#include "bind_calibration.hpp"

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "puncture/calibration.hpp"

namespace puncture::python {

namespace calibration {

// The CLI's require_finite, with the argument's name for the flag.
void require_finite(double value, const char* name, const char* range, bool ok) {
  if (!std::isfinite(value) || !ok)
    throw py::value_error(
        fmt::format("{}: must be a finite number {}, got {}", name, range, value));
}

void check_problem(const Problem& problem, Unknown unknown) {
  if (const auto message = invalid_input_message(validation_errors(problem, unknown));
      !message.empty())
    throw py::value_error(message);
}

std::vector<double> to_vector(const py::array_t<double, py::array::forcecast>& a,
                              const char* name) {
  if (a.ndim() != 1)
    throw py::value_error(
        fmt::format("{}: expected a one-dimensional array, got {} dimensions", name, a.ndim()));
  const auto v = a.unchecked<1>();
  std::vector<double> out(static_cast<std::size_t>(v.shape(0)));
  for (py::ssize_t i = 0; i < v.shape(0); ++i) out[static_cast<std::size_t>(i)] = v(i);
  return out;
}

std::optional<double> value_of(const Inversion& i) {
  return i.ok() ? std::optional<double>(i.value) : std::nullopt;
}

// ----- inversions: shared by the friction and J_lim calibrations ------------------------------

void bind_inversions(py::module_& m) {
  py::class_<Inversion, Outcome>(
      m, "Inversion", "One model parameter inverted from one measured value")
      .def_property_readonly(
          "value",
          [](const Inversion& i) { return value_of(i); },
          "the parameter; None if not found")
      .def_property_readonly(
          "solutions",
          [](py::object self) { return view(self.cast<const Inversion&>().solutions, self); },
          "every solution in the searched range")
      .def_readonly("evaluations", &Inversion::evaluations)
      .def("__repr__", [](const Inversion& i) {
        return i.ok() ? fmt::format("Inversion(value={:.8g})", i.value)
                      : fmt::format("Inversion(found=False, message='{}')", i.message);
      });
  py::class_<ScanSample>(m, "ScanSample", "The model at one point of an inversion's scan")
      .def_readonly("parameter", &ScanSample::parameter)
      .def_readonly("model", &ScanSample::model, "None where the solver failed");
}

}  // namespace calibration

void bind_calibration(py::module_& m) {
  calibration::bind_critical_i1(m);
  calibration::bind_inversions(m);
  calibration::bind_friction(m);
  calibration::bind_j_lim(m);
  calibration::bind_uniaxial(m);
  calibration::bind_band(m);
  calibration::bind_curve_fit(m);
}

}  // namespace puncture::python
