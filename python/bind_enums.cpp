// The library's enums.  Each has a `token`: the name the CLI writes in CSV and JSON.
#include "bindings.hpp"
#include "puncture/curve_events.hpp"
#include "puncture/equilibrium.hpp"

namespace puncture::python {

void bind_enums(py::module_& m) {
  py::enum_<Stage>(m, "Stage", "Loading stage: membrane held at the indenter's edge, or sliding")
      .value("Stick", Stage::Stick)
      .value("Slip", Stage::Slip)
      .def_property_readonly("token", [](Stage s) { return to_string(s); });

  py::enum_<Configuration>(m, "Configuration", "Which parts the membrane is made of")
      .value("Unloaded", Configuration::Unloaded, "flat membrane, zero force")
      .value("Stick", Configuration::Stick, "held at the indenter's edge; Part III unstretched")
      .value("SlipWithoutPartTwo",
             Configuration::SlipWithoutPartTwo,
             "Part III stretched, Part I leaves from the corner")
      .value("SlipWithPartTwo",
             Configuration::SlipWithPartTwo,
             "Part III, the corner wrapped, Part II on the indenter's side, then Part I")
      .value("PartialSlip",
             Configuration::PartialSlip,
             "after a coulomb release: a held core, a slipping annulus, then Part I")
      .def_property_readonly("token", [](Configuration c) { return to_token(c); })
      .def_property_readonly("description", [](Configuration c) { return to_string(c); });

  py::enum_<CurveEventKind>(m, "CurveEventKind", "An event along the loading curve")
      .value("ForceMaximum",
             CurveEventKind::ForceMaximum,
             "dF/d(depth) = 0, the force falls after: force control snaps through")
      .value("ContactShrinks",
             CurveEventKind::ContactShrinks,
             "the contact's edge moves back towards the tip as the probe goes deeper")
      .value("SnapThrough",
             CurveEventKind::SnapThrough,
             "the depth turns back (a fold): depth control snaps through to another state")
      .def_property_readonly("token", [](CurveEventKind k) { return to_token(k); })
      .def_property_readonly("description", [](CurveEventKind k) { return to_string(k); });

  py::enum_<FailureMode>(m, "FailureMode", "Which failure of a pre-tensioned membrane comes first")
      .value("LocalPuncture", FailureMode::LocalPuncture, "the criterion is met first at the probe")
      .value("GlobalBurst",
             FailureMode::GlobalBurst,
             "the criterion is met first in the free membrane, away from the probe")
      .value("GlobalLimitPoint",
             FailureMode::GlobalLimitPoint,
             "the force reaches a maximum before puncture: the membrane snaps through or bursts")
      .def_property_readonly("token", [](FailureMode f) { return to_token(f); })
      .def_property_readonly("description", [](FailureMode f) { return to_string(f); });

  py::class_<ValidationError>(m,
                              "ValidationError",
                              "One problem with the input: the attribute (or argument) it is about "
                              "and what is wrong")
      .def_readonly("parameter", &ValidationError::parameter, "e.g. 'geometry.clamp_radius_mm'")
      .def_readonly("message", &ValidationError::message)
      .def("__repr__", [](const ValidationError& e) { return e.parameter + ": " + e.message; });
  py::enum_<Status>(m, "Status", "Outcome of a solve")
      .value("Converged", Status::Converged)
      .value("NoConvergence", Status::NoConvergence)
      .value("BeyondLocking", Status::BeyondLocking)
      .value("LimitLoad", Status::LimitLoad)
      .value("StickWrapsSide", Status::StickWrapsSide)
      .value("NotReached", Status::NotReached)
      .value("Incomplete", Status::Incomplete)
      .value("ChecksFailed", Status::ChecksFailed)
      .value("OutsideModel", Status::OutsideModel)
      .value("OnBound", Status::OnBound)
      .value("Wrinkles", Status::Wrinkles)
      .def_property_readonly("token", [](Status s) { return to_string(s); })
      .def_property_readonly(
          "failure_kind", [](Status s) { return failure_kind(s); }, "FailureKind of this status");
  py::enum_<FailureKind>(m,
                         "FailureKind",
                         "Why a result failed: Physical (the membrane has no such state: change "
                         "the input), Numerical (the solver did not converge: a bug to report), "
                         "OutsideModel (the model does not cover the state); None when ok")
      .value("None_", FailureKind::None)
      .value("Physical", FailureKind::Physical)
      .value("Numerical", FailureKind::Numerical)
      .value("OutsideModel", FailureKind::OutsideModel)
      .def_property_readonly("token", [](FailureKind k) { return to_token(k); });
  py::class_<Outcome>(m,
                      "Outcome",
                      "What every result reports about itself: status, message and ok.  Invalid "
                      "input raises ValueError instead.")
      .def_readonly("status", &Outcome::status)
      .def_readonly("message", &Outcome::message, "why, when not ok; a warning (or empty) when ok")
      .def_property_readonly(
          "ok", &Outcome::ok, "True when the result is usable (status == Status.Converged)")
      .def_property_readonly("failure_kind",
                             &Outcome::failure_kind,
                             "FailureKind.Physical, .Numerical or .OutsideModel when not ok");

  py::enum_<StickRule>(
      m, "StickRule", "When a membrane held at the indenter's edge starts to slide")
      .value("None_", StickRule::None, "Coulomb friction only: slides from the first touch")
      .value("Force", StickRule::Force, "held until the force reaches the threshold [N]")
      .value("Depth", StickRule::Depth, "held until the depth reaches the threshold [mm]")
      .value("EdgeTension",
             StickRule::EdgeTension,
             "held until the radial line tension at the edge reaches the threshold [N/mm]")
      .value("Always", StickRule::Always, "never slides")
      .value("Coulomb",
             StickRule::Coulomb,
             "curved probes: held while the friction (mu times the contact pressure) holds "
             "every held point")
      .def_property_readonly("token", [](StickRule r) { return to_string(r); });

  py::enum_<PartTwoEquation>(m, "PartTwoEquation", "Equilibrium equation of Part II")
      .value("RingBalance", PartTwoEquation::RingBalance, "vertical balance of a ring (default)")
      .value("PaperEq18", PartTwoEquation::PaperEq18, "the paper's Eq. 18 as printed")
      .def_property_readonly("token", [](PartTwoEquation e) { return to_string(e); });
}

}  // namespace puncture::python
