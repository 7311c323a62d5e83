#pragma once
// Shared pieces of the calibration bindings (bind_calibration.cpp, bind_critical_i1.cpp,
// bind_friction.cpp, bind_j_lim.cpp, bind_uniaxial_fit.cpp, bind_band.cpp): the errors raised as
// the CLI reports them, the checks of the arguments, and each file's registration function, which
// bind_calibration calls.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "puncture/calibration.hpp"
#include "puncture/csv.hpp"
#include "puncture/problem.hpp"

namespace puncture::python::calibration {

// The CLI's require_finite, with the argument's name for the flag.
void require_finite(double value, const char* name, const char* range, bool ok);

// A library or CSV error as ValueError, with the message the CLI prints (after `prefix: `).
template <class F>
auto as_value_error(F&& f, const std::string& prefix = {}) {
  try {
    return raising_value_error(f);  // InvalidInput: ValueError naming the attribute
  } catch (const CsvError& e) {
    throw py::value_error(e.what());
  } catch (const std::invalid_argument& e) {
    throw py::value_error(prefix.empty() ? std::string(e.what())
                                         : fmt::format("{}: {}", prefix, e.what()));
  }
}

using python::check_problem;  // bindings.hpp
// The problem's errors but those of the unknown a calibration determines.
void check_problem(const Problem& problem, Unknown unknown);

std::vector<double> to_vector(const py::array_t<double, py::array::forcecast>& a, const char* name);

std::optional<double> value_of(const Inversion& i);

// The registration functions, in the order bind_calibration calls them.
void bind_critical_i1(py::module_& m);  // bind_critical_i1.cpp
void bind_inversions(py::module_& m);   // Inversion and ScanSample, shared by the next two
void bind_friction(py::module_& m);     // bind_friction.cpp
void bind_j_lim(py::module_& m);        // bind_j_lim.cpp
void bind_uniaxial(py::module_& m);     // bind_uniaxial_fit.cpp
void bind_band(py::module_& m);         // bind_band.cpp
void bind_curve_fit(py::module_& m);    // bind_curve_fit.cpp

}  // namespace puncture::python::calibration
