// Checks config trees against the option table. Every diagnostic is one line that names the
// source (file name or "--set") and the JSON path: "run.json: membrane.k_link_kBT: expected
// number (kBT), got string \"seven\"".
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config/option_table.hpp"

namespace rbcsim::config {

// What is wrong with `value` for `option` (type, range, choice), or nullopt when it is valid.
std::optional<std::string> value_problem(const Option& option, const nlohmann::json& value);

// Checks every key of `tree` (a JSON object, possibly partial) against option_table(): known
// path, type, range, choice. Throws InputError(source, "<path>: <problem>") at the first problem.
void validate_tree(const nlohmann::json& tree, std::string_view source);

// The candidate most likely meant by a mistyped `word` (case-insensitive edit distance), or
// nullopt when none is close.
std::optional<std::string> closest_match(std::string_view word,
                                         const std::vector<std::string>& candidates);

// The option or group path most likely meant by an unknown `path`; besides typos it finds a
// known key put in the wrong group ("k_bend_kBT" -> "membrane.k_bend_kBT").
std::optional<std::string> closest_known_path(std::string_view path);

}  // namespace rbcsim::config
