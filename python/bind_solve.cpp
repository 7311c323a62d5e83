// The solve functions.  Invalid input raises ValueError with the library's validation messages
// (as the CLI prints them, each naming the attribute instead of the flag); a solve that does not
// converge raises puncture.SolverError (a RuntimeError) with .status and .message.  The GIL is
// released while the C++ solver runs.
#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <variant>

#include "bindings.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"

namespace puncture::python {

namespace {

// A solve that gave no usable result; becomes puncture.SolverError.
struct SolverFailure : std::runtime_error {
  SolverFailure(Status s, std::string library_message, const std::string& what)
      : std::runtime_error(what), status(s), message(std::move(library_message)) {}
  Status status;
  std::string message;
};

using StageArg = std::variant<Stage, std::string>;

// Same wording as the CLI's checks of --force and --depth.
void check_load(double value, const char* name, const char* unit) {
  if (!std::isfinite(value) || value < 0.0)
    throw py::value_error(
        fmt::format("{}: must be a finite number >= 0 {}, got {}", name, unit, value));
}

// nullopt: "auto", the stage the problem's stick criterion gives at the load.
std::optional<Stage> explicit_stage(const StageArg& stage) {
  if (const auto* s = std::get_if<Stage>(&stage)) return *s;
  const auto& text = std::get<std::string>(stage);
  if (text == "stick") return Stage::Stick;
  if (text == "slip") return Stage::Slip;
  if (text == "auto") return std::nullopt;
  throw py::value_error(
      fmt::format("stage: expected Stage, 'stick', 'slip' or 'auto', got '{}'", text));
}

// As the CLI's --stage auto.  Runs without the GIL.
Stage automatic_stage(const Problem& problem, double load, bool by_force,
                      const SolverOptions& options) {
  const auto b = stick_slip_boundary(problem, options);
  if (b.status == Status::OutsideModel) throw SolverFailure(b.status, b.message, b.message);
  if (b.status != Status::Converged)
    throw SolverFailure(
        b.status,
        b.message,
        fmt::format(
            "cannot locate the stick -> slip switch ({}): {}", to_string(b.status), b.message));
  if (b.first_stage == Stage::Slip) return Stage::Slip;
  if (!b.switches) return Stage::Stick;
  const double limit = by_force ? b.force_stuck_n : b.depth_mm;
  return load <= limit ? Stage::Stick : Stage::Slip;
}

template <class Result>
Typed<std::decay_t<Result>> with_problem(Result&& result, const Problem& problem) {
  py::object out = py::cast(std::forward<Result>(result));
  // A copy: py::cast of the caller's Problem would return the caller's own object.
  out.attr("problem") = py::cast(Problem(problem));
  return {out};
}

Typed<Equilibrium> solve_state(const Problem& problem, double load, bool by_force,
                               const StageArg& stage, const std::optional<SolverOptions>& options) {
  check_problem(problem);
  check_load(load, by_force ? "force_n" : "depth_mm", by_force ? "N" : "mm");
  const auto chosen = explicit_stage(stage);
  const SolverOptions o = options.value_or(SolverOptions{});
  Equilibrium e;
  {
    py::gil_scoped_release release;
    const Stage s = chosen ? *chosen : automatic_stage(problem, load, by_force, o);
    e = raising_value_error([&] {
      return by_force ? solve_at_force(problem, load, s, o) : solve_at_depth(problem, load, s, o);
    });
  }
  if (!e.ok())
    throw SolverFailure(e.status,
                        e.message,
                        fmt::format("no equilibrium in the {} stage ({}): {}",
                                    to_string(e.stage),
                                    to_string(e.status),
                                    e.message));
  return with_problem(std::move(e), problem);
}

// Never destroyed: it must outlive the interpreter's own references.
py::exception<SolverFailure>* solver_error = nullptr;

// Sets the Python error indicator to a SolverError (what an exception translator must do).
void set_solver_error(Status status, const std::string& message, const std::string& what) {
  py::object error = py::handle(solver_error->ptr())(what);
  error.attr("status") = status;
  error.attr("failure_kind") = failure_kind(status);
  error.attr("message") = message;
  PyErr_SetObject(solver_error->ptr(), error.ptr());
}

}  // namespace

[[noreturn]] void raise_solver_error(Status status, const std::string& message,
                                     const std::string& what) {
  set_solver_error(status, message, what);
  throw py::error_already_set();
}

void bind_solve(py::module_& m) {
  solver_error = new py::exception<SolverFailure>(m, "SolverError", PyExc_RuntimeError);
  solver_error->doc() =
      "The solver gave no usable result (the CLI's exit code 2).  Attributes: status (Status),\n"
      "failure_kind (FailureKind: Physical, Numerical or OutsideModel) and message (the\n"
      "solver's reason); str() has both.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const SolverFailure& e) {
      set_solver_error(e.status, e.message, e.what());
    }
  });

  m.def(
      "solve_at_force",
      [](const Problem& problem,
         double force_n,
         const StageArg& stage,
         const std::optional<SolverOptions>& options) {
        return solve_state(problem, force_n, true, stage, options);
      },
      py::arg("problem"),
      py::arg("force_n"),
      py::arg("stage") = "auto",
      py::arg("options") = py::none(),
      "Equilibrium at indenter force force_n [N].  stage: Stage.Stick, Stage.Slip, their names\n"
      "'stick' / 'slip', or 'auto' (the stage the problem's stick criterion gives at this\n"
      "force, as the CLI's --stage auto).");
  m.def(
      "solve_at_depth",
      [](const Problem& problem,
         double depth_mm,
         const StageArg& stage,
         const std::optional<SolverOptions>& options) {
        return solve_state(problem, depth_mm, false, stage, options);
      },
      py::arg("problem"),
      py::arg("depth_mm"),
      py::arg("stage") = "auto",
      py::arg("options") = py::none(),
      "Equilibrium at indentation depth depth_mm [mm]; stage as for solve_at_force.");

  m.def(
      "loading_curve",
      [](const Problem& problem,
         int points,
         double max_depth_mm,
         const std::optional<SolverOptions>& options,
         const py::object& progress) {
        check_problem(problem);
        if (points < 2 || points > 100000)
          throw py::value_error(
              fmt::format("points: must be in the range 2 to 100000, got {}", points));
        if (!std::isfinite(max_depth_mm) || max_depth_mm < 0.0)
          throw py::value_error(
              fmt::format("max_depth_mm: must be a finite number >= 0 mm (0 = to puncture), got {}",
                          max_depth_mm));
        CurveOptions curve;
        curve.points = points;
        curve.max_depth_mm = max_depth_mm;
        if (!progress.is_none()) {
          // Borrowed: the caller's argument outlives the call.
          PyObject* callback = progress.ptr();
          curve.progress = [callback](int done, int total) {
            py::gil_scoped_acquire acquire;
            py::handle{callback}(done, total);
          };
        }
        LoadingCurve c;
        {
          py::gil_scoped_release release;
          c = raising_value_error(
              [&] { return loading_curve(problem, curve, options.value_or(SolverOptions{})); });
        }
        if (!c.ok())
          throw SolverFailure(
              c.status,
              c.message,
              fmt::format("the loading curve failed ({}): {}", to_string(c.status), c.message));
        return with_problem(std::move(c), problem);
      },
      py::arg("problem"),
      py::arg("points") = 200,
      py::arg("max_depth_mm") = 0.0,
      py::arg("options") = py::none(),
      py::arg("progress") = py::none(),
      "The displacement-controlled loading curve: `points` equally spaced depths from zero to\n"
      "puncture (or to max_depth_mm when > 0).  progress(done, total) is called after each\n"
      "point if given.");

  m.def(
      "predict_puncture",
      [](const Problem& problem, const std::optional<SolverOptions>& options) {
        check_problem(problem);
        PuncturePrediction p;
        {
          py::gil_scoped_release release;
          p = predict_puncture(problem, options.value_or(SolverOptions{}));
        }
        if (!p.ok()) {
          const Status status = p.state.ok() ? Status::NoConvergence : p.state.status;
          throw SolverFailure(status, p.message, "no puncture point found: " + p.message);
        }
        return with_problem(std::move(p), problem);
      },
      py::arg("problem"),
      py::arg("options") = py::none(),
      "The predicted puncture point: where the largest I1 reaches problem.critical_i1.");

  m.def(
      "stick_slip_boundary",
      [](const Problem& problem, const std::optional<SolverOptions>& options) {
        check_problem(problem);
        StageBoundary b;
        {
          py::gil_scoped_release release;
          b = stick_slip_boundary(problem, options.value_or(SolverOptions{}));
        }
        if (b.status != Status::Converged)
          throw SolverFailure(b.status,
                              b.message,
                              fmt::format("cannot locate the stick -> slip switch ({}): {}",
                                          to_string(b.status),
                                          b.message));
        return with_problem(std::move(b), problem);
      },
      py::arg("problem"),
      py::arg("options") = py::none(),
      "The stage the membrane starts in and the depth / force where the stick criterion\n"
      "switches it to sliding.");

  m.def("force_scale_n", &force_scale_n, py::arg("problem"), "2 pi G H A [N] of the problem");
}

}  // namespace puncture::python
