#include "design_map.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "plot.hpp"

namespace puncture::cli {

std::optional<std::string> design_map_target(const CLI::App& app) {
  const CLI::Option* plot = app.get_option_no_throw("--plot");
  if (plot == nullptr || plot->count() == 0) return std::nullopt;
  const std::string target = plot->as<std::string>();
  check_plot_target(target);
  return target;
}

void draw_design_map(const std::string& csv_path, const SweepSpec& spec,
                     const std::string& target) {
  nlohmann::json data;
  data["csv"] = csv_path;
  data["parameters"] = nlohmann::json::array();
  for (const SweepParameter& p : spec.parameters) data["parameters"].push_back(p.name);
  data["output"] = spec.outputs.puncture
                       ? std::string("puncture_force_n")
                       : fmt::format("force_n_at_{}_mm", spec.outputs.force_at_depth_mm.front());
  run_plot_script("sweep", data.dump(), target);
}

}  // namespace puncture::cli
