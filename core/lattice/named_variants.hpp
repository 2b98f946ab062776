// Look-up in the tables of physics variants chosen by name (collision models, kernels, wall
// rules): each table is a constexpr array of entries with a `name`.
#pragma once

#include "common/errors.hpp"

#include <span>
#include <string>
#include <string_view>

namespace rbcsim::lattice {

// The entry called `name`. Throws rbcsim::InputError naming `option`, e.g. `lattice.kernel`:
// unknown <kind> "<name>"; known <kind>s: <every name, in table order>.
template <class Entry>
const Entry& find_variant(std::span<const Entry> table, std::string_view name,
                          std::string_view option, std::string_view kind) {
  std::string known;
  for (const Entry& entry : table) {
    if (entry.name == name) {
      return entry;
    }
    known += (known.empty() ? "" : ", ") + std::string(entry.name);
  }
  throw InputError(std::string(option), "unknown " + std::string(kind) + " \"" + std::string(name) +
                                            "\"; known " + std::string(kind) + "s: " + known);
}

}  // namespace rbcsim::lattice
