#include "config/option_table.hpp"

#include <algorithm>
#include <stdexcept>

#include "config/options/option_areas.hpp"
#include "config/validation.hpp"

namespace rbcsim::config {
namespace {

bool is_proper_prefix(std::string_view group, std::string_view path) {
  return path.size() > group.size() && path.starts_with(group) && path[group.size()] == '.';
}

OptionTable build_option_table() {
  OptionTable table;
  for (const auto add_area : kOptionAreas) add_area(table);
  for (const auto& option : table.options()) {
    if (const auto problem = value_problem(option, option.default_value)) {
      throw std::logic_error("option table: default of " + option.path + ": " + *problem);
    }
  }
  return table;
}

}  // namespace

Option& Option::above(double value) {
  minimum = Limit{value, false};
  return *this;
}

Option& Option::at_least(double value) {
  minimum = Limit{value, true};
  return *this;
}

Option& Option::below(double value) {
  maximum = Limit{value, false};
  return *this;
}

Option& Option::at_most(double value) {
  maximum = Limit{value, true};
  return *this;
}

Option& OptionTable::add(Option option) {
  for (const auto& existing : options_) {
    if (existing.path == option.path || is_proper_prefix(existing.path, option.path) ||
        is_proper_prefix(option.path, existing.path)) {
      throw std::logic_error("option table: " + option.path + " collides with " + existing.path);
    }
  }
  options_.push_back(std::move(option));
  return options_.back();
}

Option& OptionTable::add_number(std::string path, std::string unit, double default_value,
                                std::string doc) {
  return add({std::move(path),
              OptionType::number,
              std::move(unit),
              default_value,
              {},
              {},
              {},
              std::move(doc)});
}

Option& OptionTable::add_integer(std::string path, std::string unit, int default_value,
                                 std::string doc) {
  return add({std::move(path),
              OptionType::integer,
              std::move(unit),
              default_value,
              {},
              {},
              {},
              std::move(doc)});
}

Option& OptionTable::add_boolean(std::string path, bool default_value, std::string doc) {
  return add({std::move(path), OptionType::boolean, "", default_value, {}, {}, {}, std::move(doc)});
}

Option& OptionTable::add_string(std::string path, std::string default_value, std::string doc) {
  return add({std::move(path),
              OptionType::string,
              "",
              std::move(default_value),
              {},
              {},
              {},
              std::move(doc)});
}

Option& OptionTable::add_choice(std::string path, std::vector<std::string> choices,
                                std::string default_value, std::string doc) {
  return add({std::move(path),
              OptionType::choice,
              "",
              std::move(default_value),
              {},
              {},
              std::move(choices),
              std::move(doc)});
}

Option& OptionTable::add_choice_list(std::string path, std::vector<std::string> choices,
                                     std::vector<std::string> default_value, std::string doc) {
  return add({std::move(path),
              OptionType::choice_list,
              "",
              std::move(default_value),
              {},
              {},
              std::move(choices),
              std::move(doc)});
}

Option& OptionTable::add_cell_list(std::string path, std::vector<std::string> morphologies,
                                   std::string doc) {
  return add({std::move(path),
              OptionType::cell_list,
              "",
              nlohmann::json::array(),
              {},
              {},
              std::move(morphologies),
              std::move(doc)});
}

const Option* OptionTable::find(std::string_view path) const {
  const auto row = std::find_if(options_.begin(), options_.end(),
                                [path](const Option& option) { return option.path == path; });
  return row == options_.end() ? nullptr : &*row;
}

bool OptionTable::is_group(std::string_view path) const {
  return std::any_of(options_.begin(), options_.end(),
                     [path](const Option& option) { return is_proper_prefix(path, option.path); });
}

std::vector<std::string> OptionTable::known_paths() const {
  std::vector<std::string> paths;
  for (const auto& option : options_) {
    paths.push_back(option.path);
    for (auto dot = option.path.find('.'); dot != std::string::npos;
         dot = option.path.find('.', dot + 1)) {
      paths.push_back(option.path.substr(0, dot));
    }
  }
  std::sort(paths.begin(), paths.end());
  paths.erase(std::unique(paths.begin(), paths.end()), paths.end());
  return paths;
}

nlohmann::json OptionTable::defaults() const {
  nlohmann::json tree = nlohmann::json::object();
  for (const auto& option : options_) tree[json_pointer(option.path)] = option.default_value;
  return tree;
}

const OptionTable& option_table() {
  static const OptionTable table = build_option_table();
  return table;
}

const AnnotationKey* find_annotation_key(std::string_view name) {
  const auto key =
      std::find_if(kAnnotationKeys.begin(), kAnnotationKeys.end(),
                   [name](const AnnotationKey& annotation) { return annotation.name == name; });
  return key == kAnnotationKeys.end() ? nullptr : &*key;
}

std::vector<std::string> split_path(std::string_view path) {
  std::vector<std::string> segments;
  std::size_t start = 0;
  for (auto dot = path.find('.'); dot != std::string_view::npos; dot = path.find('.', start)) {
    segments.emplace_back(path.substr(start, dot - start));
    start = dot + 1;
  }
  segments.emplace_back(path.substr(start));
  return segments;
}

nlohmann::json::json_pointer json_pointer(std::string_view path) {
  nlohmann::json::json_pointer pointer;
  for (const auto& segment : split_path(path)) pointer /= segment;
  return pointer;
}

}  // namespace rbcsim::config
