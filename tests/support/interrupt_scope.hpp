// For tests that raise the interrupt flag (Ctrl-C) in-process.
#pragma once

#include <filesystem>
#include <string>
#include <utility>

#include "common/interrupt.hpp"
#include "coupling/coupled_simulation.hpp"

namespace rbcsim::testing {

// Clears the flag whatever the test does, so later tests in this process are not interrupted.
struct InterruptScope {
  InterruptScope() { rbcsim::clear_interrupt(); }
  ~InterruptScope() { rbcsim::clear_interrupt(); }
};

// The simulation writes `file` only when interrupted (never by step count or wall time), so a
// test knows exactly which step the checkpoint holds.
inline void checkpoint_only_when_interrupted(coupling::CoupledSimulation& simulation,
                                             const std::filesystem::path& file,
                                             std::string config_fingerprint) {
  simulation.set_checkpoint_policy({file, std::move(config_fingerprint), 0, 0.0});
}

}  // namespace rbcsim::testing
