#include "command_registry.hpp"

#include <algorithm>

namespace rbcsim::cli {
namespace {

// Function-local static: safe to use from other translation units' static initialisers.
std::vector<CommandEntry>& registry() {
  static std::vector<CommandEntry> entries;
  return entries;
}

}  // namespace

bool register_command(CommandEntry entry) {
  registry().push_back(std::move(entry));
  return true;
}

std::vector<CommandEntry> registered_commands() {
  auto entries = registry();
  std::sort(entries.begin(), entries.end(),
            [](const CommandEntry& a, const CommandEntry& b) { return a.rank < b.rank; });
  return entries;
}

}  // namespace rbcsim::cli
