#include "strict_config.hpp"

#include <fmt/format.h>

#include <sstream>
#include <string>

namespace puncture::cli {
namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

// The value after '=' as CLI11 reads it: a trailing comment removed, quotes stripped.
bool value_is_empty(std::string value) {
  if (const auto comment = value.find('#'); comment != std::string::npos) value.erase(comment);
  value = trimmed(value);
  if (value.size() >= 2 && (value.front() == '"' || value.front() == '\'') &&
      value.back() == value.front())
    value = trimmed(value.substr(1, value.size() - 2));
  return value.empty();
}

}  // namespace

bool StrictConfig::is_flag(const std::string& key) const {
  // The key may belong to the program or to any subcommand (a [section]); a flag is an option
  // that takes no value.
  const std::string name = key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1);
  auto takes_no_value = [&](const CLI::App& app) {
    const CLI::Option* option = app.get_option_no_throw("--" + name);
    return option != nullptr && option->get_type_size_max() == 0;
  };
  if (takes_no_value(*app_)) return true;
  for (const CLI::App* sub : app_->get_subcommands([](const CLI::App*) { return true; }))
    if (takes_no_value(*sub)) return true;
  return false;
}

std::vector<CLI::ConfigItem> StrictConfig::from_config(std::istream& input) const {
  std::ostringstream whole;
  whole << input.rdbuf();
  std::istringstream lines(whole.str());
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    line = trimmed(line);
    if (line.empty() || line.front() == '#' || line.front() == ';' || line.front() == '[') continue;
    const auto equals = line.find('=');
    if (equals == std::string::npos) {
      std::string key = trimmed(line.substr(0, line.find('#')));
      if (!key.empty() && !is_flag(key))
        throw CLI::ConfigError(fmt::format(
            "--config line {}: '{}' has no value (write '{} = VALUE'; only flags may stand alone)",
            number,
            key,
            key));
      continue;
    }
    const std::string key = trimmed(line.substr(0, equals));
    const std::string value = trimmed(line.substr(equals + 1));
    if (value.size() > 1 && value.front() == '[')  // an array may run over several lines
      while (line.back() != ']' && std::getline(lines, line)) {
        line = trimmed(line);
        ++number;
        if (line.empty()) line = " ";
      }
    if (value_is_empty(value))
      throw CLI::ConfigError(
          fmt::format("--config line {}: '{}' has no value (write '{} = VALUE' or remove the line)",
                      number,
                      key,
                      key));
  }
  std::istringstream again(whole.str());
  return CLI::ConfigTOML::from_config(again);
}

}  // namespace puncture::cli
