// The puncture band (include/puncture/puncture_band.hpp): BandParameter, ParameterRange,
// BandParameters, BandEvaluation, ParameterSensitivity, PunctureBand and puncture_band.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <array>
#include <optional>
#include <string>

#include "bind_calibration.hpp"
#include "puncture/puncture_band.hpp"

namespace puncture::python::calibration {

namespace {

std::optional<ParameterRange> range_of(const py::object& value, const char* name) {
  if (value.is_none()) return std::nullopt;
  if (py::isinstance<ParameterRange>(value)) return value.cast<ParameterRange>();
  try {
    const auto pair = value.cast<std::array<double, 2>>();
    return ParameterRange{pair[0], pair[1]};
  } catch (const py::cast_error&) {
    throw py::value_error(fmt::format("{}: expected a ParameterRange or (lower, upper), got {}",
                                      name,
                                      py::repr(value).cast<std::string>()));
  }
}

}  // namespace

void bind_band(py::module_& m) {
  py::enum_<BandParameter>(m, "BandParameter", "A calibrated parameter of the puncture band")
      .value("CriticalI1", BandParameter::CriticalI1)
      .value("Friction", BandParameter::Friction)
      .value("JLim", BandParameter::JLim)
      .value("ShearModulus", BandParameter::ShearModulus)
      .def_property_readonly("token", [](BandParameter p) { return to_token(p); })
      .def_property_readonly("description", [](BandParameter p) { return to_string(p); });

  py::class_<ParameterRange>(m, "ParameterRange", "An interval [lower, upper]")
      .def(py::init([](double lower, double upper) {
             return ParameterRange{lower, upper};
           }),
           py::arg("lower"),
           py::arg("upper"))
      .def_readwrite("lower", &ParameterRange::lower)
      .def_readwrite("upper", &ParameterRange::upper)
      .def("__repr__", [](const ParameterRange& r) {
        return fmt::format("ParameterRange(lower={:g}, upper={:g})", r.lower, r.upper);
      });
  m.def("plus_minus",
        &plus_minus,
        py::arg("mean"),
        py::arg("sd"),
        py::arg("k") = 1.0,
        "ParameterRange(mean - k sd, mean + k sd)");
  m.def("documented_force_direction",
        &documented_force_direction,
        py::arg("parameter"),
        "+1 / -1: how the parameter moves the puncture force (docs/model.md)");
  m.def("documented_depth_direction",
        &documented_depth_direction,
        py::arg("parameter"),
        "+1 / -1 / 0: how the parameter moves the puncture depth");

  py::class_<BandParameters>(m, "BandParameters", "The four parameters of one evaluation")
      .def_readonly("critical_i1", &BandParameters::critical_i1)
      .def_readonly("friction", &BandParameters::friction)
      .def_readonly("j_lim", &BandParameters::j_lim, "None when the law is not Gent")
      .def_readonly("shear_modulus_mpa", &BandParameters::shear_modulus_mpa)
      .def("value", &BandParameters::value, py::arg("parameter"));
  py::class_<BandEvaluation, Outcome>(m, "BandEvaluation", "One predicted puncture of the band")
      .def_readonly("parameters", &BandEvaluation::parameters)
      .def_property_readonly("force_n",
                             [](const BandEvaluation& e) {
                               return e.ok() ? std::optional<double>(e.force_n) : std::nullopt;
                             })
      .def_property_readonly("depth_mm",
                             [](const BandEvaluation& e) {
                               return e.ok() ? std::optional<double>(e.depth_mm) : std::nullopt;
                             })
      .def_property_readonly("part_three_stretch",
                             [](const BandEvaluation& e) {
                               return e.ok() ? std::optional<double>(e.part_three_stretch)
                                             : std::nullopt;
                             })
      .def_readonly("crack_location", &BandEvaluation::crack_location);
  py::class_<ParameterSensitivity>(
      m, "ParameterSensitivity", "One parameter over its interval, the others nominal")
      .def_readonly("parameter", &ParameterSensitivity::parameter)
      .def_readonly("nominal", &ParameterSensitivity::nominal)
      .def_readonly("range", &ParameterSensitivity::range)
      .def_readonly("at_lower", &ParameterSensitivity::at_lower)
      .def_readonly("at_upper", &ParameterSensitivity::at_upper)
      .def_readonly("samples", &ParameterSensitivity::samples)
      .def_readonly("force_change_n", &ParameterSensitivity::force_change_n)
      .def_readonly("depth_change_mm", &ParameterSensitivity::depth_change_mm)
      .def_readonly("force_direction", &ParameterSensitivity::force_direction)
      .def_readonly("depth_direction", &ParameterSensitivity::depth_direction)
      .def_readonly("force_monotone", &ParameterSensitivity::force_monotone)
      .def_readonly("depth_monotone", &ParameterSensitivity::depth_monotone)
      .def_readonly("force_variance_share", &ParameterSensitivity::force_variance_share);
  py::class_<PunctureBand, Outcome>(
      m, "PunctureBand", "The puncture force and depth over the intervals")
      .def_readonly("nominal", &PunctureBand::nominal)
      .def_readonly("sensitivities", &PunctureBand::sensitivities)
      .def_readonly("corners", &PunctureBand::corners)
      .def_readonly("force_min_n", &PunctureBand::force_min_n)
      .def_readonly("force_max_n", &PunctureBand::force_max_n)
      .def_readonly("depth_min_mm", &PunctureBand::depth_min_mm)
      .def_readonly("depth_max_mm", &PunctureBand::depth_max_mm)
      .def_readonly("force_min_corner", &PunctureBand::force_min_corner)
      .def_readonly("force_max_corner", &PunctureBand::force_max_corner)
      .def_readonly("depth_min_corner", &PunctureBand::depth_min_corner)
      .def_readonly("depth_max_corner", &PunctureBand::depth_max_corner)
      .def_readonly("force_half_range_rss_n", &PunctureBand::force_half_range_rss_n)
      .def_readonly("dominant", &PunctureBand::dominant)
      .def_readonly("consistent_with_documented_directions",
                    &PunctureBand::consistent_with_documented_directions)
      .def_readonly("warnings", &PunctureBand::warnings)
      .def("__repr__", [](const PunctureBand& b) {
        if (!b.force_min_n) return std::string("PunctureBand(empty)");
        return fmt::format("PunctureBand(force_n={:.5g} in [{:.5g}, {:.5g}], corners={})",
                           b.nominal.force_n,
                           *b.force_min_n,
                           *b.force_max_n,
                           b.corners.size());
      });

  m.def(
      "puncture_band",
      [](const Problem& problem,
         const py::object& critical_i1,
         const py::object& friction,
         const py::object& j_lim,
         const py::object& shear_modulus_mpa,
         int samples_per_range,
         const std::optional<SolverOptions>& options) {
        check_problem(problem);
        BandRanges ranges;
        ranges.critical_i1 = range_of(critical_i1, "critical_i1");
        ranges.friction = range_of(friction, "friction");
        ranges.j_lim = range_of(j_lim, "j_lim");
        ranges.shear_modulus_mpa = range_of(shear_modulus_mpa, "shear_modulus_mpa");
        BandOptions o;
        o.samples_per_range = samples_per_range;
        if (options) o.solver = *options;
        PunctureBand band;
        as_value_error([&] {
          py::gil_scoped_release release;
          band = puncture_band(problem, ranges, o);
        });
        if (!band.nominal.ok())
          raise_solver_error(
              band.nominal.status,
              band.nominal.message,
              "no puncture point at the nominal parameters: " + band.nominal.message);
        return band;
      },
      py::arg("problem"),
      py::arg("critical_i1") = py::none(),
      py::arg("friction") = py::none(),
      py::arg("j_lim") = py::none(),
      py::arg("shear_modulus_mpa") = py::none(),
      py::arg("samples_per_range") = 5,
      py::arg("options") = py::none(),
      "The predicted puncture at the problem's parameters and its band over intervals of the\n"
      "critical I1, friction, Gent J_lim and G (each a ParameterRange, (lower, upper), or\n"
      "plus_minus(mean, sd); None keeps the problem's value), with the one-at-a-time\n"
      "sensitivities and the dominant parameter (as `puncture calibrate band`).  A corner\n"
      "where the solver fails is in .warnings and .ok() is False; SolverError when the\n"
      "nominal problem has no puncture point.");
}

}  // namespace puncture::python::calibration
