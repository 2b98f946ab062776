// A JSON Schema check for the tests: the keywords the shipped schemas use (type, enum, const,
// minimum, required, properties, additionalProperties, items, allOf, if/then, not, and $ref to a
// definition in the same document, "#/$defs/<name>"), which is enough to
// hold a command's output to schemas/*.schema.json. Returns the problems found, each as
// "<JSON pointer>: <what>"; empty when the document conforms.
#pragma once

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>
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

// The document being checked against and its root schema, which "$ref"s point into.
struct Checker {
  const json& root;
  std::vector<std::string>& problems;
};

inline void check(const json& value, const json& schema, const std::string& at, Checker& checker);

inline void check_object(const json& value, const json& schema, const std::string& at,
                         Checker& checker) {
  auto& problems = checker.problems;
  for (const auto& name : schema.value("required", json::array())) {
    if (!value.contains(name.get<std::string>()))
      problems.push_back(at + ": missing " + name.dump());
  }
  const auto properties = schema.value("properties", json::object());
  for (const auto& [key, member] : value.items()) {
    if (properties.contains(key)) {
      check(member, properties[key], at + "/" + key, checker);
    } else if (schema.contains("additionalProperties")) {
      const auto& extra = schema["additionalProperties"];
      if (extra.is_boolean() && !extra.get<bool>()) problems.push_back(at + ": unexpected " + key);
      if (extra.is_object()) check(member, extra, at + "/" + key, checker);
    }
  }
}

inline void check(const json& value, const json& schema, const std::string& at, Checker& checker) {
  auto& problems = checker.problems;
  if (schema.contains("$ref")) {
    const auto ref = schema["$ref"].get<std::string>();
    // Only references into the same document; anything else would be a typo in the schema.
    if (ref.rfind("#/", 0) != 0) throw std::invalid_argument("unsupported $ref " + ref);
    check(value, checker.root.at(json::json_pointer(ref.substr(1))), at, checker);
  }
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
  if (value.is_object()) check_object(value, schema, at, checker);
  if (value.is_array() && schema.contains("items")) {
    for (std::size_t i = 0; i < value.size(); ++i) {
      check(value[i], schema["items"], at + "/" + std::to_string(i), checker);
    }
  }
  for (const auto& part : schema.value("allOf", json::array())) check(value, part, at, checker);
  if (schema.contains("not")) {
    std::vector<std::string> negated;
    Checker negated_checker{checker.root, negated};
    check(value, schema["not"], at, negated_checker);
    if (negated.empty()) problems.push_back(at + ": matches a schema it must not (\"not\")");
  }
  if (schema.contains("if")) {
    std::vector<std::string> condition;
    Checker condition_checker{checker.root, condition};
    check(value, schema["if"], at, condition_checker);
    if (condition.empty() && schema.contains("then")) check(value, schema["then"], at, checker);
  }
}

}  // namespace schema_detail

inline std::vector<std::string> schema_problems(const nlohmann::json& document,
                                                const nlohmann::json& schema) {
  std::vector<std::string> problems;
  schema_detail::Checker checker{schema, problems};
  schema_detail::check(document, schema, "", checker);
  return problems;
}

}  // namespace rbcsim::testing
