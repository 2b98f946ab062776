// Where configuration comes from: JSON text (files, the embedded share/ overlays) and --set
// assignments. Each result is validated against the option table before it is returned.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string_view>

namespace rbcsim::config {

// Parses JSON text; a syntax error throws InputError(source, "line L, column C: <what>"), with
// line and column computed from the parser's byte offset. Not validated: usable for any JSON input.
nlohmann::json parse_json(std::string_view text, std::string_view source);

// parse_json + validate_tree: a partial config tree from `source`.
nlohmann::json parse_config_text(std::string_view text, std::string_view source);

// Reads and parses a --config file; the file name is the source of every diagnostic.
nlohmann::json read_config_file(const std::filesystem::path& file);

// "key.path=value" as a partial config tree. The value is read as JSON when it parses, else taken
// as a string; a string option always takes the text as written (--set mesh.file=42 is the file
// "42"), and a list of choices also reads "link,bend". `source` names the assignment in every
// diagnostic: "--set", or the command option that stands for it ("--geometry").
nlohmann::json parse_assignment(std::string_view assignment, std::string_view source = "--set");

}  // namespace rbcsim::config
