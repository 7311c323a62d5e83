// The failure criteria (include/puncture/failure_criteria.hpp, failure.hpp, critical_value.hpp):
// CriticalFirstInvariant, MaxPrincipalStretch, CriticalEnergyDensity, CriticalTrueStress,
// CriticalEnergyRelease, their names, measures and assessment, the energy release's balance
// (energy_release.hpp), and the critical values from inflation tests.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "puncture/critical_value.hpp"
#include "puncture/energy_release.hpp"
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

  bind_criterion<CriticalEnergyRelease>(
      m,
      "CriticalEnergyRelease",
      "tearing_energy_n_per_mm",
      &CriticalEnergyRelease::tearing_energy_n_per_mm,
      "Puncture when cutting the membrane along the corner's ring releases, at the same depth, "
      "the tearing energy Gamma 2 pi R_c H; Gamma [N/mm = kJ/m^2] > 0 (frictionless flat punch "
      "only; CLI energy-release:<N/mm>)");

  py::class_<EnergyRelease>(
      m, "EnergyRelease", "The energy-release criterion's balance on a state [mJ = N mm]")
      .def_readonly("stored_energy_mj",
                    &EnergyRelease::stored_energy_mj,
                    "U: the intact membrane's elastic energy (pre-stretch included)")
      .def_readonly("punctured_energy_mj",
                    &EnergyRelease::punctured_energy_mj,
                    "the cut membrane's elastic energy at the same depth")
      .def_readonly("cut_energy_mj", &EnergyRelease::cut_energy_mj, "Gamma 2 pi R_c H")
      .def_readonly("cut_reference_radius_mm", &EnergyRelease::cut_reference_radius_mm, "R_c")
      .def_readonly("collar_reference_radius_mm",
                    &EnergyRelease::collar_reference_radius_mm,
                    "R_j: the rings from R_c to it wrap the rod, meridionally slack")
      .def_readonly("hole_radius_mm", &EnergyRelease::hole_radius_mm)
      .def_property_readonly("released_energy_mj", &EnergyRelease::released_energy_mj)
      .def_property_readonly("ratio", &EnergyRelease::ratio, "released / cut_energy_mj")
      .def("__repr__", [](const EnergyRelease& b) {
        return fmt::format(
            "<EnergyRelease released={:.6g} mJ cost={:.6g} mJ ratio={:.6g} at R_c={:.6g} mm>",
            b.released_energy_mj(),
            b.cut_energy_mj,
            b.ratio(),
            b.cut_reference_radius_mm);
      });
  m.def(
      "energy_release",
      [](const Problem& problem, const Equilibrium& state, double tearing_energy_n_per_mm) {
        return raising_value_error(
            [&] { return energy_release(problem, state, tearing_energy_n_per_mm); });
      },
      py::arg("problem"),
      py::arg("state"),
      py::arg("tearing_energy_n_per_mm"),
      "The energy-release balance on a state of a frictionless flat punch (EnergyRelease)");

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
  m.def(
      "measure_at",
      [](const FailureCriterion& c, const Material& material, double l1, double l2) {
        return raising_value_error([&] { return measure_at(c, material, l1, l2); });
      },
      py::arg("criterion"),
      py::arg("material"),
      py::arg("lambda1"),
      py::arg("lambda2"),
      "The criterion's measure at the principal stretches (MPa for W, sigma)");
  m.def(
      "assess",
      [](const FailureCriterion& c, const Equilibrium& state, const Problem& problem) {
        return raising_value_error([&] { return assess(c, state, problem); });
      },
      py::arg("criterion"),
      py::arg("state"),
      py::arg("problem"),
      "Any criterion on a state of `problem` (FailureAssessment; the energy release needs it)");
  m.def(
      "assess",
      [](const FailureCriterion& c, const Equilibrium& state, const Material& material) {
        return raising_value_error([&] { return assess(c, state, material); });
      },
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
