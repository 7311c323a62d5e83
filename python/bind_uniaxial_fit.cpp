// Fit of a uniaxial tensile test (include/puncture/calibration.hpp): FitLaw, SpecimenGeometry,
// FittedParameter, UniaxialFit, uniaxial_points, uniaxial_points_from_csv and fit_uniaxial.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "bind_calibration.hpp"
#include "puncture/calibration.hpp"
#include "puncture/csv.hpp"

namespace puncture::python::calibration {

namespace {

using Points = std::pair<py::array_t<double>, py::array_t<double>>;

Points as_arrays(const std::vector<UniaxialPoint>& points) {
  return {column<double>(points, [](const UniaxialPoint& p) { return p.stretch; }),
          column<double>(points, [](const UniaxialPoint& p) { return p.nominal_stress_mpa; })};
}

FitLaw fit_law_of(const std::variant<FitLaw, std::string>& law) {
  if (const auto* l = std::get_if<FitLaw>(&law)) return *l;
  const auto& text = std::get<std::string>(law);
  for (const auto l : {FitLaw::Gent, FitLaw::NeoHookean, FitLaw::MooneyRivlin})
    if (text == to_string(l)) return l;
  throw py::value_error(fmt::format(
      "law: expected FitLaw, 'gent', 'neo-hookean' or 'mooney-rivlin', got '{}'", text));
}

UniaxialFit fit_arrays(const py::array_t<double, py::array::forcecast>& stretch,
                       const py::array_t<double, py::array::forcecast>& nominal_stress_mpa,
                       const std::variant<FitLaw, std::string>& law) {
  const auto l = to_vector(stretch, "stretch");
  const auto s = to_vector(nominal_stress_mpa, "nominal_stress_mpa");
  if (l.size() != s.size())
    throw py::value_error(fmt::format(
        "stretch and nominal_stress_mpa: need as many values, got {} and {}", l.size(), s.size()));
  std::vector<UniaxialPoint> data;
  for (std::size_t i = 0; i < l.size(); ++i) data.push_back({l[i], s[i]});
  const FitLaw chosen = fit_law_of(law);
  UniaxialFit fit;
  as_value_error([&] {
    py::gil_scoped_release release;
    fit = fit_uniaxial(data, chosen);
  });
  if (!fit.ok())
    raise_solver_error(fit.status,
                       fit.message,
                       fit.status == Status::NoConvergence
                           ? "the fit did not converge: " + fit.message
                           : fit.message);
  return fit;
}

}  // namespace

void bind_uniaxial(py::module_& m) {
  py::enum_<FitLaw>(m, "FitLaw", "Law fitted to a uniaxial test")
      .value("Gent", FitLaw::Gent)
      .value("NeoHookean", FitLaw::NeoHookean)
      .value("MooneyRivlin", FitLaw::MooneyRivlin)
      .def_property_readonly("token", [](FitLaw l) { return to_string(l); });

  py::class_<SpecimenGeometry>(m, "SpecimenGeometry", "Uniaxial specimen [mm]")
      .def(py::init([](double w, double t, double l) {
             return SpecimenGeometry{w, t, l};
           }),
           py::arg("width_mm"),
           py::arg("thickness_mm"),
           py::arg("gauge_length_mm"))
      .def_readwrite("width_mm", &SpecimenGeometry::width_mm)
      .def_readwrite("thickness_mm", &SpecimenGeometry::thickness_mm)
      .def_readwrite("gauge_length_mm", &SpecimenGeometry::gauge_length_mm);

  py::class_<FittedParameter>(m, "FittedParameter", "One fitted parameter")
      .def_readonly("name", &FittedParameter::name, "'G', 'J_lim' or 'alpha'")
      .def_readonly("unit", &FittedParameter::unit)
      .def_readonly("value", &FittedParameter::value, "None when the data give none")
      .def_readonly("standard_error", &FittedParameter::standard_error, "None when singular")
      .def_readonly("identifiable", &FittedParameter::identifiable)
      .def_readonly("note", &FittedParameter::note)
      .def("__repr__", [](const FittedParameter& p) {
        return fmt::format(
            "FittedParameter({}={}, standard_error={})",
            p.name,
            p.value ? fmt::format("{:.6g}", *p.value) : std::string("None"),
            p.standard_error ? fmt::format("{:.3g}", *p.standard_error) : std::string("None"));
      });

  py::class_<UniaxialFit, Outcome>(m, "UniaxialFit", "Least-squares fit of a uniaxial tensile test")
      .def_readonly("law", &UniaxialFit::law)
      .def_readonly("material", &UniaxialFit::material, "the fit as a Material; None if invalid")
      .def_readonly("parameters", &UniaxialFit::parameters, "G first")
      .def_readonly("inverse_j_lim", &UniaxialFit::inverse_j_lim)
      .def_readonly("inverse_j_lim_se", &UniaxialFit::inverse_j_lim_se)
      .def_readonly("j_lim_lower_bound", &UniaxialFit::j_lim_lower_bound)
      .def_readonly("max_i1_minus_3", &UniaxialFit::max_i1_minus_3)
      .def_readonly("stiffening_at_largest_stretch", &UniaxialFit::stiffening_at_largest_stretch)
      .def_readonly("rms_residual_mpa", &UniaxialFit::rms_residual_mpa)
      .def_readonly("residual_sd_mpa", &UniaxialFit::residual_sd_mpa)
      .def_readonly("points", &UniaxialFit::points)
      .def_readonly("iterations", &UniaxialFit::iterations)
      .def_property_readonly(
          "fitted_stress_mpa",
          [](py::object self) {
            return view(self.cast<const UniaxialFit&>().fitted_stress_mpa, self);
          },
          "the model at each data point [MPa]")
      .def(
          "parameter",
          [](const UniaxialFit& f, const std::string& name) {
            for (const auto& p : f.parameters)
              if (p.name == name) return p;
            throw py::key_error(name);
          },
          py::arg("name"),
          "The FittedParameter called name ('G', 'J_lim', 'alpha')");

  m.def(
      "uniaxial_points",
      [](const py::array_t<double, py::array::forcecast>& force_n,
         const py::array_t<double, py::array::forcecast>& displacement_mm,
         const SpecimenGeometry& specimen) {
        const auto f = to_vector(force_n, "force_n");
        const auto d = to_vector(displacement_mm, "displacement_mm");
        return as_arrays(as_value_error([&] { return uniaxial_points(f, d, specimen); }));
      },
      py::arg("force_n"),
      py::arg("displacement_mm"),
      py::arg("specimen"),
      "(stretch, nominal_stress_mpa) arrays from a force-displacement record:\n"
      "stretch = 1 + displacement / gauge length, stress = force / (width thickness).");
  m.def(
      "uniaxial_points_from_csv",
      [](const std::string& path, const std::optional<SpecimenGeometry>& specimen) {
        return as_arrays(as_value_error(
            [&] { return uniaxial_points_from_table(read_numeric_csv(path, 1), specimen); }, path));
      },
      py::arg("path"),
      py::arg("specimen") = py::none(),
      "(stretch, nominal_stress_mpa) arrays from a CSV file with the columns\n"
      "stretch,nominal_stress_mpa, or force_n,displacement_mm and the specimen (as the CLI's\n"
      "`fit uniaxial FILE`).");
  constexpr const char* fit_doc =
      "Fit G (and J_lim for 'gent', alpha for 'mooney-rivlin') to a uniaxial test (paper §4.1,\n"
      "Fig. 11) by Levenberg-Marquardt.  Raises SolverError when the fit does not converge.";
  m.def("fit_uniaxial",
        &fit_arrays,
        py::arg("stretch"),
        py::arg("nominal_stress_mpa"),
        py::arg("law") = "gent",
        fit_doc);
  // What uniaxial_points(_from_csv) return, passed as it comes.
  m.def(
      "fit_uniaxial",
      [](const Points& points, const std::variant<FitLaw, std::string>& law) {
        return fit_arrays(points.first, points.second, law);
      },
      py::arg("points"),
      py::arg("law") = "gent",
      "The same fit of the (stretch, nominal_stress_mpa) pair that uniaxial_points and\n"
      "uniaxial_points_from_csv return.");
}

}  // namespace puncture::python::calibration
