#include "suggest.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace puncture::cli {
namespace {

// Optimal-string-alignment distance: a transposition ("firction") counts as one edit, the most
// common slip in a typed flag.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::vector<const CLI::App*> all_commands(const CLI::App& app) {
  std::vector<const CLI::App*> out{&app};
  for (std::size_t k = 0; k < out.size(); ++k)
    for (const CLI::App* sub : out[k]->get_subcommands([](const CLI::App*) { return true; }))
      out.push_back(sub);
  return out;
}

}  // namespace

std::vector<std::string> long_option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* command : all_commands(app))
    for (const CLI::Option* option : command->get_options())
      for (const std::string& name : option->get_lnames()) names.push_back(name);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

std::optional<std::string> closest_name(const std::string& word,
                                        const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  std::size_t best_distance = std::max<std::size_t>(1, word.size() / 3) + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t d = edit_distance(word, candidate);
    if (d < best_distance) best_distance = d, best = candidate;
  }
  return best;
}

std::optional<std::string> command_holding(const CLI::App& app, const std::string& name) {
  for (const CLI::App* command : all_commands(app))
    if (command->get_option_no_throw("--" + name) != nullptr)
      return command == &app ? std::string{} : command->get_name();
  return std::nullopt;
}

std::string unknown_flags_report(const CLI::App& app, int argc, const char* const* argv) {
  const auto names = long_option_names(app);
  std::string report;
  for (int k = 1; k < argc; ++k) {
    std::string arg = argv[k];
    if (arg.size() < 3 || arg.rfind("--", 0) != 0) continue;
    std::string name =
        arg.substr(2, arg.find('=') == std::string::npos ? std::string::npos : arg.find('=') - 2);
    if (std::binary_search(names.begin(), names.end(), name)) continue;
    const auto guess = closest_name(name, names);
    report += guess ? fmt::format("\n  --{}: unknown flag (did you mean --{}?)", name, *guess)
                    : fmt::format("\n  --{}: unknown flag", name);
  }
  return report;
}

}  // namespace puncture::cli
