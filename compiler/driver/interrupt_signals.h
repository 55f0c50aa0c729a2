// SIGINT, SIGTERM and SIGHUP during a run: the first one asks the run to stop after the output
// row it is at, so that the rows so far, the criteria (incomplete) and summary.json (status
// "interrupted") are written; a second one ends the program at once, as it would without sled's
// handler. The exit status is then 128 plus the signal's number (130, 143, 129), as shells
// report a program a signal stopped.
#pragma once

#include <atomic>
#include <string_view>

namespace sled::driver {

class InterruptSignals {
 public:
  InterruptSignals();   // installs the handlers
  ~InterruptSignals();  // restores what was there before
  InterruptSignals(const InterruptSignals&) = delete;
  InterruptSignals& operator=(const InterruptSignals&) = delete;

  // Set by the first signal: runtime::RunOptions::stop.
  const std::atomic<bool>* stop() const;
  // The signal that arrived first, 0 while none has.
  int signal() const;
  // `SIGINT`, `SIGTERM`, `SIGHUP`.
  static std::string_view Name(int signal);
};

}  // namespace sled::driver
