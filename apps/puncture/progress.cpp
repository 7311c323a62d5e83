#include "progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace puncture::cli {

Progress::Progress(std::string label)
    : label_(std::move(label)), enabled_(isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
  if (shown_) {
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
  }
}

void Progress::note(std::string_view text) {
  if (enabled_) show(text);
}

void Progress::update(int done, int total) {
  if (!enabled_ || total <= 0) return;
  show(fmt::format("{}/{} points ({}%)", done, total, 100 * done / total));
}

void Progress::show(std::string_view text) {
  fmt::print(stderr, "\r\033[K{}: {}", label_, text);
  std::fflush(stderr);
  shown_ = true;
}

}  // namespace puncture::cli
