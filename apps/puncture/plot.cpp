#include "plot.hpp"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "cli_error.hpp"

#ifndef PUNCTURE_PLOT_PYTHON
#define PUNCTURE_PLOT_PYTHON "/usr/bin/python3"
#endif
#ifndef PUNCTURE_PLOT_SCRIPT
#define PUNCTURE_PLOT_SCRIPT "python/puncture/plot_cli.py"
#endif
// The installed copy of the script, relative to the directory of the installed executable.
#ifndef PUNCTURE_PLOT_SCRIPT_INSTALLED
#define PUNCTURE_PLOT_SCRIPT_INSTALLED "../lib/puncture/python/puncture/plot_cli.py"
#endif

extern char** environ;

namespace puncture::cli {

namespace {

std::string from_environment(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value && *value ? value : fallback;
}

// A temporary file holding `text`, removed when this goes out of scope.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& text) {
    std::error_code ec;
    auto dir = std::filesystem::temp_directory_path(ec);
    if (ec) dir = "/tmp";
    std::string pattern = (dir / "puncture-plot-XXXXXX.json").string();
    const int fd = mkstemps(pattern.data(), 5);
    if (fd < 0)
      throw PlotError(fmt::format(
          "cannot create a temporary file in {}: {}", dir.string(), std::strerror(errno)));
    close(fd);
    path_ = pattern;
    std::ofstream out(path_, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw PlotError(fmt::format("cannot write the temporary file {}", path_));
  }
  ~TemporaryFile() {
    std::error_code ec;
    if (!path_.empty()) std::filesystem::remove(path_, ec);
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// The installed script beside the running executable (<prefix>/bin/puncture finds
// <prefix>/<libdir>/puncture/python/puncture/plot_cli.py), else the source tree's, for the
// executable in the build tree.
std::string default_plot_script() {
  std::error_code ec;
  const auto executable = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed =
        (executable.parent_path() / PUNCTURE_PLOT_SCRIPT_INSTALLED).lexically_normal();
    if (std::filesystem::is_regular_file(installed, ec)) return installed.string();
  }
  return PUNCTURE_PLOT_SCRIPT;
}

bool is_executable(const std::string& program) {
  if (program.find('/') != std::string::npos) return access(program.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::string dirs = path;
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const auto end = std::min(dirs.find(':', start), dirs.size());
    const auto dir = dirs.substr(start, end - start);
    if (!dir.empty() && access((dir + "/" + program).c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

}  // namespace

std::string plot_python() { return from_environment("PUNCTURE_PYTHON", PUNCTURE_PLOT_PYTHON); }

std::string plot_script() {
  const char* value = std::getenv("PUNCTURE_PLOT_SCRIPT");
  return value && *value ? value : default_plot_script();
}

void check_plot_tools() {
  const auto python = plot_python();
  if (!is_executable(python))
    throw PlotError(fmt::format(
        "plots need Python 3 with matplotlib: cannot run the interpreter '{}' (install "
        "python3-matplotlib, or point PUNCTURE_PYTHON to a Python 3 that has matplotlib)",
        python));
  const auto script = plot_script();
  if (!std::filesystem::is_regular_file(script))
    throw PlotError(
        fmt::format("the plotting script '{}' is missing (it is the Python package's "
                    "puncture/plot_cli.py, installed with the program or in the source tree's "
                    "python/; set PUNCTURE_PLOT_SCRIPT to its path)",
                    script));
}

void check_plot_target(const std::string& path) {
  std::string suffix = std::filesystem::path(path).extension().string();
  std::transform(suffix.begin(), suffix.end(), suffix.begin(), [](unsigned char c) {
    return static_cast<char>(std::tolower(c));
  });
  if (suffix != ".png" && suffix != ".svg" && suffix != ".pdf")
    throw InputError(
        fmt::format("--plot: the file name must end in .png, .svg or .pdf, got '{}'", path));
  std::error_code ec;
  const bool existed = std::filesystem::exists(path, ec);
  {
    std::ofstream probe(path, std::ios::app);
    if (!probe)
      throw InputError(
          fmt::format("--plot: cannot open '{}' for writing: {}", path, std::strerror(errno)));
  }
  if (!existed) std::filesystem::remove(path, ec);
  check_plot_tools();
}

void run_plot_script(const std::string& kind, const std::string& json, const std::string& target) {
  check_plot_tools();
  const TemporaryFile data(json);
  const auto python = plot_python();
  const auto script = plot_script();
  // -B: no __pycache__ written next to the script (the source tree or the installed package).
  std::vector<std::string> args{python, "-B", script, kind, data.path(), target};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ);
  if (spawned != 0)
    throw PlotError(
        fmt::format("cannot run the interpreter '{}': {} (set PUNCTURE_PYTHON to a "
                    "Python 3 that has matplotlib)",
                    python,
                    std::strerror(spawned)));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw PlotError(fmt::format("waiting for '{}' failed", python));
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 3)
    throw PlotError(fmt::format(
        "'{}' lacks numpy or matplotlib; no figure written (install python3-matplotlib, or "
        "point PUNCTURE_PYTHON to a Python 3 that has them)",
        python));
  if (WIFEXITED(status))
    throw PlotError(fmt::format("the plotting script failed (exit status {}); no figure written",
                                WEXITSTATUS(status)));
  throw PlotError(fmt::format("the plotting script was stopped by signal {}; no figure written",
                              WTERMSIG(status)));
}

}  // namespace puncture::cli
