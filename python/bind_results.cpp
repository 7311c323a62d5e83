// What the solver returns: one equilibrium with its fields along the membrane, the loading curve
// and the puncture point.  Arrays are numpy; the solve functions attach the problem they solved
// as `.problem`.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <limits>

#include "bindings.hpp"
#include "puncture/equilibrium.hpp"
#include "puncture/loading_curve.hpp"
#include "puncture/reports.hpp"

namespace puncture::python {

namespace {

using Column = std::vector<double> MembraneFields::*;

// The fields with the CLI's CSV column names.
constexpr std::pair<const char*, Column> kFieldColumns[] = {
    {"R_mm", &MembraneFields::reference_radius_mm},
    {"r_mm", &MembraneFields::radius_mm},
    {"z_mm", &MembraneFields::deflection_mm},
    {"slope_rad", &MembraneFields::slope_rad},
    {"lambda1", &MembraneFields::radial_stretch},
    {"lambda2", &MembraneFields::hoop_stretch},
    {"lambda3", &MembraneFields::thickness_stretch},
    {"s1_mpa", &MembraneFields::radial_stress_mpa},
    {"s2_mpa", &MembraneFields::hoop_stress_mpa},
    {"I1", &MembraneFields::first_invariant},
    {"contact_pressure_mpa", &MembraneFields::contact_pressure_mpa},
    {"friction_traction_mpa", &MembraneFields::friction_traction_mpa},
};

// The part numbers as a new int array (the parts are an enum in C++).
py::array_t<int> part_numbers(const MembraneFields& f) {
  return column<int>(f.part, [](MembranePart p) { return static_cast<int>(p); });
}

void field(py::class_<MembraneFields>& c, const char* name, Column member, const char* doc) {
  c.def_property_readonly(
      name,
      [member](py::object self) { return view(self.cast<const MembraneFields&>().*member, self); },
      doc);
}

using PointValue = double CurvePoint::*;

void curve_column(py::class_<LoadingCurve, Outcome>& c, const char* name, PointValue member,
                  const char* doc) {
  c.def_property_readonly(
      name,
      [member](const LoadingCurve& curve) {
        return column<double>(curve.points, [member](const CurvePoint& p) { return p.*member; });
      },
      doc);
}

// A member object of a result, carrying its owner's `.problem` along.
template <class Owner, class Member>
py::object member_with_problem(py::object self, Member Owner::*member) {
  auto& owner = self.cast<Owner&>();
  py::object out = py::cast(&(owner.*member), py::return_value_policy::reference_internal, self);
  if (py::hasattr(self, "problem")) out.attr("problem") = self.attr("problem");
  return out;
}

std::string equilibrium_repr(const Equilibrium& e) {
  return "<Equilibrium " + brief_report(e) + ">";
}

}  // namespace

void bind_results(py::module_& m) {
  py::class_<MembraneFields> fields(
      m,
      "MembraneFields",
      "Fields along the meridian from the centre (R = 0) to the clamp (R = A), one value per\n"
      "sample, for indentation and inflation alike; read-only numpy arrays.");
  fields
      .def_property_readonly(
          "part",
          [](const MembraneFields& f) { return part_numbers(f); },
          "1 free, 2 on the indenter's side, 3 under the tip (an inflated membrane: all 1)")
      .def("__len__", &MembraneFields::size)
      .def(
          "columns",
          [](py::object self) {
            const auto& f = self.cast<const MembraneFields&>();
            py::dict d;
            d["part"] = part_numbers(f);
            for (const auto& [name, member] : kFieldColumns) d[name] = view(f.*member, self);
            return d;
          },
          "The fields as a dict of arrays named like the CLI's CSV columns");
  field(fields,
        "reference_radius_mm",
        &MembraneFields::reference_radius_mm,
        "R, position in the flat reference state [mm]");
  field(fields, "radius_mm", &MembraneFields::radius_mm, "r, current distance from the axis [mm]");
  field(fields,
        "deflection_mm",
        &MembraneFields::deflection_mm,
        "z, displacement from the clamp plane along the load: below it in the indenter's\n"
        "direction when indented, the height above it when inflated [mm]");
  field(fields,
        "slope_rad",
        &MembraneFields::slope_rad,
        "phi, angle of the meridian to the clamp plane, positive where it returns toward the\n"
        "clamp plane going outward [rad]");
  field(fields, "radial_stretch", &MembraneFields::radial_stretch, "lambda1 (meridional)");
  field(fields, "hoop_stretch", &MembraneFields::hoop_stretch, "lambda2 = r / R");
  field(fields,
        "thickness_stretch",
        &MembraneFields::thickness_stretch,
        "lambda3 = 1 / (lambda1 lambda2)");
  field(fields,
        "radial_stress_mpa",
        &MembraneFields::radial_stress_mpa,
        "s1, nominal radial stress [MPa]");
  field(
      fields, "hoop_stress_mpa", &MembraneFields::hoop_stress_mpa, "s2, nominal hoop stress [MPa]");
  field(fields,
        "first_invariant",
        &MembraneFields::first_invariant,
        "I1 = lambda1^2 + lambda2^2 + lambda3^2");
  field(fields,
        "contact_pressure_mpa",
        &MembraneFields::contact_pressure_mpa,
        "contact pressure in Part II (true, per current area) [MPa], else 0");
  field(fields,
        "friction_traction_mpa",
        &MembraneFields::friction_traction_mpa,
        "friction traction in Part II [MPa], else 0");

  py::class_<ChamberGas>(m, "ChamberGas", "A sealed chamber's gas in one state")
      .def_readonly("pressure_mpa", &ChamberGas::pressure_mpa, "gauge pressure p [MPa]")
      .def_readonly("volume_mm3",
                    &ChamberGas::volume_mm3,
                    "V, the volume between the membrane and its clamp plane [mm^3]")
      .def("__repr__", [](const ChamberGas& g) {
        return fmt::format(
            "<ChamberGas pressure_mpa={:.6g}, volume_mm3={:.6g}>", g.pressure_mpa, g.volume_mm3);
      });

  py::class_<Equilibrium, Outcome>(m, "Equilibrium", "One equilibrium state", py::dynamic_attr())
      .def_readonly("configuration", &Equilibrium::configuration)
      .def_readonly("stage", &Equilibrium::stage)
      .def_readonly("force_n", &Equilibrium::force_n, "indenter force F [N]")
      .def_readonly("normalized_force", &Equilibrium::normalized_force, "F / (2 pi G H A)")
      .def_readonly("depth_mm", &Equilibrium::depth_mm, "depth of the tip below the clamp [mm]")
      .def_readonly("part_three_stretch",
                    &Equilibrium::part_three_stretch,
                    "equibiaxial stretch under the tip")
      .def_readonly("corner_reference_radius_mm",
                    &Equilibrium::corner_reference_radius_mm,
                    "R of the material at the corner [mm]")
      .def_readonly("part_two_top_reference_radius_mm",
                    &Equilibrium::part_two_top_reference_radius_mm,
                    "R at the Part II / Part I boundary [mm]")
      .def_readonly("part_two_length_mm",
                    &Equilibrium::part_two_length_mm,
                    "current length of Part II along the side [mm]")
      .def_readonly("corner_slope_rad",
                    &Equilibrium::corner_slope_rad,
                    "slope of Part I where it leaves the indenter [rad]")
      .def_readonly("corner_tension_ratio",
                    &Equilibrium::corner_tension_ratio,
                    "s1 just outside the corner / s1 in Part III (inf for a held membrane)")
      .def_readonly("slip_front_reference_radius_mm",
                    &Equilibrium::slip_front_reference_radius_mm,
                    "partial slip: reference radius of the slip front [mm] (0 otherwise)")
      .def_readonly("slip_front_radius_mm",
                    &Equilibrium::slip_front_radius_mm,
                    "partial slip: current radius of the slip front [mm] (0 otherwise)")
      .def_readonly("max_first_invariant", &Equilibrium::max_first_invariant, "largest I1")
      .def_readonly("max_first_invariant_reference_radius_mm",
                    &Equilibrium::max_first_invariant_reference_radius_mm,
                    "reference radius R of the largest I1 [mm]")
      .def_readonly("max_first_invariant_radius_mm",
                    &Equilibrium::max_first_invariant_radius_mm,
                    "current radius r of the largest I1 [mm]")
      .def_readonly("beyond_puncture",
                    &Equilibrium::beyond_puncture,
                    "True when the failure criterion is exceeded: loaded to this state the "
                    "membrane would already have punctured")
      .def_readonly("clamp_residual", &Equilibrium::clamp_residual)
      .def_readonly("shooting_evaluations", &Equilibrium::shooting_evaluations)
      .def_readonly("fields", &Equilibrium::fields)
      .def_readonly("gas",
                    &Equilibrium::gas,
                    "over a sealed chamber (Preload.gas_volume_mm3) its gas (ChamberGas), else "
                    "None")
      .def("__repr__", &equilibrium_repr);

  py::class_<CurvePoint>(m, "CurvePoint", "One point of the loading curve")
      .def_readonly("depth_mm", &CurvePoint::depth_mm)
      .def_readonly("force_n", &CurvePoint::force_n)
      .def_readonly("normalized_force", &CurvePoint::normalized_force)
      .def_readonly("stage", &CurvePoint::stage)
      .def_readonly("configuration", &CurvePoint::configuration)
      .def_readonly("part_three_stretch", &CurvePoint::part_three_stretch)
      .def_readonly("part_two_length_mm", &CurvePoint::part_two_length_mm)
      .def_readonly("corner_slope_rad", &CurvePoint::corner_slope_rad)
      .def_readonly("max_first_invariant", &CurvePoint::max_first_invariant)
      .def_readonly("beyond_puncture",
                    &CurvePoint::beyond_puncture,
                    "True past the puncture point (the model's continuation)")
      .def_readonly("gas", &CurvePoint::gas, "a sealed chamber's gas (ChamberGas), else None")
      .def_readonly("contact_edge_radius_mm",
                    &CurvePoint::contact_edge_radius_mm,
                    "current radius where the membrane leaves the probe [mm]")
      .def_readonly("contact_edge_height_mm",
                    &CurvePoint::contact_edge_height_mm,
                    "height of that edge above the probe's tip [mm]")
      .def_readonly("slip_front_reference_radius_mm",
                    &CurvePoint::slip_front_reference_radius_mm,
                    "partial slip: reference radius of the slip front [mm] (0 otherwise)")
      .def_readonly("slip_front_radius_mm",
                    &CurvePoint::slip_front_radius_mm,
                    "partial slip: current radius of the slip front [mm] (0 otherwise)")
      .def("__repr__", [](const CurvePoint& p) {
        return fmt::format("<CurvePoint depth_mm={:.6g}, force_n={:.6g}, {}>",
                           p.depth_mm,
                           p.force_n,
                           to_string(p.configuration));
      });

  py::class_<StickSlipSwitch>(
      m, "StickSlipSwitch", "The stick -> slip switch along a displacement-controlled curve")
      .def_readonly("occurs", &StickSlipSwitch::occurs)
      .def_readonly("depth_mm", &StickSlipSwitch::depth_mm)
      .def_readonly("force_stuck_n", &StickSlipSwitch::force_stuck_n, "force just before [N]")
      .def_readonly(
          "force_sliding_n", &StickSlipSwitch::force_sliding_n, "force just after, sliding [N]")
      .def("__repr__", [](const StickSlipSwitch& s) {
        if (!s.occurs) return std::string("<StickSlipSwitch: none>");
        return fmt::format("<StickSlipSwitch at depth_mm={:.6g}: force_n {:.6g} -> {:.6g}>",
                           s.depth_mm,
                           s.force_stuck_n,
                           s.force_sliding_n);
      });

  py::class_<CurveEvent>(m, "CurveEvent", "An event along the loading curve, located")
      .def_readonly("kind", &CurveEvent::kind)
      .def_readonly("depth_mm", &CurveEvent::depth_mm, "where it starts [mm]")
      .def_readonly("force_n", &CurveEvent::force_n, "the force there [N]")
      .def_readonly("end_depth_mm",
                    &CurveEvent::end_depth_mm,
                    "force maximum: where the curve carries the force again; contact shrinks: "
                    "where it grows again [mm]; None beyond the curve")
      .def_readonly("contact_reach_mm",
                    &CurveEvent::contact_reach_mm,
                    "the contact edge's radius plus its height above the tip [mm]")
      .def_readonly("depth_uncertainty_mm", &CurveEvent::depth_uncertainty_mm)
      .def_readonly("force_after_n",
                    &CurveEvent::force_after_n,
                    "snap-through: the landing state's force at that depth [N]; else None")
      .def_readonly("description", &CurveEvent::description)
      .def("__repr__", [](const CurveEvent& e) {
        return fmt::format("<CurveEvent {} at depth_mm={:.6g}, force_n={:.6g}>",
                           to_token(e.kind),
                           e.depth_mm,
                           e.force_n);
      });

  py::class_<FailureVerdict>(
      m, "FailureVerdict", "Which failure of a pre-tensioned membrane comes first, and where")
      .def_readonly("mode", &FailureVerdict::mode)
      .def_readonly("depth_mm", &FailureVerdict::depth_mm)
      .def_readonly("force_n", &FailureVerdict::force_n)
      .def_readonly("where", &FailureVerdict::where)
      .def_readonly("reason", &FailureVerdict::reason)
      .def("__repr__", [](const FailureVerdict& v) {
        return fmt::format("<FailureVerdict {} at depth_mm={:.6g}, force_n={:.6g}>",
                           to_token(v.mode),
                           v.depth_mm,
                           v.force_n);
      });

  py::class_<PuncturePrediction, Outcome>(
      m, "PuncturePrediction", "The predicted puncture point", py::dynamic_attr())
      .def_readonly("force_n", &PuncturePrediction::force_n)
      .def_readonly("normalized_force", &PuncturePrediction::normalized_force)
      .def_readonly("depth_mm", &PuncturePrediction::depth_mm)
      .def_readonly("stage", &PuncturePrediction::stage)
      .def_readonly("configuration", &PuncturePrediction::configuration)
      .def_readonly("part_three_stretch", &PuncturePrediction::part_three_stretch)
      .def_readonly("crack_reference_radius_mm", &PuncturePrediction::crack_reference_radius_mm)
      .def_readonly("crack_radius_mm", &PuncturePrediction::crack_radius_mm)
      .def_readonly("crack_location", &PuncturePrediction::crack_location)
      .def_readonly("criterion",
                    &PuncturePrediction::criterion,
                    "the criterion met first, in words (e.g. 'critical I1 = 95.2')")
      .def_readonly("energy_to_puncture_mj",
                    &PuncturePrediction::energy_to_puncture_mj,
                    "area under the force-depth curve to puncture [mJ = N mm], or None (asked "
                    "by SolverOptions.energy_to_puncture)")
      .def_readonly("part_two_top_stretch",
                    &PuncturePrediction::part_two_top_stretch,
                    "the hoop stretch at the top of Part II when the puncture was solved at the "
                    "corner (else None): a neighbouring problem's "
                    "SolverOptions.puncture_top_stretch_start")
      .def_readonly("failure_verdict",
                    &PuncturePrediction::failure_verdict,
                    "a pre-tensioned membrane: which failure comes first (FailureVerdict; asked "
                    "by SolverOptions.failure_verdict), else None")
      .def_readonly("snap_through",
                    &PuncturePrediction::snap_through,
                    "where a later inflated state's path folds before any puncture: the "
                    "snap-through under depth control on the way (a CurveEvent: depth_mm, "
                    "force_n before, force_after_n after); the puncture is on the first "
                    "inflated state it lands on.  Else None")
      .def_property_readonly(
          "state",
          [](py::object self) { return member_with_problem(self, &PuncturePrediction::state); },
          "the full state at puncture (Equilibrium)")
      .def("__repr__", [](const PuncturePrediction& p) {
        return "<PuncturePrediction " + brief_report(p) + ">";
      });

  py::class_<LoadingCurve, Outcome> curve(
      m,
      "LoadingCurve",
      "The displacement-controlled loading curve; columns are numpy arrays",
      py::dynamic_attr());
  curve.def_readonly("points", &LoadingCurve::points, "list of CurvePoint")
      .def_readonly("stick_slip", &LoadingCurve::stick_slip)
      .def_readonly("part_two_onset_depth_mm",
                    &LoadingCurve::part_two_onset_depth_mm,
                    "depth where Part II appears [mm], or None")
      .def_readonly("part_two_onset_force_n",
                    &LoadingCurve::part_two_onset_force_n,
                    "force where Part II appears [N], or None")
      .def_readonly("part_two_onset_at_switch",
                    &LoadingCurve::part_two_onset_at_switch,
                    "Part II appears as the held membrane starts sliding")
      .def_readonly("face_slides_outward_from_mm",
                    &LoadingCurve::face_slides_outward_from_mm,
                    "flat punch under a gas pressure with friction: the first depth [mm] from "
                    "which the face's material slides outward, as modelled (the points before "
                    "it are not the membrane's states); None otherwise")
      .def_readonly("events",
                    &LoadingCurve::events,
                    "force maxima, a shrinking contact and a snap-through at a fold of the "
                    "depth (list of CurveEvent)")
      .def_readonly("beyond_fold",
                    &LoadingCurve::beyond_fold,
                    "past a fold of the depth: the branch followed by arc length (list of "
                    "CurvePoint, the depth falling); empty otherwise")
      .def_readonly("failure_verdict",
                    &LoadingCurve::failure_verdict,
                    "a pre-tensioned membrane: which failure comes first (FailureVerdict), else "
                    "None")
      .def_property_readonly(
          "puncture",
          [](py::object self) { return member_with_problem(self, &LoadingCurve::puncture); },
          "the puncture point (PuncturePrediction)")
      .def("__len__", [](const LoadingCurve& c) { return c.points.size(); })
      .def_property_readonly(
          "stage",
          [](const LoadingCurve& c) {
            py::list out;
            for (const auto& p : c.points) out.append(p.stage);
            return out;
          },
          "list of Stage, one per point")
      .def_property_readonly(
          "configuration",
          [](const LoadingCurve& c) {
            py::list out;
            for (const auto& p : c.points) out.append(p.configuration);
            return out;
          },
          "list of Configuration, one per point")
      .def(
          "columns",
          [](py::object self) {
            py::dict d;
            for (const char* name : {"depth_mm", "force_n", "normalized_force"})
              d[name] = self.attr(name);
            py::list stages, configurations;
            for (const auto& p : self.cast<const LoadingCurve&>().points) {
              stages.append(to_string(p.stage));
              configurations.append(py::cast(p.configuration).attr("token"));
            }
            d["stage"] = stages;
            d["configuration"] = configurations;
            for (const char* name :
                 {"part_three_stretch", "part_two_length_mm", "corner_slope_rad"})
              d[name] = self.attr(name);
            d["max_i1"] = self.attr("max_first_invariant");
            d["beyond_puncture"] = self.attr("beyond_puncture");
            const auto& points = self.cast<const LoadingCurve&>().points;
            if (!points.empty() && points.front().gas)  // a sealed chamber's, as the CSV
              for (const char* name : {"gas_pressure_mpa", "gas_volume_mm3"})
                d[name] = self.attr(name);
            return d;
          },
          "The curve as a dict named like the CLI's CSV columns (stage and configuration as "
          "lists of their tokens)")
      .def("__repr__",
           [](const LoadingCurve& c) { return "<LoadingCurve " + brief_report(c) + ">"; });
  curve_column(curve, "depth_mm", &CurvePoint::depth_mm, "indentation depth [mm]");
  curve_column(curve, "force_n", &CurvePoint::force_n, "indenter force [N]");
  curve_column(curve, "normalized_force", &CurvePoint::normalized_force, "F / (2 pi G H A)");
  curve_column(
      curve, "part_three_stretch", &CurvePoint::part_three_stretch, "stretch under the tip");
  curve_column(curve,
               "part_two_length_mm",
               &CurvePoint::part_two_length_mm,
               "current length of Part II [mm]");
  curve_column(curve,
               "corner_slope_rad",
               &CurvePoint::corner_slope_rad,
               "slope of Part I at the indenter [rad]");
  curve_column(curve, "max_first_invariant", &CurvePoint::max_first_invariant, "largest I1");
  curve.def_property_readonly(
      "beyond_puncture",
      [](const LoadingCurve& c) {
        return column<bool>(c.points, [](const CurvePoint& p) { return p.beyond_puncture; });
      },
      "bool per point: True past the puncture point (curves with max_depth_mm beyond it)");
  curve.def_property_readonly(
      "gas_pressure_mpa",
      [](const LoadingCurve& c) {
        return column<double>(c.points, [](const CurvePoint& p) {
          return p.gas ? p.gas->pressure_mpa : std::numeric_limits<double>::quiet_NaN();
        });
      },
      "a sealed chamber's gauge pressure at each point [MPa] (NaN without one)");
  curve.def_property_readonly(
      "gas_volume_mm3",
      [](const LoadingCurve& c) {
        return column<double>(c.points, [](const CurvePoint& p) {
          return p.gas ? p.gas->volume_mm3 : std::numeric_limits<double>::quiet_NaN();
        });
      },
      "the volume V between the membrane and its clamp plane at each point [mm^3] (NaN without a "
      "sealed chamber)");

  py::class_<StageBoundary, Outcome>(
      m, "StageBoundary", "Where the stick criterion switches the stage", py::dynamic_attr())
      .def_readonly("switches", &StageBoundary::switches, "False: stays in its first stage")
      .def_readonly("first_stage", &StageBoundary::first_stage)
      .def_readonly("depth_mm", &StageBoundary::depth_mm, "switch depth [mm], when it switches")
      .def_readonly("force_stuck_n", &StageBoundary::force_stuck_n, "held force at the switch [N]")
      .def("__repr__", [](const StageBoundary& b) {
        if (!b.switches)
          return fmt::format("<StageBoundary: stays in the {} stage>", to_string(b.first_stage));
        return fmt::format("<StageBoundary: {} until depth_mm={:.6g} (force_n={:.6g})>",
                           to_string(b.first_stage),
                           b.depth_mm,
                           b.force_stuck_n);
      });

  m.def("full_report",
        py::overload_cast<const Problem&>(&full_report),
        py::arg("problem"),
        "The inputs with units, one per line (the CLI summary's 'Inputs' block)");
  m.def("full_report",
        py::overload_cast<const Equilibrium&, const Problem&>(&full_report),
        py::arg("state"),
        py::arg("problem"),
        "The state's numbers with units, the largest I1 against the problem's critical I1");
  m.def("full_report",
        py::overload_cast<const PuncturePrediction&>(&full_report),
        py::arg("puncture"),
        "The puncture point with units and where the crack starts, or why there is none");
  m.def("full_report",
        py::overload_cast<const LoadingCurve&, const Problem&>(&full_report),
        py::arg("curve"),
        py::arg("problem"),
        "The stick -> slip switch, where Part II appears and the puncture");
}

}  // namespace puncture::python
