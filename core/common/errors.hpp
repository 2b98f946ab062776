// Error kinds that map onto the process exit codes (README.md, "Exit codes"):
//   InputError     -> exit 2 (bad usage, config, mesh: the user can fix the input)
//   RuntimeFailure -> exit 1 (instability, NaN: the simulation itself failed)
//   Interrupted    -> exit 130 (SIGINT/SIGTERM, common/interrupt.hpp; 128 + 2 as shells report
//                     Ctrl-C, whichever signal it was)
// Messages are one line and name the file (or JSON path) and the problem.
#pragma once

#include <stdexcept>
#include <string>

namespace rbcsim {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
  // "FILE: problem" — the form every input diagnostic takes.
  InputError(const std::string& source, const std::string& problem);
};

class RuntimeFailure : public std::runtime_error {
 public:
  explicit RuntimeFailure(const std::string& message) : std::runtime_error(message) {}
};

// A time loop saw the interrupt flag; the results so far are written before exiting.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(const std::string& message) : std::runtime_error(message) {}
};

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitRuntimeFailure = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitInterrupted = 130;

}  // namespace rbcsim
