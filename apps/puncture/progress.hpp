#pragma once
// Progress of a long computation on stderr, shown only when stderr is a terminal, so stdout
// and redirected output stay clean.
#include <string>
#include <string_view>

namespace puncture::cli {

class Progress {
 public:
  explicit Progress(std::string label);
  ~Progress();  // clears the progress line
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool enabled() const { return enabled_; }
  void note(std::string_view text);  // e.g. "locating the puncture point"
  void update(int done, int total);  // e.g. curve points done of total

 private:
  void show(std::string_view text);
  std::string label_;
  bool enabled_;
  bool shown_ = false;
};

}  // namespace puncture::cli
