#include "run_support.hpp"

#include <fmt/format.h>

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace puncture::cli {

namespace {

std::atomic<bool> interrupted{false};

extern "C" void on_interrupt(int) { interrupted.store(true); }

std::string duration(double s) {
  if (!(s < 1e9)) return "?";
  const long t = static_cast<long>(s + 0.5);
  if (t >= 3600) return fmt::format("{}h{:02}m", t / 3600, t / 60 % 60);
  if (t >= 60) return fmt::format("{}m{:02}s", t / 60, t % 60);
  return fmt::format("{}s", t);
}

}  // namespace

const std::atomic<bool>& interrupt_flag() { return interrupted; }

StopOnSignals::StopOnSignals() {
  interrupted.store(false);
  previous_int_ = std::signal(SIGINT, on_interrupt);
  previous_term_ = std::signal(SIGTERM, on_interrupt);
}

StopOnSignals::~StopOnSignals() {
  std::signal(SIGINT, previous_int_);
  std::signal(SIGTERM, previous_term_);
}

void end_by_interrupt() {
  std::signal(SIGINT, SIG_DFL);
  std::raise(SIGINT);
  std::_Exit(130);  // SIGINT blocked: the shell's code for it
}

std::function<void(const SweepProgress&)> progress_line(bool terminal, std::size_t resumed,
                                                        std::size_t total) {
  return [terminal, resumed, total](const SweepProgress& p) {
    const double rate = p.elapsed_s > 0.0 ? static_cast<double>(p.done) / p.elapsed_s : 0.0;
    const double eta = rate > 0.0 ? static_cast<double>(p.to_do - p.done) / rate : 1e300;
    const double percent =
        total > 0 ? 100.0 * static_cast<double>(resumed + p.done) / static_cast<double>(total)
                  : 100.0;
    fmt::print(stderr,
               "{}sweep: {}/{} points ({:.0f}%), {:.3g} points/s, {} failed, ETA {}{}",
               terminal ? "\r\033[K" : "",
               resumed + p.done,
               total,
               percent,
               rate,
               p.failed,
               duration(eta),
               terminal ? "" : "\n");
    std::fflush(stderr);
  };
}

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace puncture::cli
