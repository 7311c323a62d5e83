// Friction mu' from the hole ratio (include/puncture/calibration.hpp): HoleMethod,
// FrictionEstimate and friction_from_hole.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <variant>

#include "bind_calibration.hpp"
#include "puncture/calibration.hpp"

namespace puncture::python::calibration {

void bind_friction(py::module_& m) {
  py::enum_<HoleMethod>(m, "HoleMethod", "How the hole ratio gives the friction (§4.2)")
      .value("AtMeasuredForce",
             HoleMethod::AtMeasuredForce,
             "the paper's: Part III stretch of the sliding state at the measured force")
      .value("AtPredictedPuncture",
             HoleMethod::AtPredictedPuncture,
             "force-free: Part III stretch at the predicted puncture")
      .def_property_readonly("token", [](HoleMethod h) { return to_string(h); });

  py::class_<FrictionEstimate>(m, "FrictionEstimate", "Friction mu' from the hole ratio")
      .def_readonly("method", &FrictionEstimate::method)
      .def_readonly("force_n", &FrictionEstimate::force_n, "the measured force (at-measured-force)")
      .def_readonly("stretch_at_zero_friction", &FrictionEstimate::stretch_at_zero_friction)
      .def_readonly("stretch_at_max_friction", &FrictionEstimate::stretch_at_max_friction)
      .def_readonly("max_friction", &FrictionEstimate::max_friction)
      .def_readonly("friction", &FrictionEstimate::friction, "Inversion for the ratio")
      .def_readonly("friction_for_ratio_plus_sd", &FrictionEstimate::friction_for_ratio_plus_sd)
      .def_readonly("friction_for_ratio_minus_sd", &FrictionEstimate::friction_for_ratio_minus_sd)
      .def_readonly("max_first_invariant", &FrictionEstimate::max_first_invariant)
      .def_readonly("puncture_force_n", &FrictionEstimate::puncture_force_n)
      .def_readonly("puncture_depth_mm", &FrictionEstimate::puncture_depth_mm)
      .def_readonly("scan", &FrictionEstimate::scan, "(mu', Part III stretch)");

  m.def(
      "friction_from_hole",
      [](const Problem& problem,
         double hole_ratio,
         double hole_ratio_sd,
         const std::optional<double>& puncture_force_n,
         const std::optional<std::variant<HoleMethod, std::string>>& method,
         const std::optional<SolverOptions>& options) {
        check_problem(problem, Unknown::Friction);
        require_finite(hole_ratio, "hole_ratio", "> 0", hole_ratio > 0.0);
        require_finite(hole_ratio_sd, "hole_ratio_sd", ">= 0", hole_ratio_sd >= 0.0);
        if (puncture_force_n)
          require_finite(*puncture_force_n, "puncture_force_n", "> 0 N", *puncture_force_n > 0.0);
        HoleMethod chosen =
            puncture_force_n ? HoleMethod::AtMeasuredForce : HoleMethod::AtPredictedPuncture;
        if (method) {
          if (const auto* h = std::get_if<HoleMethod>(&*method)) {
            chosen = *h;
          } else {
            const auto& text = std::get<std::string>(*method);
            if (text == to_string(HoleMethod::AtMeasuredForce))
              chosen = HoleMethod::AtMeasuredForce;
            else if (text == to_string(HoleMethod::AtPredictedPuncture))
              chosen = HoleMethod::AtPredictedPuncture;
            else
              throw py::value_error(fmt::format(
                  "method: expected HoleMethod, 'at-measured-force' or 'at-predicted-puncture', "
                  "got '{}'",
                  text));
          }
        }
        FrictionOptions o;
        if (options) o.solver = *options;
        const HoleMeasurement hole{hole_ratio, hole_ratio_sd, puncture_force_n};
        FrictionEstimate e;
        as_value_error([&] {
          py::gil_scoped_release release;
          e = friction_from_hole(problem, hole, chosen, o);  // ignores its friction
        });
        if (!e.friction.ok())
          raise_solver_error(e.friction.status, e.friction.message, e.friction.message);
        return e;
      },
      py::arg("problem"),
      py::arg("hole_ratio"),
      py::arg("hole_ratio_sd") = 0.0,
      py::arg("puncture_force_n") = py::none(),
      py::arg("method") = py::none(),
      py::arg("options") = py::none(),
      "Friction mu' from the hole a dry membrane leaves (paper §4.2): hole_ratio = indenter\n"
      "diameter / hole diameter = Part III stretch at puncture.  method: 'at-measured-force'\n"
      "(the paper's, needs puncture_force_n; the default when it is given) or\n"
      "'at-predicted-puncture' (force-free).  problem.friction is ignored.  Raises SolverError\n"
      "when no mu' in [0, 10] gives the ratio (as the CLI's exit code 2).");
}

}  // namespace puncture::python::calibration
