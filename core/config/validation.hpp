// Checks config trees against the option table. Every diagnostic is one line that names the
// source (file name or "--set") and the JSON path: "run.json: membrane.k_link_kBT: expected
// number (kBT), got string \"seven\"".
#pragma once

#include <array>
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

// "Cell larger than the domain" (docs/architecture.md), checked before a run is set up: along each
// axis, the cell's extent plus clearance_spacings * spacing_um on both sides must fit in the
// domain's extent (a periodic box: its length, so that the cell's kernel support stays clear of its
// image's; between walls: the gap). The clearance is the immersed-boundary kernel's reach,
// support_width / 2 (phi2: 1, phi4: 2). Throws InputError(what, ...) naming the axis and the sizes.
void require_cell_fits_domain(const std::array<double, 3>& cell_extent_um,
                              const std::array<double, 3>& domain_extent_um, double spacing_um,
                              double clearance_spacings, std::string_view what);

}  // namespace rbcsim::config
