// The calibrations (include/puncture/calibration.hpp) and the puncture band
// (include/puncture/puncture_band.hpp).  As in the CLI: invalid input raises ValueError with the
// CLI's messages (naming the argument instead of the flag); a target the model cannot reach, a
// fit that does not converge or a band without a nominal puncture raises puncture.SolverError
// with the message the CLI prints before its exit code 2.  Vectors are numpy arrays, missing
// values None.  The GIL is released while the C++ code runs.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "puncture/calibration.hpp"
#include "puncture/csv.hpp"
#include "puncture/puncture_band.hpp"

namespace puncture::python {

namespace {

// puncture.SolverError, registered by bind_solve (called first).
PyObject* solver_error_type = nullptr;

[[noreturn]] void raise_solver_error(const std::string& message, const std::string& what) {
  py::object error = py::handle(solver_error_type)(what);
  error.attr("status") = Status::NoConvergence;
  error.attr("message") = message;
  PyErr_SetObject(solver_error_type, error.ptr());
  throw py::error_already_set();
}

// The CLI's require_finite, with the argument's name for the flag.
void require_finite(double value, const char* name, const char* range, bool ok) {
  if (!std::isfinite(value) || !ok)
    throw py::value_error(
        fmt::format("{}: must be a finite number {}, got {}", name, range, value));
}

// A library or CSV error as ValueError, with the message the CLI prints (after `prefix: `).
template <class F>
auto as_value_error(F&& f, const std::string& prefix = {}) {
  try {
    return f();
  } catch (const CsvError& e) {
    throw py::value_error(e.what());
  } catch (const std::invalid_argument& e) {
    throw py::value_error(prefix.empty() ? std::string(e.what())
                                         : fmt::format("{}: {}", prefix, e.what()));
  }
}

void check_problem(const Problem& problem) {
  if (const auto message = invalid_input_message(problem); !message.empty())
    throw py::value_error(message);
}

std::vector<double> to_vector(const py::array_t<double, py::array::forcecast>& a,
                              const char* name) {
  if (a.ndim() != 1)
    throw py::value_error(
        fmt::format("{}: expected a one-dimensional array, got {} dimensions", name, a.ndim()));
  const auto v = a.unchecked<1>();
  std::vector<double> out(static_cast<std::size_t>(v.shape(0)));
  for (py::ssize_t i = 0; i < v.shape(0); ++i) out[static_cast<std::size_t>(i)] = v(i);
  return out;
}

std::optional<double> value_of(const Inversion& i) {
  return i.found ? std::optional<double>(i.value) : std::nullopt;
}

// ----- critical I1 ----------------------------------------------------------------------------

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

  py::class_<CriticalI1Estimate>(
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
          "per test: 2 lambda^2 + lambda^-4")
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
      [](const std::vector<BurstTest>& tests) {
        return as_value_error([&] { return critical_i1_from_inflation(tests); });
      },
      py::arg("tests"),
      "Critical I1 from inflation tests (paper §2.3), a list of BurstTest.");
  m.def(
      "critical_i1_from_inflation",
      [](const py::array_t<double, py::array::forcecast>& burst_radii_mm, double mark_radius_mm) {
        const auto tests =
            tests_from_radii(to_vector(burst_radii_mm, "burst_radii_mm"), mark_radius_mm);
        return as_value_error([&] { return critical_i1_from_inflation(tests); });
      },
      py::arg("burst_radii_mm"),
      py::arg("mark_radius_mm"),
      "Critical I1 from the mark's radii at burst [mm] and its initial radius [mm], as the\n"
      "CLI's --burst-radii and --mark-radius.");
  m.def("burst_tests_from_csv",
        &burst_tests_from_csv,
        py::arg("path"),
        py::arg("mark_radius_mm") = py::none(),
        "The inflation tests of a CSV file with a column burst_radius_mm and either\n"
        "initial_radius_mm or, for every test, mark_radius_mm (as `calibrate critical-i1 FILE`).");
}

// ----- inversions, friction and J_lim ---------------------------------------------------------

void bind_inversions(py::module_& m) {
  py::class_<Inversion>(m, "Inversion", "One model parameter inverted from one measured value")
      .def_readonly("found", &Inversion::found)
      .def_readonly("message", &Inversion::message, "why not found, or a warning")
      .def_property_readonly(
          "value",
          [](const Inversion& i) { return value_of(i); },
          "the parameter; None if not found")
      .def_property_readonly(
          "solutions",
          [](py::object self) { return view(self.cast<const Inversion&>().solutions, self); },
          "every solution in the searched range")
      .def_readonly("evaluations", &Inversion::evaluations)
      .def("__repr__", [](const Inversion& i) {
        return i.found ? fmt::format("Inversion(value={:.8g})", i.value)
                       : fmt::format("Inversion(found=False, message='{}')", i.message);
      });
  py::class_<ScanSample>(m, "ScanSample", "The model at one point of an inversion's scan")
      .def_readonly("parameter", &ScanSample::parameter)
      .def_readonly("model", &ScanSample::model, "None where the solver failed");

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

  py::class_<JLimEstimate>(m, "JLimEstimate", "Gent J_lim from one puncture force")
      .def_readonly("force_n", &JLimEstimate::force_n)
      .def_readonly("j_lim", &JLimEstimate::j_lim, "Inversion")
      .def_readonly("smallest_force_n", &JLimEstimate::smallest_force_n)
      .def_readonly("largest_force_n", &JLimEstimate::largest_force_n)
      .def_readonly("neo_hookean_force_n", &JLimEstimate::neo_hookean_force_n)
      .def_readonly("min_j_lim", &JLimEstimate::min_j_lim)
      .def_readonly("max_j_lim", &JLimEstimate::max_j_lim)
      .def_readonly("puncture", &JLimEstimate::puncture, "predicted puncture at the fitted J_lim")
      .def_readonly("max_first_invariant_at_force", &JLimEstimate::max_first_invariant_at_force)
      .def_readonly("scan", &JLimEstimate::scan, "(J_lim, predicted puncture force [N])");

  m.def(
      "friction_from_hole",
      [](const Problem& problem,
         double hole_ratio,
         double hole_ratio_sd,
         const std::optional<double>& puncture_force_n,
         const std::optional<std::variant<HoleMethod, std::string>>& method,
         const std::optional<SolverOptions>& options) {
        Problem base = problem;
        base.friction = 0.0;  // what is calibrated
        check_problem(base);
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
          e = friction_from_hole(base, hole, chosen, o);
        });
        if (!e.friction.found) raise_solver_error(e.friction.message, e.friction.message);
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

  m.def(
      "jlim_from_puncture_force",
      [](const Problem& problem,
         double puncture_force_n,
         const std::optional<SolverOptions>& options) {
        if (!std::holds_alternative<Gent>(problem.material.law))
          throw py::value_error(fmt::format(
              "material: J_lim is a parameter of the Gent law; jlim_from_puncture_force needs "
              "a Gent material, got {}",
              law_name(problem.material.law)));
        Problem base = problem;  // its J_lim is what is calibrated: a valid placeholder
        if (std::isfinite(base.critical_i1) && base.critical_i1 > 3.0)
          base.material.law = Gent{2.0 * (base.critical_i1 - 3.0)};
        check_problem(base);
        require_finite(puncture_force_n, "puncture_force_n", "> 0 N", puncture_force_n > 0.0);
        JLimOptions o;
        if (options) o.solver = *options;
        JLimEstimate e;
        as_value_error([&] {
          py::gil_scoped_release release;
          e = jlim_from_puncture_force(base, puncture_force_n, o);
        });
        if (!e.j_lim.found) raise_solver_error(e.j_lim.message, e.j_lim.message);
        return e;
      },
      py::arg("problem"),
      py::arg("puncture_force_n"),
      py::arg("options") = py::none(),
      "Gent J_lim from one puncture test (paper §4.1): the J_lim whose predicted puncture force\n"
      "equals puncture_force_n [N].  problem's J_lim is ignored.  Raises SolverError when no\n"
      "J_lim gives the force.");
}

// ----- uniaxial fit ---------------------------------------------------------------------------

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

  py::class_<UniaxialFit>(m, "UniaxialFit", "Least-squares fit of a uniaxial tensile test")
      .def_readonly("converged", &UniaxialFit::converged)
      .def_readonly("message", &UniaxialFit::message)
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
  m.def(
      "fit_uniaxial",
      [](const py::array_t<double, py::array::forcecast>& stretch,
         const py::array_t<double, py::array::forcecast>& nominal_stress_mpa,
         const std::variant<FitLaw, std::string>& law) {
        const auto l = to_vector(stretch, "stretch");
        const auto s = to_vector(nominal_stress_mpa, "nominal_stress_mpa");
        if (l.size() != s.size())
          throw py::value_error(
              fmt::format("stretch and nominal_stress_mpa: need as many values, got {} and {}",
                          l.size(),
                          s.size()));
        std::vector<UniaxialPoint> data;
        for (std::size_t i = 0; i < l.size(); ++i) data.push_back({l[i], s[i]});
        const FitLaw chosen = fit_law_of(law);
        UniaxialFit fit;
        as_value_error([&] {
          py::gil_scoped_release release;
          fit = fit_uniaxial(data, chosen);
        });
        if (!fit.converged)
          raise_solver_error(fit.message, "the fit did not converge: " + fit.message);
        return fit;
      },
      py::arg("stretch"),
      py::arg("nominal_stress_mpa"),
      py::arg("law") = "gent",
      "Fit G (and J_lim for 'gent', alpha for 'mooney-rivlin') to a uniaxial test (paper §4.1,\n"
      "Fig. 11) by Levenberg-Marquardt.  Raises SolverError when the fit does not converge.");
}

// ----- puncture band --------------------------------------------------------------------------

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
  py::class_<BandEvaluation>(m, "BandEvaluation", "One predicted puncture of the band")
      .def_readonly("parameters", &BandEvaluation::parameters)
      .def_readonly("found", &BandEvaluation::found)
      .def_readonly("message", &BandEvaluation::message, "why not, when not found")
      .def_property_readonly("force_n",
                             [](const BandEvaluation& e) {
                               return e.found ? std::optional<double>(e.force_n) : std::nullopt;
                             })
      .def_property_readonly("depth_mm",
                             [](const BandEvaluation& e) {
                               return e.found ? std::optional<double>(e.depth_mm) : std::nullopt;
                             })
      .def_property_readonly("part_three_stretch",
                             [](const BandEvaluation& e) {
                               return e.found ? std::optional<double>(e.part_three_stretch)
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
  py::class_<PunctureBand>(m, "PunctureBand", "The puncture force and depth over the intervals")
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
      .def_readonly("complete", &PunctureBand::complete)
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
        if (!band.nominal.found)
          raise_solver_error(
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
      "where the solver fails is in .warnings and .complete is False; SolverError when the\n"
      "nominal problem has no puncture point.");
}

}  // namespace

void bind_calibration(py::module_& m) {
  solver_error_type = m.attr("SolverError").ptr();  // the module keeps it alive
  bind_critical_i1(m);
  bind_inversions(m);
  bind_uniaxial(m);
  bind_band(m);
}

}  // namespace puncture::python
