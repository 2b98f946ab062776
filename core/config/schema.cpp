#include "config/schema.hpp"

#include <cmath>

#include "config/option_table.hpp"

namespace rbcsim::config {
namespace {

using nlohmann::json;

json object_node() {
  return {{"type", "object"}, {"additionalProperties", false}, {"properties", json::object()}};
}

// Integer options get integer bounds, so the schema reads "minimum": 1 rather than 1.0.
json limit_value(const Option& option, double limit) {
  if (option.type == OptionType::integer) return static_cast<long long>(std::llround(limit));
  return limit;
}

json cell_list_node(const Option& option) {
  json item = object_node();
  item["required"] = json::array();
  for (const auto& field : kCellListFields) {
    json node;
    if (field.json_type == "vector") {
      node = {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 3}, {"maxItems", 3}};
    } else if (field.name == "morphology") {
      node = {{"type", "string"}, {"enum", option.choices}};
    } else {
      node = {{"type", std::string(field.json_type)}};
    }
    node["description"] = std::string(field.doc);
    item["properties"][std::string(field.name)] = node;
    if (field.required) item["required"].push_back(std::string(field.name));
  }
  return {{"type", "array"}, {"items", item}};
}

json type_node(const Option& option) {
  switch (option.type) {
    case OptionType::number:
      return {{"type", "number"}};
    case OptionType::integer:
      return {{"type", "integer"}};
    case OptionType::boolean:
      return {{"type", "boolean"}};
    case OptionType::string:
      return {{"type", "string"}};
    case OptionType::choice:
      return {{"type", "string"}, {"enum", option.choices}};
    case OptionType::choice_list:
      return {{"type", "array"},
              {"items", {{"type", "string"}, {"enum", option.choices}}},
              {"uniqueItems", true}};
    case OptionType::cell_list:
      return cell_list_node(option);
  }
  throw std::logic_error("type_node: unknown OptionType");
}

json option_node(const Option& option) {
  auto node = type_node(option);
  node["description"] =
      option.unit.empty() ? option.doc : option.doc + " Unit: " + option.unit + ".";
  node["default"] = option.default_value;
  if (const auto& low = option.minimum) {
    node[low->inclusive ? "minimum" : "exclusiveMinimum"] = limit_value(option, low->value);
  }
  if (const auto& high = option.maximum) {
    node[high->inclusive ? "maximum" : "exclusiveMaximum"] = limit_value(option, high->value);
  }
  return node;
}

}  // namespace

json config_schema() {
  auto schema = object_node();
  schema["$schema"] = "https://json-schema.org/draft/2020-12/schema";
  schema["title"] = "rbcsim configuration";
  schema["description"] =
      "Options of rbcsim (--config FILE). SI units, named in each key; defaults are the paper's "
      "Table 2 discocyte.";
  for (const auto& annotation : kAnnotationKeys) {
    schema["properties"][std::string(annotation.name)] = {{"type", annotation.json_type},
                                                          {"description", annotation.doc}};
  }
  for (const auto& option : option_table().options()) {
    const auto segments = split_path(option.path);
    json* group = &schema;
    for (std::size_t i = 0; i + 1 < segments.size(); ++i) {
      auto& child = (*group)["properties"][segments[i]];
      if (child.is_null()) child = object_node();
      group = &child;
    }
    (*group)["properties"][segments.back()] = option_node(option);
  }
  return schema;
}

std::string config_schema_text() { return config_schema().dump(2) + "\n"; }

}  // namespace rbcsim::config
