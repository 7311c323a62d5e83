// The failure criteria (include/puncture/failure_criteria.hpp, failure.hpp, critical_value.hpp):
// CriticalFirstInvariant, MaxPrincipalStretch, CriticalEnergyDensity, CriticalTrueStress, their
// names, measures and assessment, and their critical values from inflation tests.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "puncture/critical_value.hpp"
#include "puncture/failure.hpp"

namespace puncture::python {

namespace {

template <class Criterion>
void bind_criterion(py::module_& m, const char* name, const char* field, double Criterion::*value,
                    const char* doc) {
  py::class_<Criterion>(m, name, doc)
      .def(py::init([value](double v) {
             Criterion c;
             c.*value = v;
             return c;
           }),
           py::arg(field))
      .def_readwrite(field, value)
      .def_property_readonly("name", [](const Criterion& c) { return criterion_name(c); })
      .def("__repr__", [name, field, value](const Criterion& c) {
        return fmt::format("{}({}={:g})", name, field, c.*value);
      });
}

}  // namespace

void bind_failure(py::module_& m) {
  bind_criterion<CriticalFirstInvariant>(
      m,
      "CriticalFirstInvariant",
      "critical_i1",
      &CriticalFirstInvariant::critical_i1,
      "Puncture where I1 first reaches critical_i1 (the paper's; CLI i1:<I1>)");
  bind_criterion<MaxPrincipalStretch>(
      m,
      "MaxPrincipalStretch",
      "critical_stretch",
      &MaxPrincipalStretch::critical_stretch,
      "Puncture where the largest principal stretch reaches critical_stretch (> 1; CLI "
      "max-stretch:<l>)");
  bind_criterion<CriticalEnergyDensity>(
      m,
      "CriticalEnergyDensity",
      "critical_mpa",
      &CriticalEnergyDensity::critical_mpa,
      "Puncture where the strain-energy density W per reference volume reaches critical_mpa "
      "[MPa = MJ/m^3] (CLI energy-density:<MPa>)");
  bind_criterion<CriticalTrueStress>(
      m,
      "CriticalTrueStress",
      "critical_mpa",
      &CriticalTrueStress::critical_mpa,
      "Puncture where the largest principal Cauchy stress lambda_i s_i reaches critical_mpa "
      "[MPa] (CLI true-stress:<MPa>)");

  py::class_<FailureAssessment>(m, "FailureAssessment", "A criterion evaluated along a state")
      .def_readonly("value", &FailureAssessment::value, "the measure where it is largest")
      .def_readonly("critical", &FailureAssessment::critical, "its critical value")
      .def_property_readonly(
          "part",
          [](const FailureAssessment& a) { return static_cast<int>(a.part); },
          "the part there: 1 free, 2 on the side, 3 under the tip")
      .def_readonly("reference_radius_mm", &FailureAssessment::reference_radius_mm)
      .def_readonly("radius_mm", &FailureAssessment::radius_mm)
      .def_property_readonly("ratio", &FailureAssessment::ratio, "value / critical")
      .def_property_readonly("failed", &FailureAssessment::failed, "value >= critical")
      .def("__repr__", [](const FailureAssessment& a) {
        return fmt::format(
            "<FailureAssessment value={:.6g} critical={:g} ratio={:.6g} at "
            "R={:.6g} mm>",
            a.value,
            a.critical,
            a.ratio(),
            a.reference_radius_mm);
      });

  m.def("criterion_names", &criterion_names, "The criteria's names: i1, max-stretch, ...");
  m.def(
      "criterion_from_name",
      [](const std::string& name, double value) {
        return raising_value_error([&] { return criterion_from_name(name, value); });
      },
      py::arg("name"),
      py::arg("value"),
      "The criterion called `name` (criterion_names()) with critical value `value`");
  m.def("criterion_name", &criterion_name, py::arg("criterion"));
  m.def("describe_criterion",
        py::overload_cast<const FailureCriterion&>(&describe),
        py::arg("criterion"));
  m.def("failure_criteria",
        &failure_criteria,
        py::arg("problem"),
        "Problem.criteria, or the critical I1 of Problem.critical_i1 alone when empty");
  m.def("measure_at",
        &measure_at,
        py::arg("criterion"),
        py::arg("material"),
        py::arg("lambda1"),
        py::arg("lambda2"),
        "The criterion's measure at the principal stretches (MPa for W, sigma)");
  m.def("assess",
        &assess,
        py::arg("criterion"),
        py::arg("state"),
        py::arg("material"),
        "The criterion's measure where it is largest in an Equilibrium (FailureAssessment)");

  py::class_<CriticalValueEstimate, Outcome>(
      m, "CriticalValueEstimate", "A criterion's critical value from inflation tests")
      .def_readonly("criterion", &CriticalValueEstimate::criterion, "with the mean as its value")
      .def_readonly("stretches", &CriticalValueEstimate::stretches)
      .def_readonly("pole_values", &CriticalValueEstimate::pole_values)
      .def_readonly("values", &CriticalValueEstimate::values)
      .def_readonly("radius_fractions", &CriticalValueEstimate::radius_fractions)
      .def_readonly("from_membrane", &CriticalValueEstimate::from_membrane)
      .def_readonly("mean", &CriticalValueEstimate::mean)
      .def_readonly("standard_deviation", &CriticalValueEstimate::standard_deviation)
      .def_readonly("standard_error", &CriticalValueEstimate::standard_error);
  m.def(
      "critical_value_from_inflation",
      [](const std::vector<BurstTest>& tests,
         const FailureCriterion& criterion,
         const Material& material,
         bool pole_only) {
        try {
          return critical_value_from_inflation(tests, criterion, material, pole_only);
        } catch (const InvalidInput&) {
          throw;
        } catch (const std::invalid_argument& e) {
          throw py::value_error(e.what());
        }
      },
      py::arg("tests"),
      py::arg("criterion"),
      py::arg("material") = Material{},
      py::arg("pole_only") = false,
      "The criterion's critical value from burst tests (list of BurstTest)");
}

}  // namespace puncture::python
