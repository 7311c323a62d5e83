// Critical I1 from inflation tests (include/puncture/calibration.hpp): BurstTest,
// CriticalI1Estimate, critical_i1_from_inflation and burst_tests_from_csv.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "bind_calibration.hpp"
#include "bindings.hpp"
#include "puncture/calibration.hpp"
#include "puncture/csv.hpp"

namespace puncture::python::calibration {

namespace {

// As the CLI's --burst-radii with --mark-radius.
std::vector<BurstTest> tests_from_radii(const std::vector<double>& radii, double mark) {
  require_finite(mark, "mark_radius_mm", "> 0 mm", mark > 0.0);
  std::vector<BurstTest> tests;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const double r = radii[i];
    if (!std::isfinite(r) || r <= 0.0)
      throw py::value_error(
          fmt::format("burst_radii_mm: value {} must be a finite number > 0 mm, got {}", i + 1, r));
    if (r < mark)
      throw py::value_error(
          fmt::format("burst_radii_mm: value {} ({} mm) is below the mark radius {} mm; an "
                      "inflated membrane stretches the mark",
                      i + 1,
                      r,
                      mark));
    tests.push_back({mark, r});
  }
  return tests;
}

// As the CLI's `calibrate critical-i1 FILE`.
std::vector<BurstTest> burst_tests_from_csv(const std::string& path,
                                            const std::optional<double>& mark) {
  if (mark) require_finite(*mark, "mark_radius_mm", "> 0 mm", *mark > 0.0);
  return as_value_error([&] {
    const auto table = read_numeric_csv(path, 1);
    if (!mark && !table.has("initial_radius_mm"))
      throw py::value_error(fmt::format(
          "mark_radius_mm: {} has no column initial_radius_mm, so the mark's initial radius "
          "[mm] must be given",
          path));
    if (mark && table.has("initial_radius_mm"))
      throw py::value_error(fmt::format(
          "mark_radius_mm: {} gives each test's initial_radius_mm; do not give it too", path));
    return burst_tests_from_table(table, mark);
  });
}

// With the membrane's law when given; a state the shooting does not find raises SolverError.
CriticalI1Estimate estimate(const std::vector<BurstTest>& tests,
                            const std::optional<MaterialLaw>& law) {
  auto e = as_value_error([&] {
    return law ? critical_i1_from_inflation(tests, *law) : critical_i1_from_inflation(tests);
  });
  if (!e.ok()) raise_solver_error(e.status, e.message, "critical I1: " + e.message);
  return e;
}

}  // namespace

void bind_critical_i1(py::module_& m) {
  py::class_<BurstTest>(m, "BurstTest", "One inflation test: the mark's radius before and at burst")
      .def(py::init([](double initial, double burst) {
             return BurstTest{initial, burst};
           }),
           py::arg("initial_radius_mm"),
           py::arg("burst_radius_mm"))
      .def_readwrite("initial_radius_mm", &BurstTest::initial_radius_mm, "[mm]")
      .def_readwrite("burst_radius_mm", &BurstTest::burst_radius_mm, "[mm]")
      .def("__repr__", [](const BurstTest& t) {
        return fmt::format("BurstTest(initial_radius_mm={:g}, burst_radius_mm={:g})",
                           t.initial_radius_mm,
                           t.burst_radius_mm);
      });

  py::class_<CriticalI1Estimate, Outcome>(
      m, "CriticalI1Estimate", "Critical I1 from inflation tests: the mean of the per-test I1")
      .def_property_readonly(
          "stretches",
          [](py::object self) {
            return view(self.cast<const CriticalI1Estimate&>().stretches, self);
          },
          "per test: burst radius / initial radius")
      .def_property_readonly(
          "first_invariants",
          [](py::object self) {
            return view(self.cast<const CriticalI1Estimate&>().first_invariants, self);
          },
          "per test: the membrane's largest I1 (the pole's without a law)")
      .def_property_readonly(
          "pole_first_invariants",
          [](py::object self) {
            return view(self.cast<const CriticalI1Estimate&>().pole_first_invariants, self);
          },
          "per test: 2 lambda^2 + lambda^-4, I1 at the pole")
      .def_property_readonly(
          "largest_i1_radius_fractions",
          [](py::object self) {
            return view(self.cast<const CriticalI1Estimate&>().largest_i1_radius_fractions, self);
          },
          "per test: where the largest I1 lies, R / A (0: the pole)")
      .def_readonly("from_membrane",
                    &CriticalI1Estimate::from_membrane,
                    "True when a law's inflated membrane was solved")
      .def_readonly("mean", &CriticalI1Estimate::mean, "the critical I1")
      .def_readonly("standard_deviation",
                    &CriticalI1Estimate::standard_deviation,
                    "sample sd (n - 1); None with one test")
      .def_readonly(
          "standard_error", &CriticalI1Estimate::standard_error, "sd / sqrt(n); None with one test")
      .def("__repr__", [](const CriticalI1Estimate& e) {
        return fmt::format("CriticalI1Estimate(mean={:.6g}, standard_deviation={}, tests={})",
                           e.mean,
                           e.standard_deviation ? fmt::format("{:.6g}", *e.standard_deviation)
                                                : std::string("None"),
                           e.stretches.size());
      });

  m.def("equibiaxial_first_invariant",
        &equibiaxial_first_invariant,
        py::arg("stretch"),
        "I1 = 2 lambda^2 + lambda^-4 of an equibiaxial stretch");
  m.def(
      "equibiaxial_stretch_for_first_invariant",
      [](double i1) {
        return as_value_error([&] { return equibiaxial_stretch_for_first_invariant(i1); });
      },
      py::arg("i1"),
      "The equibiaxial stretch >= 1 whose I1 is i1 (>= 3)");
  m.def(
      "critical_i1_from_inflation",
      [](const std::vector<BurstTest>& tests, const std::optional<MaterialLaw>& law) {
        return estimate(tests, law);
      },
      py::arg("tests"),
      py::arg("law") = py::none(),
      "Critical I1 from inflation tests (paper §2.3), a list of BurstTest.  With a law\n"
      "(Gent, NeoHookean, MooneyRivlin) each test's I1 is the largest of that membrane\n"
      "inflated until its pole is stretched as the mark; without, the pole's (the paper's).");
  m.def(
      "critical_i1_from_inflation",
      [](const py::array_t<double, py::array::forcecast>& burst_radii_mm,
         double mark_radius_mm,
         const std::optional<MaterialLaw>& law) {
        return estimate(
            tests_from_radii(to_vector(burst_radii_mm, "burst_radii_mm"), mark_radius_mm), law);
      },
      py::arg("burst_radii_mm"),
      py::arg("mark_radius_mm"),
      py::arg("law") = py::none(),
      "Critical I1 from the mark's radii at burst [mm] and its initial radius [mm], as the\n"
      "CLI's --burst-radii and --mark-radius (law: as above; the CLI's default is the\n"
      "paper's Gent, its --pole-only is law=None).");
  m.def("burst_tests_from_csv",
        &burst_tests_from_csv,
        py::arg("path"),
        py::arg("mark_radius_mm") = py::none(),
        "The inflation tests of a CSV file with a column burst_radius_mm and either\n"
        "initial_radius_mm or, for every test, mark_radius_mm (as `calibrate critical-i1 FILE`).");
}

}  // namespace puncture::python::calibration
