#include "common/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <string>

#include "common/errors.hpp"

namespace rbcsim {
namespace {

// The signal number, 0 while none arrived. Lock-free, so safe to touch from a signal handler.
std::atomic<int> requested_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

void on_signal(int signal_number) {
  if (requested_signal.exchange(signal_number) != 0) _exit(kExitInterrupted);  // second Ctrl-C
}

std::string signal_name(int signal_number) {
  switch (signal_number) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "signal " + std::to_string(signal_number);
  }
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void request_interrupt(int signal_number) noexcept { requested_signal.store(signal_number); }

bool interrupt_requested() noexcept { return requested_signal.load() != 0; }

void clear_interrupt() noexcept { requested_signal.store(0); }

void throw_if_interrupted() {
  const int signal_number = requested_signal.load();
  if (signal_number != 0) throw Interrupted("interrupted by " + signal_name(signal_number));
}

}  // namespace rbcsim
