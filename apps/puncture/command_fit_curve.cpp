// `puncture fit curve`: flags, the per-test manifest, the records, the fit.
#include "command_fit_curve.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <toml.hpp>

#include "calibration/curve_fit_output.hpp"
#include "cli_error.hpp"
#include "parameter_flags.hpp"
#include "puncture/curve_fit.hpp"
#include "puncture/force_depth_record.hpp"

namespace puncture::cli {

namespace {

constexpr const char* kRecord = "Records";
constexpr const char* kFit = "Fit";

std::vector<std::string> split_list(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto at = text.find(separator, start);
    auto item = text.substr(start, at == std::string::npos ? std::string::npos : at - start);
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    out.push_back(item);
    if (at == std::string::npos) break;
    start = at + 1;
  }
  return out;
}

ColumnChoice column_choice(const std::string& text, const char* flag) {
  if (text.empty()) throw InputError(fmt::format("{}: give a column name or position", flag));
  if (std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); })) {
    const int index = text.size() > 6 ? 0 : std::stoi(text);
    if (index < 1)
      throw InputError(fmt::format("{}: a column position counts from 1, got {}", flag, text));
    return {"", index};
  }
  return {text, 0};
}

Tristate tristate(const std::string& text, const char* yes, const char* no) {
  if (text == yes) return Tristate::Yes;
  if (text == no) return Tristate::No;
  return Tristate::Auto;
}

RecordFormat format_of(const FitCurveFlags& f) {
  RecordFormat r;
  r.depth = column_choice(f.depth_column, "--depth-column");
  r.force = column_choice(f.force_column, "--force-column");
  r.depth_unit = *depth_unit_from_token(f.depth_unit);
  r.force_unit = *force_unit_from_token(f.force_unit);
  r.header = tristate(f.header, "yes", "no");
  r.separator = f.separator == "comma"       ? ','
                : f.separator == "semicolon" ? ';'
                : f.separator == "tab"       ? '\t'
                                             : 0;
  r.decimal_comma = tristate(f.decimal, "comma", "point");
  if (r.decimal_comma == Tristate::Yes && r.separator == ',')
    throw InputError("--decimal comma: needs --separator semicolon or tab");
  if (f.contact_depth_option && f.contact_depth_option->count() > 0) {
    if (!std::isfinite(f.contact_depth))
      throw InputError("--contact-depth: must be a finite number (the record's depth unit)");
    r.contact_depth = f.contact_depth;
  }
  if (!(f.drop_fraction > 0.0 && f.drop_fraction < 1.0))
    throw InputError(fmt::format("--perforation-drop: must be in (0, 1), got {}", f.drop_fraction));
  r.drop_fraction = f.drop_fraction;
  r.cut_at_perforation = !f.no_perforation_cut;
  return r;
}

CurveFitOptions options_of(const FitCurveFlags& f, const Problem& first) {
  CurveFitOptions o;
  if (f.free.empty()) throw InputError("--free: name the parameters to fit, e.g. --free jlim");
  for (const auto& name : split_list(f.free, ',')) {
    const auto p = curve_parameter_from_token(name);
    if (!p)
      throw InputError(fmt::format(
          "--free: unknown parameter '{}' (choose from: {})", name, curve_parameter_tokens()));
    if (std::find(o.free.begin(), o.free.end(), *p) != o.free.end())
      throw InputError(fmt::format("--free: '{}' is named twice", name));
    o.free.push_back(*p);
  }
  for (const auto& text : f.bounds) {
    const auto parts = split_list(text, ':');
    std::optional<CurveParameter> p;
    if (parts.size() == 3) p = curve_parameter_from_token(parts[0]);
    double lo = 0.0, hi = 0.0;
    bool numbers = false;
    if (p) try {
        std::size_t a = 0, b = 0;
        lo = std::stod(parts[1], &a);
        hi = std::stod(parts[2], &b);
        numbers = a == parts[1].size() && b == parts[2].size();
      } catch (const std::exception&) {
      }
    if (!p || !numbers || !std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
      throw InputError(
          fmt::format("--bound: expected NAME:LO:HI with LO < HI (NAME one of {}), got '{}'",
                      curve_parameter_tokens(),
                      text));
    if (std::find(o.free.begin(), o.free.end(), *p) == o.free.end())
      throw InputError(fmt::format("--bound: {} is not free (--free)", parts[0]));
    o.bounds.push_back({*p, lo, hi});
  }
  if (f.loss != "none" && !(f.loss_scale_n > 0.0 && std::isfinite(f.loss_scale_n)))
    throw InputError(fmt::format("--loss-scale: --loss {} needs a scale > 0 N", f.loss));
  o.loss = f.loss == "huber"    ? RobustLoss::Huber
           : f.loss == "cauchy" ? RobustLoss::Cauchy
                                : RobustLoss::None;
  o.loss_scale_n = f.loss_scale_n;
  if (!(f.puncture_sd_fraction > 0.0 && f.puncture_sd_fraction < 1.0))
    throw InputError(
        fmt::format("--puncture-sd: must be in (0, 1), got {}", f.puncture_sd_fraction));
  o.puncture_force_sd_fraction = o.puncture_depth_sd_fraction = f.puncture_sd_fraction;
  if (!(f.min_r_squared >= 0.0 && f.min_r_squared < 1.0))
    throw InputError(fmt::format("--min-r2: must be in [0, 1), got {}", f.min_r_squared));
  o.min_r_squared = f.min_r_squared;
  (void)first;
  return o;
}

// One test of the manifest: its file and the flags it sets.
struct TestSpec {
  std::string file;
  ProblemFlags problem;
  RecordFormat format;
  std::string where;  // "manifest.toml:4 (test 2)"
};

std::vector<TestSpec> read_manifest(const std::string& path, const ProblemFlags& base,
                                    const RecordFormat& base_format) {
  toml::value data;
  try {
    data = toml::parse(path);
  } catch (const std::exception& e) {
    throw InputError(fmt::format("--manifest: {}", e.what()));
  }
  const auto dir = std::filesystem::path(path).parent_path();
  std::vector<TestSpec> specs;
  if (!data.is_table()) throw InputError(fmt::format("{}: not a TOML table", path));
  for (const auto& [key, value] : data.as_table())
    if (key != "test")
      throw InputError(fmt::format("{}:{}: unknown key '{}' (the manifest holds [[test]] tables)",
                                   path,
                                   value.location().line(),
                                   key));
  if (!data.contains("test") || !data.at("test").is_array())
    throw InputError(
        fmt::format("{}: no [[test]] table: list the tests as [[test]] with file = "
                    "\"...\"",
                    path));
  int n = 0;
  for (const auto& t : data.at("test").as_array()) {
    ++n;
    TestSpec spec{
        "", base, base_format, fmt::format("{}:{} (test {})", path, t.location().line(), n)};
    if (!t.is_table()) throw InputError(spec.where + ": each test must be a [[test]] table");
    // A test with its own indenter gives that probe's dimensions (read in any key order): the
    // flags' describe their own probe.
    if (t.contains("indenter")) {
      spec.problem.fillet_radius_mm = 0.0;
      spec.problem.ball_radius_mm.reset();
      spec.problem.cone_half_angle_deg.reset();
      spec.problem.tip_radius_mm.reset();
    }
    for (const auto& [key, value] : t.as_table()) {
      const auto at = fmt::format("{}:{}: key '{}'", path, value.location().line(), key);
      const auto number = [&]() {
        if (value.is_integer()) return static_cast<double>(value.as_integer());
        if (value.is_floating()) return value.as_floating();
        throw InputError(at + ": must be a number");
      };
      const auto text = [&]() {
        if (value.is_string()) return value.as_string().str;
        if (value.is_integer()) return std::to_string(value.as_integer());
        throw InputError(at + ": must be a string");
      };
      if (key == "file")
        spec.file = text();
      else if (key == "clamp-radius")
        spec.problem.clamp_radius_mm = number();
      else if (key == "indenter") {
        spec.problem.indenter = text();
        if (!is_indenter_shape(spec.problem.indenter))
          throw InputError(at + ": must be flat, sphere-tipped, ball or cone");
      } else if (key == "indenter-radius")
        spec.problem.indenter_radius_mm = number();
      else if (key == "fillet-radius")
        spec.problem.fillet_radius_mm = number();
      else if (key == "ball-radius")
        spec.problem.ball_radius_mm = number();
      else if (key == "cone-half-angle")
        spec.problem.cone_half_angle_deg = number();
      else if (key == "tip-radius")
        spec.problem.tip_radius_mm = number();
      else if (key == "thickness")
        spec.problem.thickness_mm = number();
      else if (key == "prestretch")
        spec.problem.prestretch = number();
      else if (key == "friction")
        spec.problem.friction = number();
      else if (key == "critical-i1")
        spec.problem.critical_i1 = number();
      else if (key == "stick")
        spec.problem.stick = text();
      else if (key == "depth-column")
        spec.format.depth = column_choice(text(), at.c_str());
      else if (key == "force-column")
        spec.format.force = column_choice(text(), at.c_str());
      else if (key == "depth-unit") {
        const auto u = depth_unit_from_token(text());
        if (!u) throw InputError(at + ": must be mm, m or in");
        spec.format.depth_unit = *u;
      } else if (key == "force-unit") {
        const auto u = force_unit_from_token(text());
        if (!u) throw InputError(at + ": must be N, kN, lbf or gf");
        spec.format.force_unit = *u;
      } else if (key == "contact-depth")
        spec.format.contact_depth = number();
      else
        throw InputError(at +
                         ": unknown (per-test keys: file, clamp-radius, indenter, "
                         "indenter-radius, fillet-radius, ball-radius, cone-half-angle, "
                         "tip-radius, thickness, prestretch, friction, critical-i1, "
                         "stick, depth-column, force-column, depth-unit, force-unit, "
                         "contact-depth)");
    }
    if (spec.file.empty()) throw InputError(spec.where + ": no file = \"...\"");
    if (std::filesystem::path(spec.file).is_relative()) spec.file = (dir / spec.file).string();
    specs.push_back(std::move(spec));
  }
  if (specs.empty()) throw InputError(fmt::format("{}: no test listed", path));
  return specs;
}

}  // namespace

void add_fit_curve_command(CLI::App& fit, FitCurveFlags& f) {
  f.app = fit.add_subcommand(
      "curve",
      "Fit chosen parameters (--free) jointly to one or more measured force-depth\n"
      "records of indentation tests (Ceres Levenberg-Marquardt): estimates with\n"
      "standard errors, 95 % intervals, correlations and warnings for parameters\n"
      "the tests do not identify");
  f.app->footer(
      "Each record is a testing machine's CSV: the depth (crosshead displacement) and force\n"
      "columns by name or 1-based position, in --depth-unit and --force-unit, with or\n"
      "without a header, separated by commas, semicolons or tabs (a decimal comma with ';'\n"
      "or tab).  The depth's zero is --contact-depth (in the record's unit) or the contact\n"
      "found from the data: the last point before the force rises above the first 10\n"
      "forces' mean + 5 sd for 5 points in a row (late by ~(threshold/F)^(1/3) of the depth,\n"
      "since the force grows as depth^3: give it when known, or fit each test's offset\n"
      "from it with --free ...,contact-offset).  The record ends at the\n"
      "perforation: the largest force before the first one below (1 - --perforation-drop)\n"
      "of it, once it has reached a tenth of the record's largest; that point is the\n"
      "puncture point, fitted too (sd --puncture-sd of its force and depth) unless\n"
      "--ignore-puncture.\n"
      "The physical flags (see puncture --help) describe every test and give the free\n"
      "parameters' starting values; --manifest FILE (TOML) lists the tests with their own\n"
      "settings instead of the files:\n"
      "  [[test]]\n"
      "  file = \"lubricated_2mm.csv\"   # relative to the manifest\n"
      "  indenter-radius = 2\n"
      "  friction = 0.18\n"
      "  [[test]]\n"
      "  file = \"dry_1mm.csv\"\n"
      "  indenter-radius = 1\n"
      "  friction = 1.95\n"
      "  contact-depth = 0.12\n"
      "Per-test keys: file, clamp-radius, indenter (flat, sphere-tipped, ball or cone),\n"
      "indenter-radius, fillet-radius, ball-radius, cone-half-angle, tip-radius,\n"
      "thickness, prestretch, friction, critical-i1, stick, depth-column, force-column,\n"
      "depth-unit, force-unit, contact-depth (the flags' names and units).  A test that\n"
      "changes the indenter gives its own probe's dimensions.  The free parameters are\n"
      "shared by every test.\n"
      "A fit on a bound (--bound), or one explaining less than --min-r2 of the force\n"
      "variance (the data are not a curve of the model), exits 2 saying so.\n"
      "Examples:\n"
      "  puncture fit curve test.csv --free shear-modulus,jlim --indenter-radius 2\n"
      "  puncture fit curve --manifest tests.toml --free shear-modulus,jlim,friction \\\n"
      "      --depth-column 2 --force-column 3 --force-unit kN --format json");
  f.app->add_option("files", f.files, "CSV records of the tests")->type_name("FILE ...");
  auto* manifest = f.app->add_option("--manifest", f.manifest, "TOML list of the tests (above)")
                       ->type_name("FILE")
                       ->group(kRecord);
  manifest->excludes(f.app->get_option("files"));
  f.app
      ->add_option("--free",
                   f.free,
                   "Parameters to fit, comma-separated: shear-modulus [MPa], jlim,\n"
                   "friction, critical-i1 (needs a puncture point), stick-threshold\n"
                   "(the --stick rule's, in its unit; one test, alone or with others;\n"
                   "by a profile over where the switch falls, its interval where the\n"
                   "cost rises by chi2(0.95, 1)), contact-offset [mm] (each test's own:\n"
                   "the model's depth is the record's minus it; removes the bias of a\n"
                   "contact point found late)")
      ->required()
      ->type_name("LIST")
      ->group(kFit);
  f.app->add_option("--depth-column", f.depth_column, "Depth column: header name or position")
      ->capture_default_str()
      ->group(kRecord);
  f.app->add_option("--force-column", f.force_column, "Force column: header name or position")
      ->capture_default_str()
      ->group(kRecord);
  f.app->add_option("--depth-unit", f.depth_unit, "Unit of the depth column: mm, m or in")
      ->check(CLI::IsMember({"mm", "m", "in"}))
      ->capture_default_str()
      ->group(kRecord);
  f.app->add_option("--force-unit", f.force_unit, "Unit of the force column: N, kN, lbf or gf")
      ->check(CLI::IsMember({"N", "kN", "lbf", "gf"}))
      ->capture_default_str()
      ->group(kRecord);
  f.app->add_option("--header", f.header, "auto (a first line with text), yes or no")
      ->check(CLI::IsMember({"auto", "yes", "no"}))
      ->capture_default_str()
      ->group(kRecord);
  f.app->add_option("--separator", f.separator, "auto, comma, semicolon or tab")
      ->check(CLI::IsMember({"auto", "comma", "semicolon", "tab"}))
      ->capture_default_str()
      ->group(kRecord);
  f.app
      ->add_option("--decimal",
                   f.decimal,
                   "Decimal mark: auto (comma with a ';' or tab separator), point,\n"
                   "comma")
      ->check(CLI::IsMember({"auto", "point", "comma"}))
      ->capture_default_str()
      ->group(kRecord);
  f.contact_depth_option =
      f.app
          ->add_option("--contact-depth",
                       f.contact_depth,
                       "The depth column's value at contact (the depth's zero), in\n"
                       "--depth-unit; default: found from the data")
          ->group(kRecord);
  f.app
      ->add_option("--perforation-drop",
                   f.drop_fraction,
                   "Perforation: the force falls below (1 - this) of its largest\n"
                   "[dimensionless] (in (0, 1))")
      ->capture_default_str()
      ->group(kRecord);
  f.app->add_flag("--no-perforation-cut", f.no_perforation_cut, "Keep the whole record")
      ->group(kRecord);
  f.app
      ->add_flag("--ignore-puncture",
                 f.ignore_puncture,
                 "Do not fit the puncture point (the perforation) of the records")
      ->group(kFit);
  f.app
      ->add_option("--puncture-sd",
                   f.puncture_sd_fraction,
                   "Standard deviation of a puncture point's force and depth, as a\n"
                   "fraction of each (the scatter between tests) [dimensionless]")
      ->capture_default_str()
      ->group(kFit);
  f.app
      ->add_option("--bound",
                   f.bounds,
                   "NAME:LO:HI, the range of a free parameter (its unit), repeatable;\n"
                   "defaults: shear-modulus 1e-6:1e3, jlim (critical-i1 - 3):1e6,\n"
                   "friction 0:10, critical-i1 3:1e4, stick-threshold 1e-12:1e6,\n"
                   "contact-offset -+ half of each test's deepest depth [mm]")
      ->type_name("NAME:LO:HI")
      ->group(kFit);
  f.app->add_option("--loss", f.loss, "Robust loss of the curve residuals: none, huber, cauchy")
      ->check(CLI::IsMember({"none", "huber", "cauchy"}))
      ->capture_default_str()
      ->group(kFit);
  f.app->add_option("--loss-scale", f.loss_scale_n, "Scale of the robust loss [N] (> 0)")
      ->group(kFit);
  f.app
      ->add_option("--min-r2",
                   f.min_r_squared,
                   "Least share of the force variance the fit must explain (R^2)")
      ->capture_default_str()
      ->group(kFit);
}

std::string run_fit_curve(const ProblemFlags& pf, const FitCurveFlags& f, Format format,
                          std::string* json) {
  const RecordFormat base_format = format_of(f);
  std::vector<TestSpec> specs;
  if (!f.manifest.empty()) {
    specs = read_manifest(f.manifest, pf, base_format);
  } else {
    if (f.files.empty())
      throw InputError("fit curve: give the CSV records (FILE ...) or --manifest FILE");
    for (const auto& file : f.files) specs.push_back({file, pf, base_format, file});
  }
  CurveFitReport report;
  for (const auto& spec : specs) {
    CurveTest test;
    test.name = spec.file;
    try {
      test.problem = make_problem(spec.problem);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", spec.where, e.what()));
    }
    ForceDepthRecord record;
    try {
      record = read_force_depth_record(spec.file, spec.format);
    } catch (const CsvError& e) {
      throw InputError(e.what());
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("{}: {}", spec.where, e.what()));
    }
    test.depth_mm = record.depth_mm;
    test.force_n = record.force_n;
    if (record.perforation_depth_mm && !f.ignore_puncture)
      test.puncture = MeasuredPuncture{*record.perforation_depth_mm, *record.perforation_force_n};
    report.records.push_back(std::move(record));
    report.problem.tests.push_back(std::move(test));
  }
  report.options = options_of(f, report.problem.tests.front().problem);
  const std::size_t p = report.options.free.size();
  for (const auto& r : report.records)
    if (r.depth_mm.size() < p + 1)
      throw InputError(fmt::format(
          "{}: {} point{} past the contact point{}: fewer than the {} needed for {} free "
          "parameter{} (--free)",
          r.source,
          r.depth_mm.size(),
          r.depth_mm.size() == 1 ? "" : "s",
          r.perforation_depth_mm ? " up to the perforation" : "",
          p + 1,
          p,
          p == 1 ? "" : "s"));
  try {
    report.fit = fit_curves(report.problem, report.options);
  } catch (const InvalidInput& e) {
    std::string message;
    for (const auto& err : e.errors())
      message += fmt::format("\n  {}{}", err.parameter == "free" ? "--free: " : "", err.message);
    throw InputError("invalid curve fit:" + message);
  }
  if (!report.fit.ok()) throw SolveError(report.fit.message, report.fit.status);
  if (json) *json = curve_fit_text(report, Format::Json);
  return curve_fit_text(report, format);
}

}  // namespace puncture::cli
