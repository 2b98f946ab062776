// The variants of the cases module are chosen by name from one table each (relaxation methods,
// contact-patch rules, stretch modes). Entries are structs with a `name` member; these two helpers
// list the names and look one up with the diagnostic every table gives.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace rbcsim::cases {

template <class Entry>
std::vector<std::string> names_of(std::span<const Entry> table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.emplace_back(entry.name);
  return names;
}

// Throws InputError(option_path, "unknown <what> "x" (known: a, b)").
template <class Entry>
const Entry& find_named(std::span<const Entry> table, std::string_view name,
                        std::string_view option_path, std::string_view what) {
  std::string known;
  for (const auto& entry : table) {
    if (entry.name == name) return entry;
    known.append(known.empty() ? "" : ", ").append(entry.name);
  }
  throw InputError(std::string(option_path), "unknown " + std::string(what) + " " +
                                                 in_quotes(name) + " (known: " + known + ")");
}

}  // namespace rbcsim::cases
