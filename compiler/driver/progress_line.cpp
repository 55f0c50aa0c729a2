#include "compiler/driver/progress_line.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>

namespace sled::driver {

bool ProgressLine::Wanted() {
  return isatty(STDERR_FILENO) != 0 && std::getenv("SLED_NO_PROGRESS") == nullptr;
}

void ProgressLine::Show(std::string_view text, bool force) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && !force && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  // Pad with spaces over a longer line drawn before.
  const std::size_t pad = width_ > text.size() ? width_ - text.size() : 0;
  std::fprintf(stderr, "\r%.*s%*s", static_cast<int>(text.size()), text.data(),
               static_cast<int>(pad), "");
  std::fflush(stderr);
  width_ = text.size();
  drawn_ = true;
}

void ProgressLine::Clear() {
  if (!enabled_ || !drawn_) return;
  std::fprintf(stderr, "\r%*s\r", static_cast<int>(width_), "");
  std::fflush(stderr);
  drawn_ = false;
  width_ = 0;
}

void ProgressLine::ShowRunFraction(double fraction, void* context) {
  auto* line = static_cast<ProgressLine*>(context);
  line->Show(fmt::format("  simulating: {:3d} %", static_cast<int>(fraction * 100 + 0.5)),
             fraction >= 1.0);
}

}  // namespace sled::driver
