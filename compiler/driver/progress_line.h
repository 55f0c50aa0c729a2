// A one-line progress display on standard error, for long commands: drawn only when standard
// error is a terminal (quiet when piped or redirected, and with SLED_NO_PROGRESS set), redrawn
// at most ten times a second, and erased before anything else is printed.
#pragma once

#include <chrono>
#include <string>
#include <string_view>

namespace sled::driver {

class ProgressLine {
 public:
  // Enabled when standard error is a terminal and SLED_NO_PROGRESS is not set.
  static bool Wanted();

  explicit ProgressLine(bool enabled) : enabled_(enabled) {}
  ~ProgressLine() { Clear(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool enabled() const { return enabled_; }
  // `  simulating:  42 % (t = 0.084 s of 0.2 s)`; skipped when the last one was drawn less
  // than 0.1 s ago, unless `force`.
  void Show(std::string_view text, bool force = false);
  // Erases the line (before other output, and at the end).
  void Clear();

  // For runtime::RunOptions::progress: `context` is the ProgressLine; the label is
  // "simulating".
  static void ShowRunFraction(double fraction, void* context);

 private:
  bool enabled_ = false;
  bool drawn_ = false;
  std::size_t width_ = 0;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace sled::driver
