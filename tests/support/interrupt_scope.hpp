// For tests that raise the interrupt flag (Ctrl-C) in-process.
#pragma once

#include "common/interrupt.hpp"

namespace rbcsim::testing {

// Clears the flag whatever the test does, so later tests in this process are not interrupted.
struct InterruptScope {
  InterruptScope() { rbcsim::clear_interrupt(); }
  ~InterruptScope() { rbcsim::clear_interrupt(); }
};

}  // namespace rbcsim::testing
