// Runs the built rbcsim binary (RBCSIM_BINARY) for CLI integration tests and captures what a
// user would see: exit code, stdout and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/files.hpp"

namespace rbcsim::testing {

struct RunResult {
  int exit_code;
  std::string out;  // stdout
  std::string err;  // stderr
};

// `arguments` is appended to the binary's path as written, shell quoting included. Output goes
// through files in `scratch` (a directory the test owns).
inline RunResult run_rbcsim(const std::string& arguments, const std::filesystem::path& scratch) {
  const auto out = scratch / "stdout.txt";
  const auto err = scratch / "stderr.txt";
  const std::string command = std::string("'") + RBCSIM_BINARY + "' " + arguments + " >'" +
                              out.string() + "' 2>'" + err.string() + "' </dev/null";
  const int status = std::system(command.c_str());
  const int exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return {exit_code, read_text(out), read_text(err)};
}

// Starts the binary as run_rbcsim does, its output discarded, and sends it `signal` (INT as
// Ctrl-C would, TERM, KILL) once `file` exists: a stage of the run reached whatever the machine's
// load (a sanitizer build, tests in parallel), where a fixed delay can fall before the run has
// begun. Waits a minute at most. The exit code, -1 if it did not exit by itself (killed).
inline int run_rbcsim_signalled_once(const std::filesystem::path& file,
                                     const std::string& arguments,
                                     const std::string& signal = "INT") {
  const std::string command =
      std::string("'") + RBCSIM_BINARY + "' " + arguments +
      " >/dev/null 2>&1 </dev/null & pid=$!; for i in $(seq 600); do [ -e '" + file.string() +
      "' ] && break; sleep 0.1; done; kill -" + signal + " $pid; wait $pid";
  const int status = std::system(command.c_str());
  // A child killed by a signal is reported by the shell as exit code 128 + the signal's number.
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace rbcsim::testing
