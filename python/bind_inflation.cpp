// The inflation (bulge) test (include/puncture/inflation.hpp): InflationProblem, the states, the
// curve with its pressure extrema and burst, and the solve functions.  Invalid input raises
// ValueError naming the attribute or argument; a solve that does not converge raises
// puncture.SolverError with .status and .message, like the indentation solver.  The GIL is
// released while the C++ solver runs.
#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <variant>

#include "bindings.hpp"
#include "puncture/inflation.hpp"

namespace puncture::python {

namespace {

// An InflationProblem, or an indentation Problem whose membrane is used.
using ProblemArg = std::variant<InflationProblem, Problem>;

InflationProblem membrane_of(const ProblemArg& arg) {
  if (const auto* p = std::get_if<InflationProblem>(&arg)) return *p;
  return inflation_problem(std::get<Problem>(arg));
}

std::string invalid_message(const InflationProblem& problem) {
  return invalid_input_message(validation_errors(problem));
}

InflationProblem checked(const ProblemArg& arg) {
  auto problem = membrane_of(arg);
  if (const auto message = invalid_message(problem); !message.empty())
    throw py::value_error(message);
  return problem;
}

// Runs a library call without the GIL; its InvalidInput becomes ValueError naming the argument.
template <class F>
auto released(F&& f) {
  return raising_value_error([&] {
    py::gil_scoped_release release;
    return f();
  });
}

template <class Result>
Typed<std::decay_t<Result>> with_problem(Result&& result, const InflationProblem& problem) {
  py::object out = py::cast(std::forward<Result>(result));
  out.attr("problem") = py::cast(InflationProblem(problem));
  return {out};
}

InflationCurveOptions range_of(int points, double max_pole_stretch, int scan_points) {
  InflationCurveOptions o;
  o.points = points;
  o.max_pole_stretch = max_pole_stretch;
  o.scan_points = scan_points;
  return o;
}

using StateValue = double InflationState::*;

// The states' columns with the CLI's CSV names, and the attribute of each.
constexpr std::tuple<const char*, const char*, StateValue> kStateColumns[] = {
    {"pole_stretch", "pole_stretch", &InflationState::pole_stretch},
    {"pressure_mpa", "pressure_mpa", &InflationState::pressure_mpa},
    {"normalized_pressure", "normalized_pressure", &InflationState::normalized_pressure},
    {"pole_height_mm", "pole_height_mm", &InflationState::pole_height_mm},
    {"volume_mm3", "volume_mm3", &InflationState::volume_mm3},
    {"stored_energy_mj", "stored_energy_mj", &InflationState::stored_energy_mj},
    {"pole_curvature_radius_mm",
     "pole_curvature_radius_mm",
     &InflationState::pole_curvature_radius_mm},
    {"pole_tension_n_per_mm", "pole_tension_n_per_mm", &InflationState::pole_tension_n_per_mm},
    {"clamp_radial_stretch", "clamp_radial_stretch", &InflationState::clamp_radial_stretch},
    {"max_i1", "max_first_invariant", &InflationState::max_first_invariant},
    {"max_i1_R_mm",
     "max_first_invariant_reference_radius_mm",
     &InflationState::max_first_invariant_reference_radius_mm},
    {"max_i1_r_mm",
     "max_first_invariant_radius_mm",
     &InflationState::max_first_invariant_radius_mm},
};

std::string state_repr(const InflationState& s) {
  if (!s.ok())
    return fmt::format("<InflationState {} at pole_stretch={:.6g}: {}>",
                       to_string(s.status),
                       s.pole_stretch,
                       s.message);
  return fmt::format(
      "<InflationState pole_stretch={:.6g}, pressure_mpa={:.6g}, pole_height_mm={:.6g}, "
      "volume_mm3={:.6g}, max_first_invariant={:.6g}>",
      s.pole_stretch,
      s.pressure_mpa,
      s.pole_height_mm,
      s.volume_mm3,
      s.max_first_invariant);
}

std::string problem_repr(const InflationProblem& p) {
  return fmt::format(
      "InflationProblem(clamp_radius_mm={:g}, thickness_mm={:g}, material='{}', "
      "critical_i1={:g}, prestretch={:g})",
      p.clamp_radius_mm,
      p.thickness_mm,
      describe(p.material),
      p.critical_i1,
      p.prestretch);
}

void bind_types(py::module_& m) {
  py::class_<InflationProblem> problem(
      m,
      "InflationProblem",
      "The membrane of an inflation (bulge) test: clamp radius A [mm], thickness H [mm],\n"
      "material, the critical I1 at which it bursts and the equibiaxial pre-stretch L0 (>= 1:\n"
      "the stress-free disc of radius A / L0 clamped at A).  InflationProblem.of(problem)\n"
      "takes them from an indentation Problem.");
  problem
      .def(py::init([](double a,
                       double h,
                       const Material& material,
                       double critical_i1,
                       double prestretch) {
             return InflationProblem{a, h, material, critical_i1, prestretch};
           }),
           py::arg("clamp_radius_mm") = InflationProblem{}.clamp_radius_mm,
           py::arg("thickness_mm") = InflationProblem{}.thickness_mm,
           py::arg("material") = Material{},
           py::arg("critical_i1") = InflationProblem{}.critical_i1,
           py::arg("prestretch") = InflationProblem{}.prestretch)
      .def_static("of", &inflation_problem, py::arg("problem"), "The membrane of a Problem")
      .def_readwrite("clamp_radius_mm", &InflationProblem::clamp_radius_mm, "A [mm]")
      .def_readwrite("thickness_mm", &InflationProblem::thickness_mm, "H [mm]")
      .def_readwrite("material", &InflationProblem::material)
      .def_readwrite("critical_i1", &InflationProblem::critical_i1, "I1 at the burst")
      .def_readwrite("prestretch",
                     &InflationProblem::prestretch,
                     "equibiaxial pre-stretch L0 (>= 1); the flat state's pole stretch")
      .def(
          "validation_errors",
          [](const InflationProblem& p) { return validation_errors(p); },
          "Every problem with the input (ValidationError: attribute and message); empty if valid")
      .def(
          "validate",
          [](const InflationProblem& p) {
            if (const auto message = invalid_message(p); !message.empty())
              throw py::value_error(message);
          },
          "Raise ValueError listing every invalid parameter")
      .def("pressure_scale_mpa",
           &pressure_scale_mpa,
           "G H / A [MPa]: the normalised pressure is p / this")
      .def("__copy__", [](const InflationProblem& p) { return InflationProblem(p); })
      .def(
          "__deepcopy__",
          [](const InflationProblem& p, py::dict) { return InflationProblem(p); },
          py::arg("memo"))
      .def("__repr__", &problem_repr);

  py::class_<InflationState, Outcome> state(
      m, "InflationState", "One inflated equilibrium", py::dynamic_attr());
  state
      .def_readonly(
          "pole_stretch", &InflationState::pole_stretch, "equibiaxial stretch at the pole")
      .def_readonly("pressure_mpa", &InflationState::pressure_mpa, "p [MPa]")
      .def_readonly("normalized_pressure", &InflationState::normalized_pressure, "p A / (G H)")
      .def_readonly("pole_height_mm", &InflationState::pole_height_mm, "[mm]")
      .def_readonly("volume_mm3", &InflationState::volume_mm3, "enclosed volume [mm^3]")
      .def_readonly("stored_energy_mj", &InflationState::stored_energy_mj, "[mJ = N mm]")
      .def_readonly("pole_stress_mpa", &InflationState::pole_stress_mpa, "nominal, at the pole")
      .def_readonly(
          "pole_tension_n_per_mm", &InflationState::pole_tension_n_per_mm, "true line tension")
      .def_readonly("pole_curvature_radius_mm",
                    &InflationState::pole_curvature_radius_mm,
                    "radius of curvature at the pole [mm] (inf when flat)")
      .def_readonly("clamp_radial_stretch", &InflationState::clamp_radial_stretch)
      .def_readonly("clamp_slope_rad", &InflationState::clamp_slope_rad)
      .def_readonly("max_first_invariant", &InflationState::max_first_invariant)
      .def_readonly("max_first_invariant_reference_radius_mm",
                    &InflationState::max_first_invariant_reference_radius_mm,
                    "R of the largest I1 [mm] (0: the pole)")
      .def_readonly("max_first_invariant_radius_mm", &InflationState::max_first_invariant_radius_mm)
      .def_readonly("clamp_residual", &InflationState::clamp_residual)
      .def_readonly("shooting_evaluations", &InflationState::shooting_evaluations)
      .def_readonly("fields", &InflationState::fields)
      .def("__repr__", &state_repr);

  py::enum_<ExtremumKind>(m, "ExtremumKind", "A pressure maximum (limit point) or minimum")
      .value("Maximum", ExtremumKind::Maximum)
      .value("Minimum", ExtremumKind::Minimum)
      .def_property_readonly("token", [](ExtremumKind k) { return to_string(k); });

  py::class_<PressureExtremum>(m, "PressureExtremum", "A local extremum of the pressure")
      .def_readonly("kind", &PressureExtremum::kind)
      .def_readonly("state", &PressureExtremum::state)
      .def_readonly("pressure_slope_mpa",
                    &PressureExtremum::pressure_slope_mpa,
                    "dp/dlambda0 at the located stretch [MPa] (~0)")
      .def_readonly("curvature_mpa", &PressureExtremum::curvature_mpa, "d2p/dlambda0^2 [MPa]")
      .def("__repr__", [](const PressureExtremum& e) {
        return fmt::format("<PressureExtremum {} at pole_stretch={:.8g}, pressure_mpa={:.8g}>",
                           to_string(e.kind),
                           e.state.pole_stretch,
                           e.state.pressure_mpa);
      });

  py::class_<InflationBurst, Outcome>(
      m, "InflationBurst", "The first state whose largest I1 reaches the critical I1")
      .def_readonly("state", &InflationBurst::state)
      .def("__repr__", [](const InflationBurst& b) {
        if (!b.ok()) return "<InflationBurst not found: " + b.message + ">";
        return fmt::format("<InflationBurst at pole_stretch={:.8g}, pressure_mpa={:.8g}>",
                           b.state.pole_stretch,
                           b.state.pressure_mpa);
      });

  py::class_<InflationCurve, Outcome> curve(
      m,
      "InflationCurve",
      "The inflation curve, equally spaced in pole stretch; columns are numpy arrays",
      py::dynamic_attr());
  curve.def_readonly("end_pole_stretch", &InflationCurve::end_pole_stretch)
      .def_readonly("states", &InflationCurve::states, "list of InflationState (no fields)")
      .def_readonly("extrema", &InflationCurve::extrema, "list of PressureExtremum")
      .def_readonly("burst", &InflationCurve::burst)
      .def("__len__", [](const InflationCurve& c) { return c.states.size(); })
      .def(
          "columns",
          [](const InflationCurve& c) {
            py::dict d;
            for (const auto& [name, attribute, member] : kStateColumns)
              d[name] = column<double>(
                  c.states, [member = member](const InflationState& s) { return s.*member; });
            return d;
          },
          "The curve as a dict of arrays named like the CLI's CSV columns")
      .def("__repr__", [](const InflationCurve& c) {
        if (!c.ok()) return "<InflationCurve " + to_string(c.status) + ": " + c.message + ">";
        return fmt::format(
            "<InflationCurve {} states, pole_stretch 1 to {:.6g}, {} extrema, {}>",
            c.states.size(),
            c.end_pole_stretch,
            c.extrema.size(),
            c.burst.ok() ? fmt::format("burst at pressure_mpa={:.6g}", c.burst.state.pressure_mpa)
                         : std::string("no burst"));
      });
  for (const auto& [name, attribute, member] : kStateColumns)
    curve.def_property_readonly(attribute, [member = member](const InflationCurve& c) {
      return column<double>(c.states, [member](const InflationState& s) { return s.*member; });
    });

  py::class_<InflationAtPressure, Outcome>(
      m, "InflationAtPressure", "Every state at a pressure", py::dynamic_attr())
      .def_readonly("pressure_mpa", &InflationAtPressure::pressure_mpa)
      .def_readonly("max_pole_stretch", &InflationAtPressure::max_pole_stretch, "range searched")
      .def_readonly("states",
                    &InflationAtPressure::states,
                    "list of InflationState in increasing pole stretch; the first is reached "
                    "by inflating slowly from flat")
      .def_readonly("extrema", &InflationAtPressure::extrema)
      .def("__len__", [](const InflationAtPressure& a) { return a.states.size(); })
      .def("__repr__", [](const InflationAtPressure& a) {
        return fmt::format("<InflationAtPressure pressure_mpa={:.6g}: {} states>",
                           a.pressure_mpa,
                           a.states.size());
      });
}

}  // namespace

void bind_inflation(py::module_& m) {
  bind_types(m);

  m.def(
      "inflate_at_pole_stretch",
      [](const ProblemArg& arg, double pole_stretch, const std::optional<SolverOptions>& options) {
        const auto problem = checked(arg);
        auto s = released([&] {
          return inflate_at_pole_stretch(problem, pole_stretch, options.value_or(SolverOptions{}));
        });
        if (!s.ok())
          raise_solver_error(s.status,
                             s.message,
                             fmt::format("no inflated state at pole stretch {} ({}): {}",
                                         pole_stretch,
                                         to_string(s.status),
                                         s.message));
        return with_problem(std::move(s), problem);
      },
      py::arg("problem"),
      py::arg("pole_stretch"),
      py::arg("options") = py::none(),
      "The inflated state whose pole is stretched equibiaxially by pole_stretch (>= 1), with its\n"
      "fields.  problem: InflationProblem, or a Problem whose membrane is used.");

  m.def(
      "inflation_curve",
      [](const ProblemArg& arg,
         int points,
         double max_pole_stretch,
         int scan_points,
         const std::optional<SolverOptions>& options,
         const py::object& progress) {
        const auto problem = checked(arg);
        auto range = range_of(points, max_pole_stretch, scan_points);
        if (!progress.is_none()) {
          PyObject* callback = progress.ptr();  // borrowed: the argument outlives the call
          range.progress = [callback](int done, int total) {
            py::gil_scoped_acquire acquire;
            py::handle{callback}(done, total);
          };
        }
        auto c = released(
            [&] { return inflation_curve(problem, range, options.value_or(SolverOptions{})); });
        if (!c.ok())
          raise_solver_error(
              c.status,
              c.message,
              fmt::format("the inflation curve failed ({}): {}", to_string(c.status), c.message));
        return with_problem(std::move(c), problem);
      },
      py::arg("problem"),
      py::arg("points") = 100,
      py::arg("max_pole_stretch") = 0.0,
      py::arg("scan_points") = 60,
      py::arg("options") = py::none(),
      py::arg("progress") = py::none(),
      "The inflation curve: `points` states equally spaced in pole stretch from flat to the\n"
      "burst (or to max_pole_stretch when > 0), the pressure's extrema (limit points) and the\n"
      "burst.  progress(done, total) is called after each state if given.");

  m.def(
      "inflate_at_pressure",
      [](const ProblemArg& arg,
         double pressure_mpa,
         double max_pole_stretch,
         int scan_points,
         const std::optional<SolverOptions>& options) {
        const auto problem = checked(arg);
        auto a = released([&] {
          return inflate_at_pressure(problem,
                                     pressure_mpa,
                                     range_of(2, max_pole_stretch, scan_points),
                                     options.value_or(SolverOptions{}));
        });
        if (!a.ok())
          raise_solver_error(
              a.status,
              a.message,
              fmt::format("the states at pressure {} MPa could not be found ({}): {}",
                          pressure_mpa,
                          to_string(a.status),
                          a.message));
        return with_problem(std::move(a), problem);
      },
      py::arg("problem"),
      py::arg("pressure_mpa"),
      py::arg("max_pole_stretch") = 0.0,
      py::arg("scan_points") = 60,
      py::arg("options") = py::none(),
      "Every state at pressure pressure_mpa [MPa] up to the burst (or max_pole_stretch), in\n"
      "increasing pole stretch.  Raises SolverError (status NotReached) when none carries it.");

  m.def(
      "inflation_burst",
      [](const ProblemArg& arg, const std::optional<SolverOptions>& options) {
        const auto problem = checked(arg);
        auto b =
            released([&] { return inflation_burst(problem, options.value_or(SolverOptions{})); });
        if (!b.ok())
          raise_solver_error(b.state.ok() ? Status::NoConvergence : b.state.status,
                             b.message,
                             "no burst found: " + b.message);
        return b;
      },
      py::arg("problem"),
      py::arg("options") = py::none(),
      "The first state whose largest I1 reaches problem.critical_i1.");

  m.def(
      "pressure_extrema",
      [](const ProblemArg& arg,
         double max_pole_stretch,
         int scan_points,
         const std::optional<SolverOptions>& options) {
        const auto problem = checked(arg);
        auto e = released([&] {
          return pressure_extrema(
              problem, max_pole_stretch, scan_points, options.value_or(SolverOptions{}));
        });
        if (!e.ok())
          raise_solver_error(e.status, e.message, "the pressure extrema failed: " + e.message);
        return e.extrema;
      },
      py::arg("problem"),
      py::arg("max_pole_stretch"),
      py::arg("scan_points") = 60,
      py::arg("options") = py::none(),
      "The local maxima (limit points) and minima of the pressure for pole stretches up to\n"
      "max_pole_stretch, as a list of PressureExtremum.");
}

}  // namespace puncture::python
