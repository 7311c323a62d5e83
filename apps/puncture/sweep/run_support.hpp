#pragma once
// What a running sweep needs from the program: a stop on Ctrl-C, the progress line, the spec's
// text (its copy beside FILE.part).
#include <atomic>
#include <cstddef>
#include <functional>
#include <string>

#include "puncture/sweep.hpp"

namespace puncture::cli {

// Set by SIGINT or SIGTERM while a StopOnSignals lives.
const std::atomic<bool>& interrupt_flag();

// SIGINT and SIGTERM stop the sweep after the points being solved: their rows are written, the
// file stays resumable.  The previous handlers come back when the sweep ends.
class StopOnSignals {
 public:
  StopOnSignals();
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

 private:
  void (*previous_int_)(int);
  void (*previous_term_)(int);
};

// Ends the program by SIGINT (the default action), as the interrupted sweep's exit status.
[[noreturn]] void end_by_interrupt();

// Rate, failures and ETA on stderr: a line rewritten in place on a terminal, else one line per
// report for logs.  `resumed`: points written before this run; `total`: the sweep's points.
std::function<void(const SweepProgress&)> progress_line(bool terminal, std::size_t resumed,
                                                        std::size_t total);

std::string file_text(const std::string& path);

}  // namespace puncture::cli
