// The second method and the cross-checks (finite_element.hpp, verification.hpp): the finite
// elements at a list of depths, and `verify`, the table of `puncture verify`.  Invalid input
// raises ValueError with the library's message.  The GIL is released while the C++ code runs.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>
#include <vector>

#include "bindings.hpp"
#include "puncture/finite_element.hpp"
#include "puncture/reports.hpp"
#include "puncture/verification.hpp"

namespace puncture::python {

namespace {

std::optional<double> number_of(const VerificationCheck& c, double value) {
  return has_numbers(c) ? std::optional<double>(value) : std::nullopt;
}

}  // namespace

void bind_verification(py::module_& m) {
  py::enum_<FeContact>(m, "FeContact", "Contact the finite elements model")
      .value("Frictionless", FeContact::Frictionless, "sliding freely over tip, corner and side")
      .value("Held",
             FeContact::Held,
             "held: at the flat punch's edge, or on a smooth probe where the membrane touched (the "
             "stick stage)");
  py::enum_<Verdict>(m, "Verdict")
      .value("Pass", Verdict::Pass)
      .value("Fail", Verdict::Fail)
      .value("Skipped", Verdict::Skipped);

  py::class_<FePart>(m, "FePart", "One part of the meridian as the elements represent it")
      .def_property_readonly(
          "part",
          [](const FePart& p) { return static_cast<int>(p.part); },
          "1 free, 2 on the indenter's side, 3 under the tip")
      .def_readonly("start_radius_mm", &FePart::start_radius_mm)
      .def_readonly("end_radius_mm", &FePart::end_radius_mm)
      .def_readonly("logarithmic", &FePart::logarithmic)
      .def_readonly("elements", &FePart::elements)
      .def_property_readonly(
          "radius_mm",
          [](py::object self) { return view(self.cast<const FePart&>().radius_mm, self); },
          "current radius r at the nodes [mm]")
      .def_property_readonly(
          "deflection_mm",
          [](py::object self) { return view(self.cast<const FePart&>().deflection_mm, self); },
          "deflection z at the nodes [mm]")
      .def_property_readonly(
          "arclength_mm",
          [](py::object self) { return view(self.cast<const FePart&>().arclength_mm, self); },
          "on a smooth probe's profile: arclength from the pole at the nodes [mm] (else empty)");

  py::class_<FeState, Outcome>(m, "FeState", "A finite-element equilibrium at a prescribed depth")
      .def_readonly("contact", &FeState::contact)
      .def_readonly("order", &FeState::order)
      .def_readonly("depth_mm", &FeState::depth_mm)
      .def_readonly("force_n", &FeState::force_n)
      .def_readonly("normalized_force", &FeState::normalized_force)
      .def_readonly("stored_energy_nmm", &FeState::stored_energy_nmm, "elastic energy [N mm]")
      .def_readonly("volume_mm3",
                    &FeState::volume_mm3,
                    "under a gas pressure: the volume between the membrane and its clamp plane "
                    "[mm^3] (U - p V is the energy minimised); 0 without")
      .def_readonly("part_two", &FeState::part_two, "the membrane wraps the indenter's side")
      .def_readonly("part_three_stretch", &FeState::part_three_stretch)
      .def_readonly("corner_reference_radius_mm", &FeState::corner_reference_radius_mm)
      .def_readonly("part_two_top_reference_radius_mm", &FeState::part_two_top_reference_radius_mm)
      .def_readonly("contact_edge_radius_mm",
                    &FeState::contact_edge_radius_mm,
                    "current radius where the membrane leaves the probe [mm]")
      .def_readonly("largest_penetration_mm",
                    &FeState::largest_penetration_mm,
                    "smooth probe: deepest free node inside the probe [mm] (0 when none)")
      .def_readonly("max_first_invariant", &FeState::max_first_invariant)
      .def_readonly("unknowns", &FeState::unknowns)
      .def_readonly("parts", &FeState::parts)
      .def(
          "first_invariant",
          [](const FeState& s, int part, double reference_radius_mm) {
            if (part < 1 || part > 3)
              throw py::value_error(fmt::format("part: expected 1, 2 or 3, got {}", part));
            return fe_first_invariant(s, static_cast<MembranePart>(part), reference_radius_mm);
          },
          py::arg("part"),
          py::arg("reference_radius_mm"),
          "I1 at reference radius R [mm] inside part 1, 2 or 3; None outside it");

  m.def(
      "fe_solve_at_depths",
      [](const Problem& problem,
         const std::vector<double>& depths_mm,
         FeContact contact,
         int elements,
         int order) {
        check_problem(problem);
        FeOptions options;
        options.elements = elements;
        options.order = order;
        try {
          py::gil_scoped_release release;
          return fe_solve_at_depths(problem, depths_mm, contact, options);
        } catch (const std::invalid_argument& e) {
          throw py::value_error(e.what());
        }
      },
      py::arg("problem"),
      py::arg("depths_mm"),
      py::arg("contact") = FeContact::Frictionless,
      py::arg("elements") = 64,
      py::arg("order") = 2,
      "The second method: finite elements minimising the stored energy at increasing depths\n"
      "[mm], by continuation from the flat membrane (under a gas pressure: U - p V from the\n"
      "elements' own inflated dome, frictionless or on a smooth probe held where it\n"
      "touched).  Frictionless or held contact only\n"
      "(problem.friction and problem.stick are not used).  A list of FeState; one that did not\n"
      "converge says why in .message.");

  m.def(
      "fe_inflated_state",
      [](const Problem& problem, int elements, int order) {
        check_problem(problem);
        FeOptions options;
        options.elements = elements;
        options.order = order;
        try {
          py::gil_scoped_release release;
          return fe_inflated_state(problem, options);
        } catch (const std::invalid_argument& e) {
          throw py::value_error(e.what());
        }
      },
      py::arg("problem"),
      py::arg("elements") = 64,
      py::arg("order") = 2,
      "Under a gas pressure: the elements' inflated membrane before contact (U - p V\n"
      "minimised, depth 0), the start of fe_solve_at_depths.  An FeState.");

  py::class_<VerificationCheck>(m, "VerificationCheck", "One row of `puncture verify`")
      .def_readonly("group", &VerificationCheck::group)
      .def_readonly("quantity", &VerificationCheck::quantity)
      .def_readonly("condition", &VerificationCheck::condition)
      .def_property_readonly("shooting",
                             [](const VerificationCheck& c) { return number_of(c, c.shooting); })
      .def_property_readonly("second_method",
                             [](const VerificationCheck& c) { return number_of(c, c.reference); })
      .def_property_readonly("relative_difference",
                             [](const VerificationCheck& c) { return number_of(c, c.difference); })
      .def_property_readonly("tolerance",
                             [](const VerificationCheck& c) { return number_of(c, c.tolerance); })
      .def_readonly("verdict", &VerificationCheck::verdict)
      .def_readonly("note", &VerificationCheck::note)
      .def("__repr__", [](const VerificationCheck& c) {
        return fmt::format("<VerificationCheck {} | {} | {}: {}>",
                           c.group,
                           c.quantity,
                           c.condition,
                           to_string(c.verdict));
      });

  py::class_<VerificationReport, Outcome>(m, "VerificationReport")
      .def_readonly("checks", &VerificationReport::checks)
      .def_readonly("elements", &VerificationReport::elements)
      .def("count", &VerificationReport::count, py::arg("verdict"));

  m.def(
      "verify",
      [](const Problem& problem, int elements, int depths) {
        check_problem(problem);
        VerifyOptions options;
        options.elements = elements;
        options.depths = depths;
        try {
          py::gil_scoped_release release;
          return verify(problem, options);
        } catch (const std::invalid_argument& e) {
          throw py::value_error(e.what());
        }
      },
      py::arg("problem"),
      py::arg("elements") = 128,
      py::arg("depths") = 4,
      "The checks of `puncture verify` for this membrane: the finite elements at mu' = 0 and\n"
      "held, work = stored energy, and the Foppl limit.  A VerificationReport: .checks,\n"
      ".ok.  Takes seconds.");
  m.def("full_report",
        py::overload_cast<const VerificationReport&>(&full_report),
        py::arg("report"),
        "Every check with both values, the difference, the tolerance and the verdict");
}

}  // namespace puncture::python
