#include "strict_config.hpp"

#include <fmt/format.h>

#include <sstream>
#include <string>

#include "suggest.hpp"

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

void StrictConfig::check_key(const std::string& key, const std::string& section, int number) const {
  // A dotted key ("state.force") names its section itself.
  const auto dot = key.rfind('.');
  const std::string name = dot == std::string::npos ? key : key.substr(dot + 1);
  const std::string where = dot == std::string::npos ? section : key.substr(0, dot);
  const auto holder = command_holding(*app_, name);
  if (!holder) {
    const auto guess = closest_name(name, long_option_names(*app_));
    throw CLI::ConfigError(
        guess ? fmt::format(
                    "--config line {}: unknown key '{}' (did you mean '{}'?)", number, name, *guess)
              : fmt::format("--config line {}: unknown key '{}' (keys are the long flag names, "
                            "see puncture --help)",
                            number,
                            name));
  }
  // The program's own flags hold everywhere (subcommands accept them too); a subcommand's flag
  // belongs in that subcommand's section.
  if (!holder->empty() && where.empty())
    throw CLI::ConfigError(fmt::format(
        "--config line {}: '{}' is a flag of the '{}' command: write it below a line '[{}]'",
        number,
        name,
        *holder,
        *holder));
}

std::vector<CLI::ConfigItem> StrictConfig::from_config(std::istream& input) const {
  std::ostringstream whole;
  whole << input.rdbuf();
  std::istringstream lines(whole.str());
  std::string line;
  std::string section;  // the [section] the lines below belong to; "" at the top
  for (int number = 1; std::getline(lines, line); ++number) {
    line = trimmed(line);
    if (line.empty() || line.front() == '#' || line.front() == ';') continue;
    if (line.front() == '[') {
      section = trimmed(line.substr(
          1, line.find(']') == std::string::npos ? std::string::npos : line.find(']') - 1));
      continue;
    }
    const auto equals = line.find('=');
    if (equals == std::string::npos) {
      std::string key = trimmed(line.substr(0, line.find('#')));
      if (!key.empty()) check_key(key, section, number);
      if (!key.empty() && !is_flag(key))
        throw CLI::ConfigError(fmt::format(
            "--config line {}: '{}' has no value (write '{} = VALUE'; only flags may stand alone)",
            number,
            key,
            key));
      continue;
    }
    const std::string key = trimmed(line.substr(0, equals));
    check_key(key, section, number);
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
