#include "compiler/driver/interrupt_signals.h"

#include <signal.h>

#include <csignal>

namespace sled::driver {
namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Lock-free, so that the handler may set them.
std::atomic<bool> stop_requested{false};
std::atomic<int> first_signal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

struct sigaction previous[3];

extern "C" void OnSignal(int number) {
  int none = 0;
  first_signal.compare_exchange_strong(none, number);
  stop_requested.store(true);
  // A second signal ends the program at once.
  for (const int s : kSignals) std::signal(s, SIG_DFL);
}

}  // namespace

InterruptSignals::InterruptSignals() {
  stop_requested.store(false);
  first_signal.store(0);
  struct sigaction action {};
  action.sa_handler = OnSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // reads and writes in progress go on
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &action, &previous[i]);
}

InterruptSignals::~InterruptSignals() {
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &previous[i], nullptr);
}

const std::atomic<bool>* InterruptSignals::stop() const { return &stop_requested; }

int InterruptSignals::signal() const { return first_signal.load(); }

std::string_view InterruptSignals::Name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

}  // namespace sled::driver
