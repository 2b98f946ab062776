// Subcommands register themselves here from their own file; main() attaches them all to the
// application. Order of registration does not matter: help lists them in the order of `rank`.
// Each cli/cmd_<name>.cpp keeps its helpers in a namespace of its own, rbcsim::cli::<name>_command,
// so that the commands' same-named helpers stay apart in the unity build.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace rbcsim::cli {

struct CommandEntry {
  std::string name;
  int rank;  // position in --help (mesh=10, calibrate=20, stretch=30, shear=40, ...)
  std::function<void(CLI::App& application)> attach;
  // Whether the command runs on several processes (`mpirun -np N rbcsim <name>`); main() refuses
  // the others there with exit 2 before they start.
  bool runs_on_processes = false;
};

// Called from a static initialiser in each cli/cmd_*.cpp; returns true so it can initialise a bool.
bool register_command(CommandEntry entry);

std::vector<CommandEntry> registered_commands();

}  // namespace rbcsim::cli
