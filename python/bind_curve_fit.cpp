// Fit of force-depth records (include/puncture/curve_fit.hpp, force_depth_record.hpp):
// CurveTest, FittedCurveParameter, CurveTestFit, CurveFit, fit_curves and
// read_force_depth_record, with numpy arrays for the points.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bind_calibration.hpp"
#include "puncture/curve_fit.hpp"
#include "puncture/force_depth_record.hpp"

namespace puncture::python::calibration {

namespace {

CurveParameter parameter_of(const std::string& name) {
  if (const auto p = curve_parameter_from_token(name)) return *p;
  throw py::value_error(fmt::format(
      "free: unknown parameter '{}' (choose from: {})", name, curve_parameter_tokens()));
}

RobustLoss loss_of(const std::string& loss) {
  for (const auto l : {RobustLoss::None, RobustLoss::Huber, RobustLoss::Cauchy})
    if (loss == to_string(l)) return l;
  throw py::value_error(fmt::format("loss: expected 'none', 'huber' or 'cauchy', got '{}'", loss));
}

ColumnChoice column_of(const py::object& column, const char* name) {
  if (py::isinstance<py::int_>(column)) return {"", column.cast<int>()};
  if (py::isinstance<py::str>(column)) return {column.cast<std::string>(), 0};
  throw py::value_error(fmt::format("{}: a column name (str) or 1-based position (int)", name));
}

}  // namespace

void bind_curve_fit(py::module_& m) {
  py::class_<CurveTest>(m, "CurveTest", "One measured force-depth record and its problem")
      .def(py::init([](const Problem& problem,
                       const py::array_t<double, py::array::forcecast>& depth_mm,
                       const py::array_t<double, py::array::forcecast>& force_n,
                       const std::string& name,
                       const std::optional<std::pair<double, double>>& puncture,
                       double contact_offset_mm) {
             CurveTest t;
             t.contact_offset_mm = contact_offset_mm;
             t.name = name;
             t.problem = problem;
             t.depth_mm = to_vector(depth_mm, "depth_mm");
             t.force_n = to_vector(force_n, "force_n");
             if (puncture) t.puncture = MeasuredPuncture{puncture->first, puncture->second};
             return t;
           }),
           py::arg("problem"),
           py::arg("depth_mm"),
           py::arg("force_n"),
           py::arg("name") = "test",
           py::arg("puncture") = py::none(),
           py::arg("contact_offset_mm") = 0.0,
           "problem: geometry, probe, fixed parameters (the free ones' values are the start);\n"
           "depth_mm from the contact point (> 0, not decreasing), force_n [N];\n"
           "puncture: (depth_mm, force_n) of the perforation, when the record has it;\n"
           "contact_offset_mm: the model's depth is depth_mm minus it (the start when\n"
           "'contact-offset' is free)")
      .def_readonly("name", &CurveTest::name)
      .def_readonly("problem", &CurveTest::problem)
      .def_readonly("contact_offset_mm", &CurveTest::contact_offset_mm);

  py::class_<FittedCurveParameter>(m, "FittedCurveParameter", "One fitted parameter")
      .def_readonly("name", &FittedCurveParameter::name, "'shear-modulus', 'jlim', ...")
      .def_readonly("unit", &FittedCurveParameter::unit)
      .def_readonly("test", &FittedCurveParameter::test, "a per-test parameter's test, else ''")
      .def_readonly("value", &FittedCurveParameter::value)
      .def_readonly("standard_error", &FittedCurveParameter::standard_error)
      .def_readonly("ci_lower", &FittedCurveParameter::ci_lower, "95 % interval")
      .def_readonly("ci_upper", &FittedCurveParameter::ci_upper, "95 % interval")
      .def_readonly("profile_interval",
                    &FittedCurveParameter::profile_interval,
                    "the interval is the profile's (stick-threshold), not value -+ t se")
      .def_readonly("on_bound", &FittedCurveParameter::on_bound)
      .def_readonly("identifiable", &FittedCurveParameter::identifiable)
      .def_readonly("note", &FittedCurveParameter::note)
      .def("__repr__", [](const FittedCurveParameter& p) {
        return fmt::format(
            "FittedCurveParameter({}={:.6g}, standard_error={})",
            p.name,
            p.value,
            p.standard_error ? fmt::format("{:.3g}", *p.standard_error) : std::string("None"));
      });

  py::class_<CurveTestFit>(m, "CurveTestFit", "One test's points and the fitted model there")
      .def_readonly("name", &CurveTestFit::name)
      .def_property_readonly(
          "depth_mm",
          [](py::object self) { return view(self.cast<const CurveTestFit&>().depth_mm, self); })
      .def_property_readonly(
          "force_n",
          [](py::object self) { return view(self.cast<const CurveTestFit&>().force_n, self); })
      .def_property_readonly("model_force_n",
                             [](py::object self) {
                               return view(self.cast<const CurveTestFit&>().model_force_n, self);
                             })
      .def_property_readonly(
          "residual_n",
          [](py::object self) { return view(self.cast<const CurveTestFit&>().residual_n, self); })
      .def_readonly("rms_residual_n", &CurveTestFit::rms_residual_n)
      .def_property_readonly(
          "measured_puncture",
          [](const CurveTestFit& t) -> std::optional<std::pair<double, double>> {
            if (!t.measured_puncture) return std::nullopt;
            return std::pair{t.measured_puncture->depth_mm, t.measured_puncture->force_n};
          },
          "(depth_mm, force_n) or None")
      .def_property_readonly(
          "model_puncture",
          [](const CurveTestFit& t) -> std::optional<std::pair<double, double>> {
            if (!t.model_puncture) return std::nullopt;
            return std::pair{t.model_puncture->depth_mm, t.model_puncture->force_n};
          },
          "(depth_mm, force_n) predicted at the estimates, or None");

  py::class_<CurveFit, Outcome>(m, "CurveFit", "Joint least-squares fit of force-depth records")
      .def_readonly("parameters", &CurveFit::parameters, "in the order of `free`")
      .def_property_readonly(
          "correlation",
          [](const CurveFit& f) {
            const auto n = static_cast<py::ssize_t>(f.correlation.size());
            py::array_t<double> a({n, n});
            auto out = a.mutable_unchecked<2>();
            for (py::ssize_t i = 0; i < n; ++i)
              for (py::ssize_t j = 0; j < n; ++j)
                out(i, j) = f.correlation[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
            return a;
          },
          "p x p correlation matrix (empty when the covariance is rank-deficient)")
      .def_readonly("tests", &CurveFit::tests)
      .def_readonly("warnings", &CurveFit::warnings)
      .def_readonly("residual_sd_n", &CurveFit::residual_sd_n)
      .def_readonly("r_squared", &CurveFit::r_squared)
      .def_readonly("points", &CurveFit::points)
      .def_readonly("iterations", &CurveFit::iterations)
      .def_readonly("curve_evaluations", &CurveFit::curve_evaluations)
      .def_readonly("fitted_problems", &CurveFit::fitted_problems)
      .def(
          "parameter",
          [](const CurveFit& f, const std::string& name) {
            for (const auto& p : f.parameters)
              if (p.name == name) return p;
            throw py::key_error(name);
          },
          py::arg("name"));

  m.def(
      "fit_curves",
      [](const std::vector<CurveTest>& tests,
         const std::vector<std::string>& free,
         const std::vector<std::tuple<std::string, double, double>>& bounds,
         const std::string& loss,
         double loss_scale_n,
         double puncture_sd_fraction,
         double min_r_squared) {
        CurveFitOptions o;
        for (const auto& name : free) o.free.push_back(parameter_of(name));
        for (const auto& [name, lo, hi] : bounds) o.bounds.push_back({parameter_of(name), lo, hi});
        o.loss = loss_of(loss);
        o.loss_scale_n = loss_scale_n;
        o.puncture_force_sd_fraction = o.puncture_depth_sd_fraction = puncture_sd_fraction;
        o.min_r_squared = min_r_squared;
        CurveFit fit;
        as_value_error([&] {
          py::gil_scoped_release release;
          fit = fit_curves(CurveFitProblem{tests}, o);
        });
        if (!fit.ok()) raise_solver_error(fit.status, fit.message, fit.message);
        return fit;
      },
      py::arg("tests"),
      py::arg("free"),
      py::kw_only(),
      py::arg("bounds") = std::vector<std::tuple<std::string, double, double>>{},
      py::arg("loss") = "none",
      py::arg("loss_scale_n") = 0.0,
      py::arg("puncture_sd_fraction") = 0.05,
      py::arg("min_r_squared") = 0.9,
      "Fit the free parameters ('shear-modulus', 'jlim', 'friction', 'critical-i1') jointly\n"
      "to the CurveTests (as `puncture fit curve`): estimates with standard errors, 95 %\n"
      "intervals, the correlation matrix and, per test, numpy arrays of the points, the model\n"
      "and the residuals.  bounds: [(name, lower, upper)].  Raises SolverError when the fit\n"
      "ends on a bound, explains less than min_r_squared of the force variance or does not\n"
      "converge; ValueError for invalid input.");

  m.def(
      "read_force_depth_record",
      [](const std::string& path,
         const py::object& depth_column,
         const py::object& force_column,
         const std::string& depth_unit,
         const std::string& force_unit,
         const std::optional<double>& contact_depth,
         bool cut_at_perforation) {
        RecordFormat f;
        f.depth = column_of(depth_column, "depth_column");
        f.force = column_of(force_column, "force_column");
        const auto du = depth_unit_from_token(depth_unit);
        const auto fu = force_unit_from_token(force_unit);
        if (!du) throw py::value_error("depth_unit: expected 'mm', 'm' or 'in'");
        if (!fu) throw py::value_error("force_unit: expected 'N', 'kN', 'lbf' or 'gf'");
        f.depth_unit = *du;
        f.force_unit = *fu;
        f.contact_depth = contact_depth;
        f.cut_at_perforation = cut_at_perforation;
        const auto r = as_value_error([&] { return read_force_depth_record(path, f); });
        py::dict out;
        out["depth_mm"] = column<double>(r.depth_mm, [](double x) { return x; });
        out["force_n"] = column<double>(r.force_n, [](double x) { return x; });
        out["contact_depth_mm"] = r.contact_depth_mm;
        out["contact_found"] = r.contact_found;
        out["puncture"] =
            r.perforation_depth_mm
                ? py::object(py::make_tuple(*r.perforation_depth_mm, *r.perforation_force_n))
                : py::object(py::none());
        return out;
      },
      py::arg("path"),
      py::kw_only(),
      py::arg("depth_column") = "depth_mm",
      py::arg("force_column") = "force_n",
      py::arg("depth_unit") = "mm",
      py::arg("force_unit") = "N",
      py::arg("contact_depth") = py::none(),
      py::arg("cut_at_perforation") = true,
      "A testing machine's CSV record as `puncture fit curve` reads it: a dict with depth_mm\n"
      "(from the contact point) and force_n arrays, contact_depth_mm, contact_found and\n"
      "puncture ((depth_mm, force_n) of the perforation, or None).  The separator, header and\n"
      "decimal mark are detected; ValueError names the file, line and column.");
}

}  // namespace puncture::python::calibration
