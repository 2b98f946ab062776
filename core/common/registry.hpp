// The ONE mechanism by which rbcsim chooses a variant by name: force terms, hinge distributions,
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
    if (const auto* entry = find_if_known(name)) return *entry;
    throw InputError(std::string(key), in_quotes(name) + " is not one of " + joined_names());
  }

  std::span<const Entry> entries() const { return entries_; }

  std::vector<std::string> names() const {
    std::vector<std::string> result;
    for (const auto& entry : entries_) result.emplace_back(entry.name);
    return result;
  }

  // "a, b, c", for help texts.
  std::string joined_names(std::string_view separator = ", ") const {
    std::string result;
    for (const auto& entry : entries_) {
      if (!result.empty()) result.append(separator);
      result.append(entry.name);
    }
    return result;
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
