// Fit of a uniaxial or equibiaxial test (include/puncture/calibration.hpp): FitLaw, StressTest,
// SpecimenGeometry, FittedParameter, InformationCriteria, UniaxialFit, uniaxial_points,
// uniaxial_points_from_csv, fit_uniaxial, compare_uniaxial_fits and information_criteria.
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

FitLaw law_of(const std::variant<FitLaw, std::string>& law) {
  if (const auto* l = std::get_if<FitLaw>(&law)) return *l;
  const auto& text = std::get<std::string>(law);
  try {
    return fit_law_of(text);
  } catch (const InvalidInput&) {
    std::string names;
    for (const auto l : all_fit_laws()) names += (names.empty() ? "'" : ", '") + to_string(l) + "'";
    throw py::value_error(
        fmt::format("law: expected a FitLaw or one of {}, got '{}'", names, text));
  }
}

StressTest test_of(const std::string& test) {
  if (test == "uniaxial") return StressTest::Uniaxial;
  if (test == "equibiaxial") return StressTest::Equibiaxial;
  throw py::value_error(fmt::format("test: expected 'uniaxial' or 'equibiaxial', got '{}'", test));
}

// The fit's keyword arguments after the data and the law.
struct FitKeywords {
  std::string test = "uniaxial";
  std::optional<std::vector<double>> ogden_alpha;
  int ogden_terms = 3;
  int max_iterations = 500;

  UniaxialFitOptions options() const {
    UniaxialFitOptions o;
    o.test = test_of(test);
    if (ogden_alpha) o.ogden_alpha_start = *ogden_alpha;
    o.ogden_terms = ogden_terms;
    o.max_iterations = max_iterations;
    return o;
  }
};

std::vector<UniaxialPoint> points_of(const py::array_t<double, py::array::forcecast>& stretch,
                                     const py::array_t<double, py::array::forcecast>& stress) {
  const auto l = to_vector(stretch, "stretch");
  const auto s = to_vector(stress, "nominal_stress_mpa");
  if (l.size() != s.size())
    throw py::value_error(fmt::format(
        "stretch and nominal_stress_mpa: need as many values, got {} and {}", l.size(), s.size()));
  std::vector<UniaxialPoint> data;
  for (std::size_t i = 0; i < l.size(); ++i) data.push_back({l[i], s[i]});
  return data;
}

UniaxialFit fit_arrays(const py::array_t<double, py::array::forcecast>& stretch,
                       const py::array_t<double, py::array::forcecast>& nominal_stress_mpa,
                       const std::variant<FitLaw, std::string>& law, const FitKeywords& k) {
  const auto data = points_of(stretch, nominal_stress_mpa);
  const FitLaw chosen = law_of(law);
  const auto options = k.options();
  UniaxialFit fit;
  as_value_error([&] {
    py::gil_scoped_release release;
    fit = fit_uniaxial(data, chosen, options);
  });
  if (!fit.ok())
    raise_solver_error(fit.status,
                       fit.message,
                       fit.status == Status::NoConvergence
                           ? "the fit did not converge: " + fit.message
                           : fit.message);
  return fit;
}

std::vector<UniaxialFit> compare_arrays(
    const py::array_t<double, py::array::forcecast>& stretch,
    const py::array_t<double, py::array::forcecast>& nominal_stress_mpa,
    const std::variant<std::string, std::vector<std::variant<FitLaw, std::string>>>& laws,
    const FitKeywords& k) {
  const auto data = points_of(stretch, nominal_stress_mpa);
  std::vector<FitLaw> chosen;
  if (const auto* all = std::get_if<std::string>(&laws)) {
    if (*all != "all")
      throw py::value_error(fmt::format("laws: expected 'all' or a list of laws, got '{}'", *all));
    chosen = all_fit_laws();
  } else {
    for (const auto& l : std::get<1>(laws)) chosen.push_back(law_of(l));
  }
  const auto options = k.options();
  std::vector<UniaxialFit> fits;
  as_value_error([&] {
    py::gil_scoped_release release;
    fits = compare_uniaxial_fits(data, chosen, options);
  });
  return fits;
}

}  // namespace

void bind_uniaxial(py::module_& m) {
  py::enum_<FitLaw>(m, "FitLaw", "Law fitted to a uniaxial test")
      .value("Gent", FitLaw::Gent)
      .value("NeoHookean", FitLaw::NeoHookean)
      .value("MooneyRivlin", FitLaw::MooneyRivlin)
      .value("Yeoh", FitLaw::Yeoh)
      .value("Ogden", FitLaw::Ogden)
      .value("ArrudaBoyce", FitLaw::ArrudaBoyce)
      .value("GentGent", FitLaw::GentGent)
      .def_property_readonly("token", [](FitLaw l) { return to_string(l); });
  py::enum_<StressTest>(m, "StressTest", "The homogeneous test whose nominal stress is fitted")
      .value("Uniaxial", StressTest::Uniaxial)
      .value("Equibiaxial", StressTest::Equibiaxial)
      .def_property_readonly("token", [](StressTest t) { return to_string(t); });

  py::class_<InformationCriteria>(
      m,
      "InformationCriteria",
      "AIC = n ln(RSS/n) + 2k, AICc = AIC + 2k(k+1)/(n-k-1), BIC = n ln(RSS/n) + k ln n, with\n"
      "k the law's parameters plus the variance; compare fits of the same data only")
      .def_readonly("points", &InformationCriteria::points)
      .def_readonly("parameters", &InformationCriteria::parameters, "k (with the variance)")
      .def_readonly("rss_mpa2", &InformationCriteria::rss_mpa2)
      .def_readonly("aic", &InformationCriteria::aic)
      .def_readonly("aicc", &InformationCriteria::aicc, "None when n <= k + 1")
      .def_readonly("bic", &InformationCriteria::bic)
      .def("__repr__", [](const InformationCriteria& c) {
        return fmt::format("InformationCriteria(aic={:.6g}, bic={:.6g}, n={}, k={})",
                           c.aic,
                           c.bic,
                           c.points,
                           c.parameters);
      });
  m.def(
      "information_criteria",
      [](int points, int law_parameters, double rss_mpa2) {
        return as_value_error(
            [&] { return information_criteria(points, law_parameters, rss_mpa2); });
      },
      py::arg("points"),
      py::arg("law_parameters"),
      py::arg("rss_mpa2"),
      "AIC, AICc and BIC of a least-squares fit of n points with p law parameters.");

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
      .def_readonly("name",
                    &FittedParameter::name,
                    "'G', 'J_lim', 'alpha', 'C10', 'mu_1', 'alpha_1', 'N', 'beta', ...")
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
      .def_readonly("test", &UniaxialFit::test)
      .def_readonly("material", &UniaxialFit::material, "the fit as a Material; None if invalid")
      .def_readonly("parameters",
                    &UniaxialFit::parameters,
                    "G first (yeoh: C10, C20, C30; ogden: mu_1.., alpha_1..)")
      .def_readonly("correlation",
                    &UniaxialFit::correlation,
                    "correlation coefficients between parameters (rows); [] when singular")
      .def_readonly("information", &UniaxialFit::information, "InformationCriteria; None if exact")
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
      "Fit a law ('gent', 'neo-hookean', 'mooney-rivlin', 'yeoh', 'ogden', 'arruda-boyce',\n"
      "'gent-gent' or a FitLaw) to a uniaxial (test='uniaxial') or equibiaxial test's nominal\n"
      "stress [MPa] by bounded Levenberg-Marquardt inside the law's validity range.  Ogden:\n"
      "ogden_terms (1-3) terms, or starting exponents ogden_alpha (each keeps its sign).\n"
      "Raises SolverError when the fit does not converge or ends on a bound of the range.";
  m.def(
      "fit_uniaxial",
      [](const py::array_t<double, py::array::forcecast>& stretch,
         const py::array_t<double, py::array::forcecast>& stress,
         const std::variant<FitLaw, std::string>& law,
         const std::string& test,
         const std::optional<std::vector<double>>& ogden_alpha,
         int ogden_terms,
         int max_iterations) {
        return fit_arrays(stretch, stress, law, {test, ogden_alpha, ogden_terms, max_iterations});
      },
      py::arg("stretch"),
      py::arg("nominal_stress_mpa"),
      py::arg("law") = "gent",
      py::kw_only(),
      py::arg("test") = "uniaxial",
      py::arg("ogden_alpha") = py::none(),
      py::arg("ogden_terms") = 3,
      py::arg("max_iterations") = 500,
      fit_doc);
  // What uniaxial_points(_from_csv) return, passed as it comes.
  m.def(
      "fit_uniaxial",
      [](const Points& points,
         const std::variant<FitLaw, std::string>& law,
         const std::string& test,
         const std::optional<std::vector<double>>& ogden_alpha,
         int ogden_terms,
         int max_iterations) {
        return fit_arrays(
            points.first, points.second, law, {test, ogden_alpha, ogden_terms, max_iterations});
      },
      py::arg("points"),
      py::arg("law") = "gent",
      py::kw_only(),
      py::arg("test") = "uniaxial",
      py::arg("ogden_alpha") = py::none(),
      py::arg("ogden_terms") = 3,
      py::arg("max_iterations") = 500,
      "The same fit of the (stretch, nominal_stress_mpa) pair that uniaxial_points and\n"
      "uniaxial_points_from_csv return.");
  m.def(
      "compare_uniaxial_fits",
      [](const py::array_t<double, py::array::forcecast>& stretch,
         const py::array_t<double, py::array::forcecast>& stress,
         const std::variant<std::string, std::vector<std::variant<FitLaw, std::string>>>& laws,
         const std::string& test,
         const std::optional<std::vector<double>>& ogden_alpha,
         int ogden_terms) {
        return compare_arrays(stretch, stress, laws, {test, ogden_alpha, ogden_terms, 500});
      },
      py::arg("stretch"),
      py::arg("nominal_stress_mpa"),
      py::arg("laws") = "all",
      py::kw_only(),
      py::arg("test") = "uniaxial",
      py::arg("ogden_alpha") = py::none(),
      py::arg("ogden_terms") = 3,
      "Every law of `laws` (a list, or 'all') fitted to the same data, as UniaxialFit objects\n"
      "ranked by AIC (lowest first; fits without one last).  A fit that fails is returned\n"
      "with its status, not raised.");
}

}  // namespace puncture::python::calibration
