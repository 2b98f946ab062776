// Ctrl-C and `kill` (docs/architecture.md: Ctrl-C writes what has been computed). The signal
// handlers only set a process-wide flag (async-signal-safe); every time loop calls
// throw_if_interrupted() once per step or iteration, so the run unwinds at a clean point between
// steps, and the command writes its results so far (status "interrupted") and a checkpoint, then
// exits with kExitInterrupted. A second signal while the first is being handled ends the process at
// once.
#pragma once

namespace rbcsim {

// SIGINT and SIGTERM set the flag (cli/main.cpp installs them before running a command).
void install_interrupt_handlers();

// What the handlers do; also for tests, which interrupt without a signal.
void request_interrupt(int signal_number) noexcept;
bool interrupt_requested() noexcept;
// Forgets a request (tests run several interrupted loops in one process).
void clear_interrupt() noexcept;

// Throws Interrupted ("interrupted by SIGINT") if a signal arrived.
void throw_if_interrupted();

}  // namespace rbcsim
