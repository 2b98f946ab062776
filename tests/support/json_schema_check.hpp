// A JSON Schema check for the tests: the keywords the shipped schemas use (type, enum, const,
// minimum, required, properties, additionalProperties, items, allOf, if/then), which is enough to
// hold a command's output to schemas/*.schema.json. Returns the problems found, each as
// "<JSON pointer>: <what>"; empty when the document conforms.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rbcsim::testing {

namespace schema_detail {

using nlohmann::json;

inline bool has_type(const json& value, const std::string& type) {
  if (type == "object") return value.is_object();
  if (type == "array") return value.is_array();
  if (type == "string") return value.is_string();
  if (type == "boolean") return value.is_boolean();
  if (type == "null") return value.is_null();
  if (type == "integer") return value.is_number_integer();
  if (type == "number") return value.is_number();
  return false;
}

inline void check(const json& value, const json& schema, const std::string& at,
                  std::vector<std::string>& problems);

inline void check_object(const json& value, const json& schema, const std::string& at,
                         std::vector<std::string>& problems) {
  for (const auto& name : schema.value("required", json::array())) {
    if (!value.contains(name.get<std::string>()))
      problems.push_back(at + ": missing " + name.dump());
  }
  const auto properties = schema.value("properties", json::object());
  for (const auto& [key, member] : value.items()) {
    if (properties.contains(key)) {
      check(member, properties[key], at + "/" + key, problems);
    } else if (schema.contains("additionalProperties")) {
      const auto& extra = schema["additionalProperties"];
      if (extra.is_boolean() && !extra.get<bool>()) problems.push_back(at + ": unexpected " + key);
      if (extra.is_object()) check(member, extra, at + "/" + key, problems);
    }
  }
}

inline void check(const json& value, const json& schema, const std::string& at,
                  std::vector<std::string>& problems) {
  if (schema.contains("type")) {
    const auto types = schema["type"].is_array() ? schema["type"] : json::array({schema["type"]});
    bool matched = false;
    for (const auto& type : types) matched = matched || has_type(value, type.get<std::string>());
    if (!matched) problems.push_back(at + ": not of type " + schema["type"].dump());
  }
  if (schema.contains("enum") &&
      std::find(schema["enum"].begin(), schema["enum"].end(), value) == schema["enum"].end()) {
    problems.push_back(at + ": " + value.dump() + " not in " + schema["enum"].dump());
  }
  if (schema.contains("const") && value != schema["const"]) {
    problems.push_back(at + ": " + value.dump() + " is not " + schema["const"].dump());
  }
  if (schema.contains("minimum") && value.is_number() &&
      value.get<double>() < schema["minimum"].get<double>()) {
    problems.push_back(at + ": below the minimum");
  }
  if (value.is_object()) check_object(value, schema, at, problems);
  if (value.is_array() && schema.contains("items")) {
    for (std::size_t i = 0; i < value.size(); ++i) {
      check(value[i], schema["items"], at + "/" + std::to_string(i), problems);
    }
  }
  for (const auto& part : schema.value("allOf", json::array())) check(value, part, at, problems);
  if (schema.contains("if")) {
    std::vector<std::string> condition;
    check(value, schema["if"], at, condition);
    if (condition.empty() && schema.contains("then")) check(value, schema["then"], at, problems);
  }
}

}  // namespace schema_detail

inline std::vector<std::string> schema_problems(const nlohmann::json& document,
                                                const nlohmann::json& schema) {
  std::vector<std::string> problems;
  schema_detail::check(document, schema, "", problems);
  return problems;
}

}  // namespace rbcsim::testing
