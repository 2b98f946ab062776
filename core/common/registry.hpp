// The ONE mechanism by which rbcsim chooses a variant by name (find_entry, entry_names; and the
// Registry for the kinds that code may extend at run time): force terms, hinge distributions,
// membrane and fluid kernels, collision models, wall rules, IBM kernels and integrators, wall
// shapes, cell shapes, shape methods, relaxation methods, experiment modes. A Registry holds
// entries (structs with a `name` and a one-line `description`) in registration order; config
// choices, schema enums, --help texts and error messages all read their names from it, so no list
// of names is ever written by hand.
//
// Built-in entries are given to the constructor (a function-local static, so the registry exists
// before anything looks in it); more can be added at start-up or by a test (add), e.g. a force
// term defined in one file. Lookups of an unknown name throw InputError naming the config key:
//   membrane.forces: "bendin" is not one of link, bend, area, volume, area_difference, ...
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace rbcsim {

// The names of a table of entries (anything with a `name`), in order.
template <class Entries>
std::vector<std::string> entry_names(const Entries& entries) {
  std::vector<std::string> names;
  for (const auto& entry : entries) names.emplace_back(entry.name);
  return names;
}

// "a, b, c".
template <class Entries>
std::string joined_entry_names(const Entries& entries, std::string_view separator = ", ") {
  std::string joined;
  for (const auto& entry : entries) {
    if (!joined.empty()) joined.append(separator);
    joined.append(entry.name);
  }
  return joined;
}

// The entry called `name`; InputError(key, "\"x\" is not one of a, b, c") otherwise. The one
// lookup of every named variant, compile-time tables and Registry alike.
template <class Entries>
const auto& find_entry(const Entries& entries, std::string_view name, std::string_view key) {
  for (const auto& entry : entries) {
    if (entry.name == name) return entry;
  }
  throw InputError(std::string(key),
                   in_quotes(name) + " is not one of " + joined_entry_names(entries));
}

template <class Entry>
class Registry {
 public:
  // `kind` names the variants in programming errors ("force term").
  Registry(std::string kind, std::vector<Entry> entries) : kind_(std::move(kind)) {
    for (auto& entry : entries) add(std::move(entry));
  }

  // Throws std::logic_error for an empty or duplicate name (a programming error).
  void add(Entry entry) {
    if (entry.name.empty() || find_if_known(entry.name) != nullptr) {
      throw std::logic_error("Registry<" + kind_ + ">: empty or duplicate name '" +
                             std::string(entry.name) + "'");
    }
    entries_.push_back(std::move(entry));
  }

  // Removes an entry added by add (for a test that registered one); false if not known.
  bool remove(std::string_view name) {
    for (auto it = entries_.begin(); it != entries_.end(); ++it) {
      if (it->name == name) {
        entries_.erase(it);
        return true;
      }
    }
    return false;
  }

  const Entry* find_if_known(std::string_view name) const {
    for (const auto& entry : entries_) {
      if (entry.name == name) return &entry;
    }
    return nullptr;
  }

  // Throws InputError(key, "\"x\" is not one of a, b, c").
  const Entry& find(std::string_view name, std::string_view key) const {
    return find_entry(entries_, name, key);
  }

  std::span<const Entry> entries() const { return entries_; }

  std::vector<std::string> names() const { return entry_names(entries_); }

  // "a, b, c", for help texts.
  std::string joined_names(std::string_view separator = ", ") const {
    return joined_entry_names(entries_, separator);
  }

  // "a (what a is), b (what b is)", for help texts that explain each choice.
  std::string described_names() const {
    std::string result;
    for (const auto& entry : entries_) {
      if (!result.empty()) result.append("; ");
      result.append(entry.name).append(": ").append(entry.description);
    }
    return result;
  }

 private:
  std::string kind_;
  std::vector<Entry> entries_;
};

}  // namespace rbcsim
