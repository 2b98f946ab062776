#include "config/config_sources.hpp"

#include <algorithm>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "config/option_table.hpp"
#include "config/validation.hpp"
#include "io/text_file.hpp"

namespace rbcsim::config {
namespace {

using nlohmann::json;

// nlohmann reports the 1-based offset of the last byte it read; count lines up to it.
std::string position_of(std::string_view text, std::size_t byte) {
  const auto before = text.substr(0, std::min(text.size(), byte > 0 ? byte - 1 : 0));
  const auto line = 1 + std::count(before.begin(), before.end(), '\n');
  const auto last_newline = before.rfind('\n');
  const auto column = last_newline == std::string_view::npos ? byte : byte - (last_newline + 1);
  return "line " + std::to_string(line) + ", column " +
         std::to_string(std::max<std::size_t>(column, 1));
}

// The parser's own words, without nlohmann's "[json.exception.parse_error.101] parse error at
// line 1, column 2: " prefix.
std::string parser_complaint(const nlohmann::json::exception& error) {
  std::string_view message = error.what();
  message.remove_prefix(std::min(message.size(), message.find("] ") + 2));
  if (message.starts_with("parse error")) message.remove_prefix(message.find(": ") + 2);
  return std::string(message);
}

std::vector<std::string> comma_separated(std::string_view text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  for (auto comma = text.find(','); comma != std::string_view::npos;
       comma = text.find(',', start)) {
    items.emplace_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  items.emplace_back(text.substr(start));
  return items;
}

json assignment_value(const Option* option, std::string_view text) {
  const bool takes_text = option && option->type == OptionType::string;
  const bool takes_list = option && option->type == OptionType::choice_list;
  if (json::accept(text)) {
    auto value = json::parse(text);
    if (value.is_string() || !takes_text) return value;
  } else if (takes_list) {
    return comma_separated(text);
  }
  return std::string(text);
}

}  // namespace

json parse_json(std::string_view text, std::string_view source) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& error) {
    throw InputError(std::string(source),
                     position_of(text, error.byte) + ": " + parser_complaint(error));
  } catch (const json::out_of_range& error) {  // a number beyond double: 1e999
    throw InputError(std::string(source), parser_complaint(error));
  }
}

json parse_config_text(std::string_view text, std::string_view source) {
  auto tree = parse_json(text, source);
  validate_tree(tree, source);
  return tree;
}

json read_config_file(const std::filesystem::path& file) {
  return parse_config_text(io::read_text_file(file), file.string());
}

json parse_assignment(std::string_view assignment, std::string_view source) {
  const auto equals = assignment.find('=');
  if (equals == std::string_view::npos || equals == 0) {
    throw InputError(std::string(source), "expected key.path=value, got " + in_quotes(assignment));
  }
  const std::string path(assignment.substr(0, equals));
  const auto segments = split_path(path);
  if (find_annotation_key(segments.front())) {
    throw InputError(std::string(source), path + ": written by rbcsim, cannot be set");
  }
  json tree = json::object();
  json* node = &tree;
  for (const auto& segment : segments) {
    if (segment.empty()) {
      throw InputError(std::string(source), path + ": empty key in the path");
    }
    node = &(*node)[segment];
  }
  *node = assignment_value(option_table().find(path), assignment.substr(equals + 1));
  validate_tree(tree, source);
  return tree;
}

}  // namespace rbcsim::config
