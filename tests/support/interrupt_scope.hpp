// For tests that raise the interrupt flag (Ctrl-C) in-process.
#pragma once

#include <csignal>
#include <cstddef>
#include <filesystem>
#include <functional>
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

// A run's configure hook that checkpoints to `file` only when interrupted and raises the interrupt
// after step `step`; and the hook that resumes the same run from that checkpoint.
inline std::function<void(coupling::CoupledSimulation&)> interrupt_after_step(
    std::size_t step, const std::filesystem::path& file, const std::string& config_fingerprint) {
  return [step, file, config_fingerprint](coupling::CoupledSimulation& simulation) {
    checkpoint_only_when_interrupted(simulation, file, config_fingerprint);
    simulation.add_observer({"interrupt", 1, [step](const coupling::CoupledSimulation& s) {
                               if (s.time_step() == step) rbcsim::request_interrupt(SIGINT);
                             }});
  };
}

inline std::function<void(coupling::CoupledSimulation&)> resume_from_checkpoint(
    const std::filesystem::path& file, const std::string& config_fingerprint) {
  return [file, config_fingerprint](coupling::CoupledSimulation& simulation) {
    checkpoint_only_when_interrupted(simulation, file, config_fingerprint);
    simulation.resume_from(file);
  };
}

}  // namespace rbcsim::testing
