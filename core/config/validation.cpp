#include "config/validation.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace rbcsim::config {
namespace {

using nlohmann::json;

std::string lowercase(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> previous(b.size() + 1);
  std::vector<std::size_t> current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::string last_segment(std::string_view path) {
  const auto dot = path.rfind('.');
  return std::string(dot == std::string_view::npos ? path : path.substr(dot + 1));
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const auto& word : words) text += (text.empty() ? "" : ", ") + word;
  return text;
}

// "string \"seven\"", "number 4.5", "array": the type of a JSON value, and the value when short.
std::string describe(const json& value) {
  std::string text = value.type_name();
  if (value.is_primitive() && !value.is_null()) {
    const auto shown = value.dump(-1, ' ', false, json::error_handler_t::replace);
    if (shown.size() <= 40) text += " " + shown;
  }
  return text;
}

std::string expected_type(const Option& option) {
  switch (option.type) {
    case OptionType::number:
      return option.unit.empty() ? "number" : "number (" + option.unit + ")";
    case OptionType::integer:
      return "integer";
    case OptionType::boolean:
      return "boolean";
    case OptionType::string:
      return "string";
    case OptionType::choice:
      return "one of " + joined(option.choices);
    case OptionType::choice_list:
      return "array of strings, each one of " + joined(option.choices);
    case OptionType::cell_list:
      return "array of cells ({\"morphology\": one of " + joined(option.choices) +
             ", \"centre_um\": [x, y, z], optional \"axis\": [x, y, z] and \"spin_deg\"})";
  }
  throw std::logic_error("expected_type: unknown OptionType");
}

std::string mistyped(const Option& option, const json& value) {
  return "expected " + expected_type(option) + ", got " + describe(value);
}

std::optional<std::string> range_problem(const Option& option, double value) {
  if (!std::isfinite(value)) return "must be finite, got " + format_number(value);
  if (const auto& low = option.minimum;
      low && (low->inclusive ? value < low->value : value <= low->value)) {
    return "must be " + std::string(low->inclusive ? ">= " : "> ") + format_number(low->value) +
           ", got " + format_number(value);
  }
  if (const auto& high = option.maximum;
      high && (high->inclusive ? value > high->value : value >= high->value)) {
    return "must be " + std::string(high->inclusive ? "<= " : "< ") + format_number(high->value) +
           ", got " + format_number(value);
  }
  return std::nullopt;
}

std::optional<std::string> integer_problem(const Option& option, const json& value) {
  if (!value.is_number_integer()) return mistyped(option, value);
  const bool fits = value.is_number_unsigned()
                        ? value.get<std::uint64_t>() <= std::numeric_limits<int>::max()
                        : value.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
                              value.get<std::int64_t>() <= std::numeric_limits<int>::max();
  if (!fits) return "integer " + value.dump() + " is out of range";
  return range_problem(option, value.get<double>());
}

std::optional<std::string> choice_problem(const Option& option, const std::string& choice) {
  if (std::find(option.choices.begin(), option.choices.end(), choice) != option.choices.end()) {
    return std::nullopt;
  }
  std::string problem = in_quotes(choice) + " is not one of " + joined(option.choices);
  if (const auto meant = closest_match(choice, option.choices)) {
    problem += "; did you mean `" + *meant + "`?";
  }
  return problem;
}

// One field of a cell_list element, or nullopt when it is fine.
std::optional<std::string> cell_field_problem(const Option& option, const CellListField& field,
                                              const json& value) {
  if (field.json_type == "vector") {
    const bool three = value.is_array() && value.size() == 3 &&
                       std::all_of(value.begin(), value.end(), [](const json& component) {
                         return component.is_number() && std::isfinite(component.get<double>());
                       });
    if (!three) {
      return "expected 3 finite numbers, got " +
             (value.is_array() ? "an array of " + std::to_string(value.size()) : describe(value));
    }
    if (field.name == "axis" && value[0].get<double>() == 0.0 && value[1].get<double>() == 0.0 &&
        value[2].get<double>() == 0.0) {
      return std::string("the zero vector has no direction");
    }
    return std::nullopt;
  }
  if (field.json_type == "number") {
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
      return "expected a finite number, got " + describe(value);
    }
    return std::nullopt;
  }
  if (!value.is_string()) return "expected string, got " + describe(value);
  if (field.name == "mesh_file") {
    if (value.get_ref<const std::string&>().empty()) return std::string("an empty path");
    return std::nullopt;
  }
  return choice_problem(option, value.get<std::string>());
}

std::string cell_list_keys() {
  std::string keys;
  for (const auto& field : kCellListFields) {
    keys.append(keys.empty() ? "" : ", ").append(field.name);
  }
  return keys;
}

std::optional<std::string> cell_list_problem(const Option& option, const json& value) {
  if (!value.is_array()) return mistyped(option, value);
  for (std::size_t i = 0; i < value.size(); ++i) {
    std::string where = "[";  // appended: GCC 12 warns falsely (-Wrestrict) on "[" + std::string
    where.append(std::to_string(i)).append("]");
    const auto& cell = value[i];
    if (!cell.is_object()) return where + ": expected an object, got " + describe(cell);
    for (const auto& item : cell.items()) {
      const std::string& key = item.key();
      const json& field_value = item.value();
      const auto field = std::find_if(kCellListFields.begin(), kCellListFields.end(),
                                      [&key](const CellListField& f) { return f.name == key; });
      if (field == kCellListFields.end()) {
        return where + "." + key + ": unknown key (a cell has " + cell_list_keys() + ")";
      }
      if (const auto problem = cell_field_problem(option, *field, field_value)) {
        return where + "." + key + ": " + *problem;
      }
    }
    for (const auto& field : kCellListFields) {
      if (field.required && !cell.contains(std::string(field.name))) {
        return where + ": missing " + std::string(field.name);
      }
    }
  }
  return std::nullopt;
}

std::optional<std::string> choice_list_problem(const Option& option, const json& value) {
  if (!value.is_array()) return mistyped(option, value);
  for (std::size_t i = 0; i < value.size(); ++i) {
    std::string where = "[";  // appended: GCC 12 warns falsely (-Wrestrict) on "[" + std::string
    where.append(std::to_string(i)).append("]: ");
    if (!value[i].is_string()) return where + "expected string, got " + describe(value[i]);
    const auto& choice = value[i].get_ref<const std::string&>();
    if (const auto problem = choice_problem(option, choice)) return where + *problem;
    if (std::count(value.begin(), value.end(), value[i]) > 1) {
      return "lists " + in_quotes(choice) + " more than once";
    }
  }
  return std::nullopt;
}

void validate_annotation(const AnnotationKey& key, const json& value, std::string_view source) {
  if (value.type_name() != key.json_type) {
    throw InputError(std::string(source), std::string(key.name) + ": expected " +
                                              std::string(key.json_type) + ", got " +
                                              describe(value));
  }
}

[[noreturn]] void throw_unknown_key(const std::string& path, std::string_view source) {
  std::string problem = path + ": unknown key";
  if (const auto meant = closest_known_path(path)) {
    problem += "; did you mean `" + *meant + "`?";
  } else {
    problem += " (`rbcsim config schema` lists every key)";
  }
  throw InputError(std::string(source), problem);
}

void validate_node(const json& node, const std::string& group, std::string_view source) {
  const auto& table = option_table();
  for (const auto& [key, value] : node.items()) {
    const std::string path = group.empty() ? key : group + "." + key;
    if (key.empty()) throw InputError(std::string(source), path + ": empty key");
    if (key.find('.') != std::string::npos) {
      throw InputError(std::string(source),
                       path + ": keys are single names; nest objects instead of dots");
    }
    if (const auto* annotation = group.empty() ? find_annotation_key(key) : nullptr) {
      validate_annotation(*annotation, value, source);
    } else if (const auto* option = table.find(path)) {
      if (const auto problem = value_problem(*option, value)) {
        throw InputError(std::string(source), path + ": " + *problem);
      }
    } else if (table.is_group(path)) {
      if (!value.is_object()) {
        throw InputError(
            std::string(source),
            path + ": expected an object (a group of options), got " + describe(value));
      }
      validate_node(value, path, source);
    } else {
      throw_unknown_key(path, source);
    }
  }
}

// A size in a diagnostic to 4 significant digits: cell extents are computed from the vertices
// ("7.82", not "7.819999999983796").
std::string format_size_um(double size_um) { return format_significant(size_um) + " um"; }

}  // namespace

std::optional<std::string> value_problem(const Option& option, const json& value) {
  switch (option.type) {
    case OptionType::number:
      if (!value.is_number()) return mistyped(option, value);
      return range_problem(option, value.get<double>());
    case OptionType::integer:
      return integer_problem(option, value);
    case OptionType::boolean:
      if (!value.is_boolean()) return mistyped(option, value);
      return std::nullopt;
    case OptionType::string:
      if (!value.is_string()) return mistyped(option, value);
      return std::nullopt;
    case OptionType::choice:
      if (!value.is_string()) return mistyped(option, value);
      return choice_problem(option, value.get<std::string>());
    case OptionType::choice_list:
      return choice_list_problem(option, value);
    case OptionType::cell_list:
      return cell_list_problem(option, value);
  }
  throw std::logic_error("value_problem: unknown OptionType");
}

void validate_tree(const json& tree, std::string_view source) {
  if (!tree.is_object()) {
    throw InputError(std::string(source), "expected a JSON object at the top level, got " +
                                              std::string(tree.type_name()));
  }
  validate_node(tree, "", source);
}

std::optional<std::string> closest_match(std::string_view word,
                                         const std::vector<std::string>& candidates) {
  const auto lower_word = lowercase(word);
  std::optional<std::string> best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (const auto& candidate : candidates) {
    // A typo or a forgotten suffix changes a few characters: allow about one edit in three of
    // the longer word, and at least two.
    const std::size_t tolerance =
        std::max<std::size_t>(2, std::max(word.size(), candidate.size()) / 3);
    const auto distance = edit_distance(lower_word, lowercase(candidate));
    if (distance <= tolerance && distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

std::optional<std::string> closest_known_path(std::string_view path) {
  const auto known = option_table().known_paths();
  const auto name = lowercase(last_segment(path));
  for (const auto& candidate : known) {
    if (lowercase(last_segment(candidate)) == name) return candidate;
  }
  return closest_match(path, known);
}

void require_cell_fits_domain(const std::array<double, 3>& cell_extent_um,
                              const std::array<double, 3>& domain_extent_um, double spacing_um,
                              double clearance_spacings, std::string_view what) {
  const double clearance_um = 2.0 * clearance_spacings * spacing_um;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    if (cell_extent_um[axis] + clearance_um <= domain_extent_um[axis]) continue;
    throw InputError(std::string(what), std::string("the cell does not fit the domain along ") +
                                            "xyz"[axis] + ": " +
                                            format_size_um(cell_extent_um[axis]) +
                                            " of cell plus " + format_size_um(clearance_um) +
                                            " of clearance (" + format_number(clearance_spacings) +
                                            " lattice spacings per side) exceed the domain's " +
                                            format_size_um(domain_extent_um[axis]));
  }
}

}  // namespace rbcsim::config
