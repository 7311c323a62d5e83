// `puncture calibrate critical-i1|friction|jlim|band` and `puncture fit uniaxial`.
#include "command_calibrate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "calibration/band_monte_carlo.hpp"
#include "calibration/critical_value_output.hpp"
#include "calibration_output.hpp"
#include "cli_error.hpp"
#include "parameter_flags.hpp"
#include "progress.hpp"
#include "puncture/calibration.hpp"
#include "puncture/csv.hpp"
#include "puncture/failure.hpp"
#include "puncture/puncture_band.hpp"

namespace puncture::cli {

namespace {

constexpr const char* kCalibrateFooter =
    "The physical flags (see puncture --help) describe the membrane and indenter of the test;\n"
    "the parameter being calibrated must not be given.  Output flags: --format, --output.";

// The criteria the burst tests calibrate: those with a local measure (the energy release's
// tearing energy is not a stretch the inflated membrane reaches).
std::vector<std::string> local_criterion_names() {
  std::vector<std::string> out;
  for (const std::string& name : criterion_names())
    if (has_local_measure(criterion_from_name(name, 1.0))) out.push_back(name);
  return out;
}

void require_finite(double value, const char* flag, const char* range, bool ok) {
  if (!std::isfinite(value) || !ok)
    throw InputError(fmt::format("{}: must be a finite number {}, got {}", flag, range, value));
}

// A library input error, with the flag it is about when known.
[[noreturn]] void rethrow_as_input(const std::exception& e, const char* prefix = nullptr) {
  if (const auto* invalid = dynamic_cast<const InvalidInput*>(&e); invalid && !prefix)
    rethrow_with_flags(*invalid);
  throw InputError(prefix ? fmt::format("{}: {}", prefix, e.what()) : std::string(e.what()));
}

std::string run_critical_i1(const CLI::App& app, const ProblemFlags& pf, const CalibrationFlags& f,
                            Format format) {
  if (given(app, "--critical-i1"))
    throw InputError(
        "--critical-i1: `calibrate critical-i1` determines the critical I1; do not give it");
  CriticalI1Report report;
  const std::optional<double> mark =
      f.mark_radius_option->count() > 0 ? std::optional<double>(f.mark_radius_mm) : std::nullopt;
  if (mark) require_finite(*mark, "--mark-radius", "> 0 mm", *mark > 0.0);
  if (!f.burst_data.empty()) {
    report.source = f.burst_data;
    try {
      const auto table = read_numeric_csv(f.burst_data, 1);
      if (!mark && !table.has("initial_radius_mm"))
        throw InputError(fmt::format(
            "--mark-radius: {} has no column initial_radius_mm, so the mark's initial radius "
            "[mm] must be given",
            f.burst_data));
      if (mark && table.has("initial_radius_mm"))
        throw InputError(
            fmt::format("--mark-radius: {} gives each test's initial_radius_mm; do not give it too",
                        f.burst_data));
      report.tests = burst_tests_from_table(table, mark);
    } catch (const CsvError& e) {
      throw InputError(e.what());
    } catch (const std::invalid_argument& e) {
      rethrow_as_input(e);
    }
  } else {
    if (f.burst_radii_mm.empty())
      throw InputError(
          "calibrate critical-i1: give the mark's radii at burst, --burst-radii R1,R2,... [mm] "
          "with --mark-radius, or a CSV file");
    if (!mark)
      throw InputError(
          "--mark-radius: the mark's initial radius [mm] is needed with --burst-radii");
    report.source = "--burst-radii";
    for (std::size_t i = 0; i < f.burst_radii_mm.size(); ++i) {
      const double r = f.burst_radii_mm[i];
      if (!std::isfinite(r) || r <= 0.0)
        throw InputError(fmt::format(
            "--burst-radii: value {} must be a finite number > 0 mm, got {}", i + 1, r));
      if (r < *mark)
        throw InputError(fmt::format(
            "--burst-radii: value {} ({} mm) is below the mark radius {} mm; an inflated membrane "
            "stretches the mark",
            i + 1,
            r,
            *mark));
      report.tests.push_back({*mark, r});
    }
  }
  if (f.measure != "i1") {
    CriticalValueReport value{report.source, report.tests, {}, f.pole_only, {}};
    try {
      // The membrane's law and G (Ogden's G from its terms).
      const MaterialLaw law = make_law(pf);
      value.material = std::holds_alternative<Ogden>(law)
                           ? ogden_material(pf.ogden_mu_mpa, pf.ogden_alpha)
                           : Material{pf.shear_modulus_mpa, law};
      value.estimate = critical_value_from_inflation(
          value.tests, criterion_from_name(f.measure, 0.0), value.material, f.pole_only);
    } catch (const std::invalid_argument& e) {
      rethrow_as_input(e);
    }
    if (!value.estimate.ok()) throw SolveError(value.estimate.message, value.estimate.status);
    return calibration_text(value, format);
  }
  try {
    if (!f.pole_only) report.law = make_law(pf);
    report.estimate = report.law ? critical_i1_from_inflation(report.tests, *report.law)
                                 : critical_i1_from_inflation(report.tests);
  } catch (const std::invalid_argument& e) {
    rethrow_as_input(e);
  }
  if (!report.estimate.ok()) throw SolveError(report.estimate.message, report.estimate.status);
  return calibration_text(report, format);
}

std::string run_friction(const CLI::App& app, const ProblemFlags& pf, const CalibrationFlags& f,
                         Format format) {
  if (given(app, "--friction"))
    throw InputError(
        "--friction: `calibrate friction` determines the friction coefficient; do not give it");
  const bool with_force = f.friction_force_option->count() > 0;
  require_finite(f.hole_ratio, "--hole-ratio", "> 0", f.hole_ratio > 0.0);
  require_finite(f.hole_ratio_sd, "--hole-ratio-sd", ">= 0", f.hole_ratio_sd >= 0.0);
  if (with_force)
    require_finite(f.puncture_force_n, "--puncture-force", "> 0 N", f.puncture_force_n > 0.0);
  FrictionReport report;
  report.problem = make_problem(pf, Unknown::Friction);
  report.hole = {f.hole_ratio,
                 f.hole_ratio_sd,
                 with_force ? std::optional<double>(f.puncture_force_n) : std::nullopt};
  try {
    Progress progress("calibrate friction");
    if (with_force) {
      progress.note("friction at the measured force");
      report.at_measured_force =
          friction_from_hole(report.problem, report.hole, HoleMethod::AtMeasuredForce);
    }
    progress.note("friction at the predicted puncture");
    report.at_predicted_puncture =
        friction_from_hole(report.problem, report.hole, HoleMethod::AtPredictedPuncture);
  } catch (const std::invalid_argument& e) {
    rethrow_as_input(e);
  }
  const auto& primary =
      report.at_measured_force ? *report.at_measured_force : report.at_predicted_puncture;
  if (!primary.friction.ok()) throw SolveError(primary.friction.message, primary.friction.status);
  return calibration_text(report, format);
}

std::string run_jlim(const CLI::App& app, const ProblemFlags& pf, const CalibrationFlags& f,
                     Format format) {
  if (given(app, "--jlim"))
    throw InputError("--jlim: `calibrate jlim` determines J_lim; do not give it");
  if (pf.material != "gent")
    throw InputError(fmt::format(
        "--material: J_lim is a parameter of the Gent law; calibrate jlim needs --material gent, "
        "got {}",
        pf.material));
  require_finite(f.puncture_force_n, "--puncture-force", "> 0 N", f.puncture_force_n > 0.0);
  const bool force_sd = f.puncture_force_sd_n > 0.0;
  const bool i1_sd = f.critical_i1_sd > 0.0;
  require_finite(f.puncture_force_sd_n,
                 "--puncture-force-sd",
                 ">= 0 N and below --puncture-force",
                 f.puncture_force_sd_n >= 0.0 && f.puncture_force_sd_n < f.puncture_force_n);
  JLimReport report;
  report.problem = make_problem(pf, Unknown::JLim);
  require_finite(f.critical_i1_sd,
                 "--critical-i1-sd",
                 ">= 0 and below --critical-i1 - 3",
                 f.critical_i1_sd >= 0.0 && f.critical_i1_sd < report.problem.critical_i1 - 3.0);
  report.force_n = f.puncture_force_n;
  if (force_sd) report.force_sd_n = f.puncture_force_sd_n;
  if (i1_sd) report.critical_i1_sd = f.critical_i1_sd;
  try {
    Progress progress("calibrate jlim");
    progress.note("J_lim for the measured force");
    report.estimate = j_lim_from_puncture_force(report.problem, f.puncture_force_n);
    if (force_sd) {
      progress.note("J_lim for the force +- sd");
      report.force_plus_sd =
          j_lim_from_puncture_force(report.problem, f.puncture_force_n + f.puncture_force_sd_n);
      report.force_minus_sd =
          j_lim_from_puncture_force(report.problem, f.puncture_force_n - f.puncture_force_sd_n);
    }
    if (i1_sd) {
      progress.note("J_lim for the critical I1 +- sd");
      Problem plus = report.problem;
      plus.critical_i1 += f.critical_i1_sd;
      Problem minus = report.problem;
      minus.critical_i1 -= f.critical_i1_sd;
      report.i1_plus_sd = j_lim_from_puncture_force(plus, f.puncture_force_n);
      report.i1_minus_sd = j_lim_from_puncture_force(minus, f.puncture_force_n);
    }
  } catch (const std::invalid_argument& e) {
    rethrow_as_input(e);
  }
  if (!report.estimate.j_lim.ok())
    throw SolveError(report.estimate.j_lim.message, report.estimate.j_lim.status);
  return calibration_text(report, format);
}

// ----- calibrate band -------------------------------------------------------------------------

constexpr BandParameter kBandParameters[4] = {BandParameter::CriticalI1,
                                              BandParameter::Friction,
                                              BandParameter::JLim,
                                              BandParameter::ShearModulus};

struct BandFlagNames {
  const char* sd;
  const char* range;
  const char* nominal;  // the physical flag of the nominal value
  const char* unit;     // for help and messages
};
constexpr BandFlagNames kBandFlags[4] = {
    {"--critical-i1-sd", "--critical-i1-range", "--critical-i1", ""},
    {"--friction-sd", "--friction-range", "--friction", ""},
    {"--jlim-sd", "--jlim-range", "--jlim", ""},
    {"--shear-modulus-sd", "--shear-modulus-range", "--shear-modulus", " MPa"},
};

std::string run_band(const ProblemFlags& pf, const CalibrationFlags& f, Format format) {
  BandReport report;
  report.problem = make_problem(pf);
  const bool monte_carlo = f.band_method == "monte-carlo";
  require_finite(f.band_sd_multiple, "--sd-multiple", "> 0", f.band_sd_multiple > 0.0);
  // Monte Carlo: a normal truncated at +-3 sd unless told otherwise.
  report.sd_multiple =
      monte_carlo && f.band_sd_multiple_option->count() == 0 ? 3.0 : f.band_sd_multiple;
  const int most_samples = monte_carlo ? 100000000 : 1000;
  if (f.band_samples < 2 || f.band_samples > most_samples)
    throw InputError(fmt::format("--samples: must be in the range 2 to {} with --method {}, got {}",
                                 most_samples,
                                 f.band_method,
                                 f.band_samples));
  const BandParameters nominal = band_parameters(report.problem);
  bool any = false;
  for (int i = 0; i < 4; ++i) {
    const auto p = kBandParameters[i];
    const auto& names = kBandFlags[i];
    const bool by_sd = f.band_sd_option[i]->count() > 0;
    const bool by_range = f.band_range_option[i]->count() > 0;
    if (!by_sd && !by_range) continue;
    const char* flag = by_sd ? names.sd : names.range;
    if (p == BandParameter::JLim && !nominal.j_lim)
      throw InputError(
          fmt::format("{}: J_lim is a parameter of the Gent law; needs --material gent, got {}",
                      flag,
                      pf.material));
    const double x = nominal.value(p);
    ParameterRange range;
    if (by_sd) {
      const double sd = f.band_sd[i];
      require_finite(sd, names.sd, ">= 0", sd >= 0.0);
      report.sd[i] = sd;
      range = plus_minus(x, sd, report.sd_multiple);
    } else {
      const auto& v = f.band_range[i];
      if (v.size() != 2)
        throw InputError(fmt::format("{}: expected LO,HI (two numbers), got {} value{}",
                                     flag,
                                     v.size(),
                                     v.size() == 1 ? "" : "s"));
      range = {v[0], v[1]};
    }
    // The range itself (finite, ordered, containing the nominal value, valid at both ends and
    // at every corner) is checked by the library, with the messages the Python bindings give.
    report.ranges.of(p) = range;
    any = true;
  }
  if (!any)
    throw InputError(
        "calibrate band: give at least one interval, e.g. --critical-i1-sd 4.8 or "
        "--friction-range 0.1,0.3 (see calibrate band --help)");
  if (monte_carlo) {
    MonteCarloBandRequest request{report.problem, report.ranges, {}, 0, f.band_seed};
    for (int i = 0; i < 4; ++i)
      if (f.band_sd_option[i]->count() > 0) request.sd[i] = f.band_sd[i];
    request.samples = static_cast<std::size_t>(f.band_samples);
    return monte_carlo_band_text(request, format);
  }
  BandOptions options;
  options.samples_per_range = f.band_samples;
  try {
    Progress progress("calibrate band");
    progress.note("puncture at the corners of the intervals");
    report.band = puncture_band(report.problem, report.ranges, options);
  } catch (const std::invalid_argument& e) {
    rethrow_as_input(e);
  }
  if (!report.band.nominal.ok())
    throw SolveError("no puncture point at the nominal parameters: " + report.band.nominal.message,
                     report.band.nominal.status);
  return calibration_text(report, format);
}

// The starting Ogden exponents and term count of --ogden-alpha / --ogden-terms; refused for
// another law, and when both are given with different counts.
UniaxialFitOptions fit_options_of(const CLI::App& app, const ProblemFlags& pf,
                                  const CalibrationFlags& f, bool ogden) {
  UniaxialFitOptions options;
  options.test = f.fit_test == "equibiaxial" ? StressTest::Equibiaxial : StressTest::Uniaxial;
  const bool alpha = given(app, "--ogden-alpha"), terms = f.ogden_terms_option->count() > 0;
  if (!ogden && (alpha || terms))
    throw InputError(fmt::format(
        "{}: the starting Ogden exponents apply only to fitting the ogden law (--material ogden "
        "or --compare with ogden)",
        alpha ? "--ogden-alpha" : "--ogden-terms"));
  if (terms && (f.ogden_terms < 1 || f.ogden_terms > 3))
    throw InputError(fmt::format("--ogden-terms: Ogden takes 1 to 3 terms, got {}", f.ogden_terms));
  if (alpha && terms && static_cast<int>(pf.ogden_alpha.size()) != f.ogden_terms)
    throw InputError(fmt::format(
        "--ogden-alpha, --ogden-terms: {} starting exponents for {} terms; give one exponent "
        "per term (or only one of the flags)",
        pf.ogden_alpha.size(),
        f.ogden_terms));
  if (alpha) options.ogden_alpha_start = pf.ogden_alpha;
  options.ogden_terms = f.ogden_terms;
  return options;
}

// The laws of --compare: names, or "all".
std::vector<FitLaw> compared_laws(const std::vector<std::string>& names) {
  if (names.size() == 1 && names.front() == "all") return all_fit_laws();
  std::vector<FitLaw> laws;
  for (const auto& name : names) {
    FitLaw law{};
    try {
      law = fit_law_of(name);
    } catch (const InvalidInput& e) {
      throw InputError("--compare: " + e.errors().front().message + ", or all");
    }
    if (std::find(laws.begin(), laws.end(), law) != laws.end())
      throw InputError(fmt::format("--compare: {} is listed twice", name));
    laws.push_back(law);
  }
  return laws;
}

std::string run_fit_uniaxial(const CLI::App& app, const ProblemFlags& pf, const CalibrationFlags& f,
                             Format format) {
  for (const char* fitted : {"--shear-modulus",
                             "--jlim",
                             "--mr-alpha",
                             "--yeoh",
                             "--ogden-mu",
                             "--chain-segments",
                             "--chain-stretch",
                             "--i2-share",
                             "--material-preset"})
    if (given(app, fitted))
      throw InputError(fmt::format(
          "{}: `fit uniaxial` determines the material's parameters; do not give it", fitted));
  const bool compare = f.compare_option->count() > 0;
  if (compare && given(app, "--material"))
    throw InputError(
        "--compare, --material: --compare fits every law it lists; give one of them, not both");
  const auto laws =
      compare ? compared_laws(f.compare_laws) : std::vector<FitLaw>{fit_law_of(pf.material)};
  const bool ogden = std::find(laws.begin(), laws.end(), FitLaw::Ogden) != laws.end();
  const auto options = fit_options_of(app, pf, f, ogden);
  std::optional<SpecimenGeometry> specimen;
  int specimen_flags = 0;
  for (const auto* option : f.specimen_options) specimen_flags += option->count() > 0 ? 1 : 0;
  if (specimen_flags == 3) {
    require_finite(f.specimen_width_mm, "--specimen-width", "> 0 mm", f.specimen_width_mm > 0.0);
    require_finite(
        f.specimen_thickness_mm, "--specimen-thickness", "> 0 mm", f.specimen_thickness_mm > 0.0);
    require_finite(f.gauge_length_mm, "--gauge-length", "> 0 mm", f.gauge_length_mm > 0.0);
    specimen = SpecimenGeometry{f.specimen_width_mm, f.specimen_thickness_mm, f.gauge_length_mm};
  } else if (specimen_flags > 0) {
    throw InputError(
        "--specimen-width, --specimen-thickness, --gauge-length: give all three (force and "
        "displacement data) or none (stretch and stress data)");
  }
  // The most parameters of the laws fitted, and one more point for the residual's variance.
  std::size_t parameters = 1;
  for (const auto law : laws)
    parameters = std::max<std::size_t>(
        parameters,
        law == FitLaw::Ogden
            ? 2 * (options.ogden_alpha_start.empty() ? static_cast<std::size_t>(options.ogden_terms)
                                                     : options.ogden_alpha_start.size())
        : law == FitLaw::NeoHookean                      ? 1
        : law == FitLaw::Yeoh || law == FitLaw::GentGent ? 3
                                                         : 2);
  std::vector<UniaxialPoint> data;
  UniaxialFitReport report;
  UniaxialComparisonReport comparison;
  try {
    const auto table = read_numeric_csv(f.uniaxial_data, parameters + 1);
    data = uniaxial_points_from_table(table, specimen);
    Progress progress("fit uniaxial");
    progress.note("least squares");
    if (compare)
      comparison.fits = compare_uniaxial_fits(data, laws, options);
    else
      report.fit = fit_uniaxial(data, laws.front(), options);
  } catch (const CsvError& e) {
    throw InputError(e.what());
  } catch (const std::invalid_argument& e) {
    rethrow_as_input(e, f.uniaxial_data.c_str());
  }
  if (compare) {
    comparison.source = f.uniaxial_data;
    comparison.specimen = specimen;
    comparison.data = std::move(data);
    comparison.test = options.test;
    if (std::all_of(comparison.fits.begin(), comparison.fits.end(), [](const UniaxialFit& fit) {
          return fit.status == Status::NoConvergence;
        }))
      throw SolveError("no law's fit converged: " + comparison.fits.front().message,
                       Status::NoConvergence);
    return calibration_text(comparison, format);
  }
  report.source = f.uniaxial_data;
  report.specimen = specimen;
  report.data = std::move(data);
  if (report.fit.status == Status::NoConvergence)
    throw SolveError("the fit did not converge: " + report.fit.message, report.fit.status);
  if (!report.fit.ok()) throw SolveError(report.fit.message, report.fit.status);
  return calibration_text(report, format);
}

}  // namespace

void add_calibration_commands(CLI::App& app, CalibrationFlags& f) {
  f.calibrate =
      app.add_subcommand("calibrate",
                         "Model parameters from experiments: critical-i1 (inflation tests),\n"
                         "friction (hole size), jlim (puncture force); band (the puncture\n"
                         "force their uncertainties allow)");
  f.calibrate->require_subcommand(1);
  f.calibrate->footer(kCalibrateFooter);

  f.critical_i1 = f.calibrate->add_subcommand(
      "critical-i1",
      "Critical I1 from inflation (bulge) tests (paper §2.3): the mark at the\n"
      "membrane's centre (the pole) is stretched equibiaxially, lambda = burst\n"
      "radius / initial radius.  Each test's critical I1 is the largest I1 of the\n"
      "membrane (the --material law) inflated until its pole is stretched so: for\n"
      "Gent and neo-Hookean it is the pole's, 2 lambda^2 + lambda^-4 (the paper's),\n"
      "for Mooney-Rivlin it lies near the clamp.  Mean and sample sd over tests");
  f.critical_i1->footer(
      "The result does not depend on the clamp radius, thickness or modulus; --critical-i1\n"
      "is what is calibrated and must not be given.\n"
      "Examples:\n"
      "  puncture calibrate critical-i1 --mark-radius 0.5 --burst-radii 3.39,3.45,3.46,3.55\n"
      "  puncture calibrate critical-i1 bursts.csv      (columns burst_radius_mm and\n"
      "                                                  initial_radius_mm, or --mark-radius)\n"
      "  puncture calibrate critical-i1 --material mooney-rivlin --mr-alpha 0.1 \\\n"
      "      --mark-radius 0.5 --burst-radii 3.2      (its burst starts near the clamp)");
  f.mark_radius_option =
      f.critical_i1
          ->add_option("--mark-radius",
                       f.mark_radius_mm,
                       "Initial radius of the mark at the membrane's centre [mm] (> 0;\n"
                       "the paper's: 0.5)")
          ->group("Inflation tests");
  auto* radii = f.critical_i1
                    ->add_option("--burst-radii",
                                 f.burst_radii_mm,
                                 "Radius of the mark when the membrane burst, one per test\n"
                                 "[mm], comma-separated")
                    ->delimiter(',')
                    ->group("Inflation tests");
  auto* file = f.critical_i1
                   ->add_option("file",
                                f.burst_data,
                                "CSV file instead of --burst-radii: a header, then one row per\n"
                                "test with burst_radius_mm [mm] and initial_radius_mm [mm]\n"
                                "(or --mark-radius for all)")
                   ->type_name("FILE")
                   ->group("Inflation tests");
  radii->excludes(file);
  f.critical_i1
      ->add_flag("--pole-only",
                 f.pole_only,
                 "The paper's estimate: I1 at the pole, 2 lambda^2 + lambda^-4, whatever\n"
                 "the law (no membrane is solved)")
      ->group("Inflation tests");
  f.critical_i1
      ->add_option("--measure",
                   f.measure,
                   "The criterion (--criterion) whose critical value the tests give:\n"
                   "i1, max-stretch [dimensionless], energy-density [MPa] or\n"
                   "true-stress [MPa], each the largest over the burst membrane (with\n"
                   "--pole-only the pole's: lambda, W(lambda, lambda), lambda s(lambda));\n"
                   "energy and stress depend on --shear-modulus and the law")
      ->check(CLI::IsMember(local_criterion_names()))
      ->group("Inflation tests")
      ->capture_default_str();

  f.friction = f.calibrate->add_subcommand(
      "friction",
      "Friction coefficient mu' from the hole a dry membrane leaves (paper §4.2):\n"
      "indenter diameter / hole diameter = Part III stretch at puncture");
  f.friction->footer(
      "Two estimates: at the measured force (the paper's method: the sliding equilibrium at\n"
      "--puncture-force has the ratio as its Part III stretch), and at the predicted puncture\n"
      "(force-free: the predicted puncture has the ratio as its Part III stretch; with the\n"
      "crack at the corner that stretch depends only on the material, mu' and the critical\n"
      "I1).  Without --puncture-force only the second.\n"
      "Example:\n"
      "  puncture calibrate friction --indenter-radius 1 --puncture-force 1.72 \\\n"
      "      --hole-ratio 1.58 --hole-ratio-sd 0.14");
  f.friction
      ->add_option("--hole-ratio",
                   f.hole_ratio,
                   "Indenter diameter / hole diameter [dimensionless] (> 0; the\n"
                   "paper's dry 1 mm indenter: 1.58)")
      ->required()
      ->group("Hole");
  f.friction
      ->add_option("--hole-ratio-sd",
                   f.hole_ratio_sd,
                   "Standard deviation of the ratio [dimensionless] (>= 0; the\n"
                   "paper's: 0.14); gives the interval of mu'")
      ->group("Hole");
  f.friction_force_option =
      f.friction
          ->add_option("--puncture-force",
                       f.puncture_force_n,
                       "Measured puncture force [N] (> 0), for the paper's method")
          ->group("Hole");

  f.jlim = f.calibrate->add_subcommand(
      "jlim",
      "Gent J_lim from one puncture test (paper §4.1): the J_lim whose predicted\n"
      "puncture force (largest I1 = --critical-i1) equals the measured force");
  f.jlim->footer(
      "Example:\n"
      "  puncture calibrate jlim --indenter-radius 2 --puncture-force 0.7 --critical-i1 95.2\n"
      "The friction, stick criterion and Part II equation are the model's (--friction, ...).");
  f.jlim->add_option("--puncture-force", f.puncture_force_n, "Measured puncture force [N] (> 0)")
      ->required()
      ->group("Puncture test");
  f.jlim
      ->add_option("--puncture-force-sd",
                   f.puncture_force_sd_n,
                   "Standard deviation of the measured force [N] (>= 0)")
      ->group("Puncture test");
  f.jlim
      ->add_option("--critical-i1-sd",
                   f.critical_i1_sd,
                   "Standard deviation of the critical I1 [dimensionless] (>= 0;\n"
                   "the paper's: 4.8)")
      ->group("Puncture test");

  f.band = f.calibrate->add_subcommand(
      "band",
      "The predicted puncture force and depth, and their band, over intervals of the\n"
      "calibrated parameters (critical I1, friction, J_lim, G): mean +- sd or LO,HI");
  f.band->footer(
      "The nominal values are the physical flags' (--critical-i1, --friction, --jlim,\n"
      "--shear-modulus; default the paper's).  For each parameter give its standard deviation\n"
      "(the interval is nominal +- --sd-multiple sd) or its range LO,HI; the others stay fixed.\n"
      "The band is the least and largest prediction over every corner of the intervals (2^k\n"
      "puncture solves for k parameters).  Each parameter is also varied alone (the others\n"
      "nominal) at --samples points: its change of the force, its share of the first-order\n"
      "variance (the dominant parameter) and whether the prediction is monotone along it.\n"
      "Documented directions: the force rises with critical I1, friction and G and falls with\n"
      "J_lim; the depth rises with critical I1 and friction, falls with J_lim and does not\n"
      "depend on G.  The intervals are treated as independent: when J_lim was calibrated from\n"
      "a puncture force with the same critical I1 (calibrate jlim) their errors are\n"
      "correlated and the band is conservative.  A corner where the solver fails is reported\n"
      "(summary warnings, JSON warnings, CSV 'found' column), not left out silently.\n"
      "Example (the paper's critical I1 95.2 +- 4.8 and mu' 0.18 +- 0.05):\n"
      "  puncture calibrate band --critical-i1-sd 4.8 --friction-sd 0.05\n"
      "  puncture calibrate band --jlim-range 110,140 --shear-modulus-sd 0.00025 --format json");
  const char* band_help[4][2] = {
      {"Standard deviation of the critical I1 [dimensionless] (>= 0;\nthe paper's: 4.8)",
       "Range LO,HI of the critical I1 [dimensionless]"},
      {"Standard deviation of the friction coefficient mu'\n[dimensionless] (>= 0)",
       "Range LO,HI of mu' [dimensionless] (within [0, 10])"},
      {"Standard deviation of the Gent J_lim [dimensionless] (>= 0)",
       "Range LO,HI of J_lim [dimensionless]"},
      {"Standard deviation of the shear modulus G [MPa] (>= 0)", "Range LO,HI of G [MPa]"},
  };
  for (int i = 0; i < 4; ++i) {
    f.band_sd_option[i] =
        f.band->add_option(kBandFlags[i].sd, f.band_sd[i], band_help[i][0])->group("Intervals");
    f.band_range_option[i] =
        f.band->add_option(kBandFlags[i].range, f.band_range[i], band_help[i][1])
            ->delimiter(',')
            ->type_name("LO,HI")
            ->group("Intervals");
    f.band_sd_option[i]->excludes(f.band_range_option[i]);
  }
  f.band_sd_multiple_option =
      f.band
          ->add_option("--sd-multiple",
                       f.band_sd_multiple,
                       "Intervals from standard deviations are nominal +- this many sd\n"
                       "(> 0; default 1)")
          ->group("Intervals");
  f.band
      ->add_option("--samples",
                   f.band_samples,
                   "Points along each interval, ends included, where the prediction\n"
                   "is checked for monotonicity (2 to 1000; default 5); with --method\n"
                   "monte-carlo: the number of samples (2 to 10^8)")
      ->group("Intervals");
  f.band
      ->add_option("--method",
                   f.band_method,
                   "corners: the least and largest prediction over the intervals'\n"
                   "corners; monte-carlo: --samples random parameter sets on every\n"
                   "core, each parameter normal(nominal, sd) truncated to nominal +-\n"
                   "--sd-multiple sd (default 3 here) or uniform on LO,HI; reports the\n"
                   "force's and depth's percentiles and the parameters' ranking")
      ->check(CLI::IsMember({"corners", "monte-carlo"}))
      ->capture_default_str()
      ->group("Intervals");
  f.band->add_option("--seed", f.band_seed, "Seed of the Monte Carlo samples (default 1)")
      ->group("Intervals");

  f.fit = app.add_subcommand(
      "fit", "Least-squares fits of material tests: uniaxial, curve (force-depth records)");
  f.fit->require_subcommand(1);
  f.uniaxial = f.fit->add_subcommand(
      "uniaxial",
      "Fit any law (--material) to a uniaxial tensile test (paper §4.1, Fig. 11) or an\n"
      "equibiaxial one (--test) by bounded Levenberg-Marquardt: each parameter with its\n"
      "standard error and whether the data determine it, their correlations and AIC/BIC;\n"
      "--compare ranks several laws on the same data by AIC");
  f.uniaxial->footer(
      "The CSV file has a header and the columns stretch,nominal_stress_mpa, or\n"
      "force_n,displacement_mm with the specimen's --specimen-width, --specimen-thickness\n"
      "and --gauge-length [mm] (stretch = 1 + displacement / gauge length, nominal stress =\n"
      "force / (width thickness)).  --material chooses the law; its parameters:\n"
      "  gent G, J_lim; neo-hookean G; mooney-rivlin G, alpha; yeoh C10, C20, C30 [MPa];\n"
      "  ogden mu_p [MPa], alpha_p, N = 1 to 3 terms (--ogden-terms, or --ogden-alpha:\n"
      "  the starting exponents); arruda-boyce G, N; gent-gent G, J_lim, beta.\n"
      "The parameters stay in the law's range (G > 0; mooney-rivlin 0 <= alpha <= 1;\n"
      "gent, gent-gent 0 <= 1/J_lim < 1/(I1 - 3) at the largest stretch; arruda-boyce\n"
      "3 N above it; yeoh C20, C30 >= 0; ogden mu_p alpha_p >= 0 and |alpha_p| >= 1, each\n"
      "alpha_p keeping its starting sign; gent-gent 0 <= beta <= 1); a best fit on the\n"
      "edge of that range means the law does not describe the data: exit 2, saying\n"
      "which edge (--compare lists it instead).  AIC = n ln(RSS/n) + 2k with k the law's\n"
      "parameters plus the variance; only differences between laws mean anything.\n"
      "Examples:\n"
      "  puncture fit uniaxial tensile.csv --material gent --specimen-width 10 \\\n"
      "      --specimen-thickness 0.2 --gauge-length 60\n"
      "  puncture fit uniaxial treloar.csv --compare all --plot laws.png");
  f.uniaxial->add_option("file", f.uniaxial_data, "CSV file of the tensile test")
      ->required()
      ->type_name("FILE");
  f.specimen_options = {
      f.uniaxial->add_option("--specimen-width", f.specimen_width_mm, "Specimen width [mm] (> 0)")
          ->group("Specimen (force and displacement data)"),
      f.uniaxial
          ->add_option(
              "--specimen-thickness", f.specimen_thickness_mm, "Specimen thickness [mm] (> 0)")
          ->group("Specimen (force and displacement data)"),
      f.uniaxial->add_option("--gauge-length", f.gauge_length_mm, "Initial gauge length [mm] (> 0)")
          ->group("Specimen (force and displacement data)"),
  };
  f.uniaxial
      ->add_option("--test",
                   f.fit_test,
                   "The test the data come from: uniaxial (lambda2 = lambda3 =\n"
                   "lambda^-1/2) or equibiaxial (lambda1 = lambda2 = lambda, e.g. the\n"
                   "pole of an inflated membrane); the stress is nominal [MPa]")
      ->check(CLI::IsMember({"uniaxial", "equibiaxial"}))
      ->capture_default_str()
      ->group("Law");
  f.ogden_terms_option =
      f.uniaxial
          ->add_option("--ogden-terms",
                       f.ogden_terms,
                       "Ogden terms N to fit (1 to 3; default 3), from the exponents\n"
                       "{2}, {3,-2} or Ogden's {1.3,5,-2}; --ogden-alpha A1,...,AN\n"
                       "gives other starting exponents instead")
          ->group("Law");
  f.compare_option =
      f.uniaxial
          ->add_option("--compare",
                       f.compare_laws,
                       "Fit each law of a comma-separated list (or all) to the data and\n"
                       "rank them by AIC: n, k, RSS [MPa^2], AIC, delta AIC, AICc, BIC\n"
                       "(instead of --material)")
          ->delimiter(',')
          ->type_name("LAWS")
          ->group("Law");
  add_fit_curve_command(*f.fit, f.curve);
}

std::string run_calibration(const CLI::App& app, const ProblemFlags& problem,
                            const CalibrationFlags& f, Format format) {
  if (f.critical_i1->parsed()) return run_critical_i1(app, problem, f, format);
  if (f.friction->parsed()) return run_friction(app, problem, f, format);
  if (f.jlim->parsed()) return run_jlim(app, problem, f, format);
  if (f.band->parsed()) return run_band(problem, f, format);
  if (f.curve.app->parsed()) return run_fit_curve(problem, f.curve, format);
  return run_fit_uniaxial(app, problem, f, format);
}

}  // namespace puncture::cli
