#pragma once
// Shared pieces of the Python bindings: the registration functions of each file, and the numpy
// conversions used by several of them.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "puncture/outcome.hpp"
#include "puncture/problem.hpp"

namespace puncture::python {

namespace py = pybind11;

void bind_enums(py::module_& m);
void bind_problem(py::module_& m);
void bind_material_presets(py::module_& m);  // after bind_problem (Material)
void bind_results(py::module_& m);
void bind_solve(py::module_& m);
void bind_calibration(py::module_& m);   // after bind_solve: raises its SolverError
void bind_inflation(py::module_& m);     // after bind_solve and bind_problem
void bind_verification(py::module_& m);  // after bind_problem
void bind_sweep(py::module_& m);         // after bind_problem
void bind_failure(py::module_& m);       // after bind_problem, bind_results and bind_calibration

// A read-only numpy array viewing `values`, which `owner` (a Python object) keeps alive.
template <class T>
py::array_t<T> view(const std::vector<T>& values, py::handle owner) {
  py::array_t<T> a(static_cast<py::ssize_t>(values.size()), values.data(), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// A new numpy array with one value per element of `items`.
template <class T, class Items, class Get>
py::array_t<T> column(const Items& items, Get get) {
  py::array_t<T> a(static_cast<py::ssize_t>(items.size()));
  auto out = a.template mutable_unchecked<1>();
  py::ssize_t i = 0;
  for (const auto& item : items) out(i++) = get(item);
  return a;
}

// A Python object holding a T (e.g. with extra attributes set on it), shown as T in the
// signatures, where a bare py::object would read "-> object".
template <class T>
struct Typed {
  py::object object;
};

// Raises puncture.SolverError (registered by bind_solve) with .status, .failure_kind and
// .message (the library's reason); str() is `what`.  Needs the GIL.
[[noreturn]] void raise_solver_error(Status status, const std::string& message,
                                     const std::string& what);

// The library's validation errors, each message prefixed with the attribute it is about (as the
// CLI prefixes them with the flag), under "invalid input:"; empty when there is none.
std::string invalid_input_message(const std::vector<ValidationError>& errors);
std::string invalid_input_message(const Problem& problem);
// ValueError with that message when the problem has validation errors.
void check_problem(const Problem& problem);

// Runs f; an InvalidInput it throws becomes ValueError naming the attribute or argument (one
// error: "name: message"; several: as invalid_input_message).
template <class F>
auto raising_value_error(F&& f) {
  try {
    return f();
  } catch (const InvalidInput& e) {
    if (e.errors().size() == 1)
      throw py::value_error(e.errors().front().parameter + ": " + e.errors().front().message);
    throw py::value_error(invalid_input_message(e.errors()));
  }
}

}  // namespace puncture::python

namespace pybind11::detail {

template <class T>
struct type_caster<puncture::python::Typed<T>> {
  PYBIND11_TYPE_CASTER(puncture::python::Typed<T>, make_caster<T>::name);
  bool load(handle, bool) { return false; }  // a result type only
  static handle cast(const puncture::python::Typed<T>& src, return_value_policy, handle) {
    return src.object.inc_ref();
  }
};

}  // namespace pybind11::detail
