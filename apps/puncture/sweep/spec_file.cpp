#include "spec_file.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <toml.hpp>

#include "cli_error.hpp"
#include "problem_options.hpp"

namespace puncture::cli {

namespace {

// The reader's position for error messages: the file and the line of a value.
class SpecReader {
 public:
  explicit SpecReader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const toml::value& at, const std::string& message) const {
    throw InputError(fmt::format("{} line {}: {}", path_, at.location().line(), message));
  }

  double number(const toml::value& v, const std::string& key) const {
    if (v.is_integer()) return static_cast<double>(v.as_integer());
    if (v.is_floating() && std::isfinite(v.as_floating())) return v.as_floating();
    fail(v, fmt::format("'{}' must be a finite number", key));
  }

  std::vector<double> numbers(const toml::value& v, const std::string& key) const {
    if (!v.is_array()) fail(v, fmt::format("'{}' must be an array of numbers, e.g. [1, 2]", key));
    std::vector<double> out;
    for (const toml::value& x : v.as_array()) out.push_back(number(x, key));
    return out;
  }

  // A value as the flag's text: numbers in their shortest exact form, words as written, an
  // array comma-separated (e.g. yeoh = [0.03, 0.001, 0]).
  std::string text(const toml::value& v, const std::string& key) const {
    if (v.is_integer()) return std::to_string(v.as_integer());
    if (v.is_floating()) return fmt::format("{}", number(v, key));
    if (v.is_string()) return toml::get<std::string>(v);
    if (v.is_boolean()) return v.as_boolean() ? "true" : "false";
    if (v.is_array()) {
      std::string joined;
      for (const toml::value& x : v.as_array())
        joined += (joined.empty() ? "" : ",") + text(x, key);
      return joined;
    }
    fail(v, fmt::format("'{}' must be a number, a word or an array of them", key));
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// A table's entries in the file's order (toml11's table is unordered): columns, the grid's
// order and the samples' streams follow the order in which the parameters are written.
std::vector<std::pair<std::string, const toml::value*>> in_file_order(const toml::value& table) {
  std::vector<std::pair<std::string, const toml::value*>> entries;
  for (const auto& [key, value] : table.as_table()) entries.emplace_back(key, &value);
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    const auto la = a.second->location().line(), lb = b.second->location().line();
    return la != lb ? la < lb : a.first < b.first;
  });
  return entries;
}

void check_flag(const SpecReader& r, const toml::value& at, const std::string& key,
                const char* table) {
  const auto names = problem_flag_names();
  if (std::find(names.begin(), names.end(), key) == names.end())
    r.fail(at,
           fmt::format("[{}] '{}' is not a flag of the problem (the flags: {})",
                       table,
                       key,
                       fmt::join(names, ", ")));
}

DistributionKind distribution_kind(const SpecReader& r, const toml::value& v,
                                   const std::string& name) {
  const std::string word = r.text(v, name + ".distribution");
  for (DistributionKind k : {DistributionKind::Uniform,
                             DistributionKind::Normal,
                             DistributionKind::LogNormal,
                             DistributionKind::TruncatedNormal})
    if (to_token(k) == word) return k;
  r.fail(v,
         fmt::format("'{}.distribution': '{}' is not uniform, normal, lognormal or "
                     "truncated-normal",
                     name,
                     word));
}

SweepParameter parameter_of(const SpecReader& r, const std::string& name, const toml::value& v,
                            SweepDesign design) {
  if (!v.is_table())
    r.fail(v,
           fmt::format(
               "parameter '{}' must be a table, e.g. {} = {{ range = [0.1, 0.3] }}", name, name));
  SweepParameter p;
  p.name = name;
  std::optional<std::vector<double>> range;
  std::optional<int> levels;
  bool has_distribution = false, has_mean = false, has_sd = false;
  for (const auto& [key, value] : in_file_order(v)) {
    const std::string where = name + "." + key;
    if (key == "range") {
      range = r.numbers(*value, where);
      if (range->size() != 2 || (*range)[0] > (*range)[1])
        r.fail(*value, fmt::format("'{}' must be [lower, upper] with lower <= upper", where));
    } else if (key == "levels") {
      const double n = r.number(*value, where);
      if (!value->is_integer() || n < 2 || n > 1e6)
        r.fail(*value, fmt::format("'{}' must be a whole number from 2 to 10^6", where));
      levels = static_cast<int>(n);
    } else if (key == "values") {
      if (!value->is_array() || value->as_array().empty())
        r.fail(*value, fmt::format("'{}' must be a non-empty array", where));
      for (const toml::value& x : value->as_array()) p.levels.push_back(r.text(x, where));
    } else if (key == "distribution") {
      p.distribution.kind = distribution_kind(r, *value, name);
      has_distribution = true;
    } else if (key == "mean") {
      p.distribution.mean = r.number(*value, where);
      has_mean = true;
    } else if (key == "sd") {
      p.distribution.sd = r.number(*value, where);
      has_sd = true;
    } else {
      r.fail(*value,
             fmt::format("unknown key '{}' (a parameter has range, levels, values, "
                         "distribution, mean, sd)",
                         where));
    }
  }
  const auto refuse = [&](const std::string& what) {
    r.fail(v, fmt::format("parameter '{}': {}", name, what));
  };
  if (design == SweepDesign::Grid) {
    if (has_distribution || has_mean || has_sd)
      refuse(
          "a grid takes values = [...] or range = [lower, upper] with levels = N, not a "
          "distribution");
    if (!p.levels.empty() && (range || levels))
      refuse("give values, or range with levels, not both");
    if (p.levels.empty()) {
      if (!range || !levels)
        refuse("a grid needs values = [...] or range = [lower, upper] with levels = N");
      p.levels = evenly_spaced_levels((*range)[0], (*range)[1], *levels);
    }
    return p;
  }
  if (!p.levels.empty() || levels)
    refuse(
        fmt::format("values and levels belong to a grid; a {} design samples a range or a "
                    "distribution",
                    to_token(design)));
  const DistributionKind kind = p.distribution.kind;
  const bool needs_range =
      kind == DistributionKind::Uniform || kind == DistributionKind::TruncatedNormal;
  const bool needs_moments = kind != DistributionKind::Uniform;
  if (needs_range != range.has_value())
    refuse(fmt::format("a {} distribution {} range = [lower, upper]",
                       to_token(kind),
                       needs_range ? "needs" : "takes no"));
  if (needs_moments != (has_mean && has_sd))
    refuse(fmt::format(
        "a {} distribution {} mean and sd", to_token(kind), needs_moments ? "needs" : "takes no"));
  if (range) {
    p.distribution.lower = (*range)[0];
    p.distribution.upper = (*range)[1];
  }
  return p;
}

SweepDesign design_of(const SpecReader& r, const toml::value& v) {
  const std::string word = r.text(v, "design");
  for (SweepDesign d : {SweepDesign::Grid,
                        SweepDesign::LatinHypercube,
                        SweepDesign::Sobol,
                        SweepDesign::MonteCarlo})
    if (to_token(d) == word) return d;
  r.fail(v, fmt::format("'design': '{}' is not grid, latin-hypercube, sobol or monte-carlo", word));
}

}  // namespace

std::vector<std::string> problem_flag_names() {
  CLI::App app;
  ProblemFlags flags;
  add_problem_options(app, flags);
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options())
    if (!o->get_lnames().empty() && o->get_lnames().front() != "help")
      names.push_back(o->get_lnames().front());
  return names;
}

SweepFile read_sweep_file(const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw InputError(fmt::format("sweep: cannot read the spec '{}': no such file", path));
  toml::value data;
  try {
    data = toml::parse(path);
  } catch (const toml::syntax_error& e) {
    throw InputError(fmt::format("sweep: {} is not valid TOML:\n{}", path, e.what()));
  } catch (const std::exception& e) {
    throw InputError(fmt::format("sweep: cannot read the spec '{}': {}", path, e.what()));
  }
  const SpecReader r(path);
  SweepFile file;
  SweepSpec& spec = file.spec;
  const toml::value* parameters = nullptr;
  // The design first: how each parameter is read depends on it.
  if (data.contains("design"))
    spec.design = design_of(r, data.at("design"));
  else
    throw InputError(
        fmt::format("{}: 'design' is missing (grid, latin-hypercube, sobol or monte-carlo)", path));
  for (const auto& [key, value] : in_file_order(data)) {
    if (key == "design") continue;
    if (key == "samples") {
      const double n = r.number(*value, key);
      if (!value->is_integer() || n < 1) r.fail(*value, "'samples' must be a whole number >= 1");
      spec.samples = static_cast<std::size_t>(value->as_integer());
    } else if (key == "seed") {
      if (!value->is_integer() || value->as_integer() < 0)
        r.fail(*value, "'seed' must be a whole number >= 0");
      spec.seed = static_cast<std::uint64_t>(value->as_integer());
    } else if (key == "puncture") {
      if (!value->is_boolean()) r.fail(*value, "'puncture' must be true or false");
      spec.outputs.puncture = value->as_boolean();
    } else if (key == "warm-start") {
      if (!value->is_boolean()) r.fail(*value, "'warm-start' must be true or false");
      if (value->as_boolean() && spec.design != SweepDesign::Grid)
        r.fail(*value,
               fmt::format("'warm-start': a {} has no neighbouring points to start from (only a "
                           "grid does); its points are always solved cold",
                           to_token(spec.design)));
      spec.warm_start = value->as_boolean();
    } else if (key == "force-at-depth") {
      spec.outputs.force_at_depth_mm = r.numbers(*value, key);
      for (const double depth : spec.outputs.force_at_depth_mm)
        if (depth < 0.0)
          r.fail(*value, fmt::format("'force-at-depth': depths are >= 0 mm, got {}", depth));
    } else if (key == "problem") {
      if (!value->is_table()) r.fail(*value, "'problem' must be a table ([problem])");
      for (const auto& [flag, v] : in_file_order(*value)) {
        check_flag(r, *v, flag, "problem");
        file.fixed.emplace_back(flag, r.text(*v, flag));
      }
    } else if (key == "parameters") {
      if (!value->is_table()) r.fail(*value, "'parameters' must be a table ([parameters])");
      parameters = value;
    } else {
      r.fail(*value,
             fmt::format("unknown key '{}' (the spec's keys: design, samples, seed, puncture, "
                         "force-at-depth, warm-start, [problem], [parameters])",
                         key));
    }
  }
  if (!parameters)
    throw InputError(fmt::format("{}: [parameters] is missing: nothing is swept", path));
  for (const auto& [name, v] : in_file_order(*parameters)) {
    check_flag(r, *v, name, "parameters");
    for (const auto& [flag, value] : file.fixed)
      if (flag == name)
        r.fail(*v, fmt::format("'{}' is both fixed in [problem] and swept in [parameters]", name));
    spec.parameters.push_back(parameter_of(r, name, *v, spec.design));
  }
  if (auto errors = validation_errors(spec); !errors.empty()) {
    std::string text = fmt::format("{}: invalid sweep:", path);
    for (const ValidationError& e : errors) text += "\n  " + e.message;
    throw InputError(text);
  }
  return file;
}

}  // namespace puncture::cli
