// Look-up in a table of named variants (kernels, integrators): the entry called `name`, or an
// InputError naming the config key, the unknown name and the known ones.
#pragma once

#include <algorithm>
#include <string>
#include <string_view>

#include "common/errors.hpp"

namespace rbcsim::ibm {

template <typename Entry, typename Table>
const Entry& find_by_name(const Table& table, std::string_view name, std::string_view config_key) {
  const auto found = std::ranges::find(table, name, &Entry::name);
  if (found != std::ranges::end(table)) return *found;
  std::string known;
  for (const Entry& entry : table) known += (known.empty() ? "" : ", ") + std::string(entry.name);
  throw InputError(std::string(config_key),
                   "unknown name '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace rbcsim::ibm
