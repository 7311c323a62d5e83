// --help layout: CLI11's, with an option's exclusions moved from the option's column (where
// "Excludes: --depth" runs into the description) to a last line of its description.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace puncture::cli {

class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_option_opts(const CLI::Option* option) const override {
    std::string opts = CLI::Formatter::make_option_opts(option);
    // CLI11 writes the exclusions last.
    if (const auto at = opts.find(" " + get_label("Excludes") + ":"); at != std::string::npos)
      opts.erase(at);
    return opts;
  }

  std::string make_option_desc(const CLI::Option* option) const override {
    std::string desc = CLI::Formatter::make_option_desc(option);
    if (option->get_excludes().empty()) return desc;
    desc += "\nNot with:";
    for (const CLI::Option* other : option->get_excludes()) desc += " " + other->get_name();
    return desc;
  }
};

}  // namespace puncture::cli
