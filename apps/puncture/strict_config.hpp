// A --config reader that refuses what CLI11's TOML/INI reader would silently drop.
#pragma once

#include <CLI/CLI.hpp>
#include <istream>
#include <vector>

namespace puncture::cli {

// CLI11's reader, preceded by a check of every line: a key with an empty value ('friction =',
// 'friction = ""') or an option written without '= value' (which CLI11 reads as a flag set to
// true) is a CLI::ConfigError naming the key and the line, so the CLI exits 1 instead of running
// with the default.  An unknown key is refused with a "did you mean".  Flags (options taking no
// value) may be written alone.
class StrictConfig : public CLI::ConfigTOML {
 public:
  explicit StrictConfig(const CLI::App& app) : app_(&app) {}
  std::vector<CLI::ConfigItem> from_config(std::istream& input) const override;

 private:
  bool is_flag(const std::string& key) const;
  // A key no command knows is a CLI::ConfigError with the closest flag name; so is a
  // subcommand's flag outside that subcommand's [section].
  void check_key(const std::string& key, const std::string& section, int number) const;
  const CLI::App* app_;
};

}  // namespace puncture::cli
