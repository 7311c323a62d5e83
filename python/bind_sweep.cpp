// Sweeps (include/puncture/sweep.hpp) for Python: _sweep, wrapped by puncture.sweep
// (python/puncture/sweeps.py), which reads the spec dict and builds the columns' table.
#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <cmath>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "puncture/sweep.hpp"

namespace puncture::python {

namespace {

// The rows' columns, numpy arrays (a word's parameter: a list of str).
py::dict columns_of(const SweepSpec& spec, const std::vector<SweepRow>& rows) {
  py::dict out;
  out["point"] = column<std::int64_t>(
      rows, [](const SweepRow& r) { return static_cast<std::int64_t>(r.point.index); });
  for (std::size_t j = 0; j < spec.parameters.size(); ++j) {
    bool numeric = true;
    for (const SweepRow& r : rows) numeric = numeric && std::isfinite(r.point.values[j]);
    if (numeric)
      out[spec.parameters[j].name.c_str()] =
          column<double>(rows, [j](const SweepRow& r) { return r.point.values[j]; });
    else {
      py::list words;
      for (const SweepRow& r : rows) words.append(r.point.texts[j]);
      out[spec.parameters[j].name.c_str()] = words;
    }
  }
  py::list status, kind, message, location;
  for (const SweepRow& r : rows) {
    status.append(to_string(r.status));
    kind.append(to_token(r.failure_kind()));
    message.append(r.message);
    location.append(r.puncture && r.puncture->ok() ? r.puncture->crack_location : "");
  }
  out["status"] = status;
  out["failure_kind"] = kind;
  const double nan = std::nan("");
  const auto puncture_column = [&](auto get) {
    return column<double>(rows, [&](const SweepRow& r) {
      return r.puncture && r.puncture->ok() ? get(*r.puncture) : nan;
    });
  };
  if (spec.outputs.puncture) {
    out["puncture_force_n"] = puncture_column([](const SweepPuncture& p) { return p.force_n; });
    out["puncture_depth_mm"] = puncture_column([](const SweepPuncture& p) { return p.depth_mm; });
    out["part_three_stretch"] =
        puncture_column([](const SweepPuncture& p) { return p.part_three_stretch; });
    out["max_i1"] = puncture_column([](const SweepPuncture& p) { return p.max_first_invariant; });
    out["crack_location"] = location;
  }
  for (std::size_t k = 0; k < spec.outputs.force_at_depth_mm.size(); ++k) {
    const std::string name = fmt::format("force_n_at_{}_mm", spec.outputs.force_at_depth_mm[k]);
    out[name.c_str()] = column<double>(rows, [k, nan](const SweepRow& r) {
      return r.at_depth[k].ok() ? r.at_depth[k].force_n : nan;
    });
  }
  out["message"] = message;
  return out;
}

}  // namespace

void bind_sweep(py::module_& m) {
  m.def(
      "_sweep",
      [](const std::string& design,
         const std::vector<std::string>& names,
         const std::vector<std::vector<std::string>>& levels,
         const std::vector<std::tuple<std::string, double, double, double, double>>& distributions,
         std::size_t samples,
         std::uint64_t seed,
         bool puncture,
         const std::vector<double>& force_at_depth_mm,
         bool warm_start,
         int threads,
         std::size_t offset,
         std::size_t stride,
         const std::function<Problem(py::dict)>& problem_of) {
        SweepSpec spec;
        bool known = false;
        for (SweepDesign d : {SweepDesign::Grid,
                              SweepDesign::LatinHypercube,
                              SweepDesign::Sobol,
                              SweepDesign::MonteCarlo})
          if (to_token(d) == design) spec.design = d, known = true;
        if (!known)
          throw py::value_error("design: '" + design +
                                "' is not grid, latin-hypercube, sobol or monte-carlo");
        for (std::size_t j = 0; j < names.size(); ++j) {
          SweepParameter p;
          p.name = names[j];
          p.levels = levels.at(j);
          const auto& [kind, lower, upper, mean, sd] = distributions.at(j);
          for (DistributionKind k : {DistributionKind::Uniform,
                                     DistributionKind::Normal,
                                     DistributionKind::LogNormal,
                                     DistributionKind::TruncatedNormal})
            if (to_token(k) == kind) p.distribution.kind = k;
          p.distribution.lower = lower;
          p.distribution.upper = upper;
          p.distribution.mean = mean;
          p.distribution.sd = sd;
          spec.parameters.push_back(std::move(p));
        }
        spec.samples = samples;
        spec.seed = seed;
        spec.outputs.puncture = puncture;
        spec.outputs.force_at_depth_mm = force_at_depth_mm;
        spec.warm_start = warm_start;
        // The solves run without the GIL; each problem is built by the Python callable with it.
        const ProblemOfPoint of_point = [&](const SweepPoint& point) {
          py::gil_scoped_acquire gil;
          py::dict values;
          for (std::size_t j = 0; j < spec.parameters.size(); ++j) {
            const char* name = spec.parameters[j].name.c_str();
            if (std::isfinite(point.values[j]))
              values[name] = point.values[j];
            else
              values[name] = point.texts[j];
          }
          return problem_of(values);
        };
        std::vector<SweepRow> rows;
        SweepOptions options;
        options.threads = threads;
        options.offset = offset;
        options.stride = stride;
        options.on_row = [&rows](const SweepRow& row) { rows.push_back(row); };
        {
          py::gil_scoped_release release;
          try {
            sweep(spec, of_point, options);
          } catch (const InvalidInput& e) {
            // The whole text: it names the point ("invalid input at sweep point 3:").
            py::gil_scoped_acquire gil;
            throw py::value_error(e.what());
          }
        }
        return columns_of(spec, rows);
      },
      py::arg("design"),
      py::arg("names"),
      py::arg("levels"),
      py::arg("distributions"),
      py::arg("samples"),
      py::arg("seed"),
      py::arg("puncture"),
      py::arg("force_at_depth_mm"),
      py::arg("warm_start"),
      py::arg("threads"),
      py::arg("offset"),
      py::arg("stride"),
      py::arg("problem_of"),
      "The engine behind puncture.sweep (python/puncture/sweeps.py); use that.");
}

}  // namespace puncture::python
