// Typed reads of a JSON document that name the file and the JSON pointer of whatever is missing
// or of the wrong type: "runs/a/result.json: /stretch/points/2/force_pN: expected a number, found
// a string". A run directory written by another command is input, so every read is checked.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace rbcsim::report {

class JsonField {
 public:
  // `document` must outlive every field read from it.
  JsonField(const nlohmann::json& document, std::string file);

  JsonField at(std::string_view key) const;  // a member of an object; throws if missing
  JsonField at(std::size_t index) const;     // an element of an array
  std::optional<JsonField> find(std::string_view key) const;  // nullopt if missing

  double number() const;
  int integer() const;
  bool boolean() const;
  std::string string() const;
  std::size_t array_size() const;        // throws if not an array
  const nlohmann::json& object() const;  // throws if not an object

  const nlohmann::json& json() const { return *value_; }
  const std::string& file() const { return file_; }
  const std::string& pointer() const { return pointer_; }

  // InputError "FILE: POINTER: problem" (or "FILE: problem" at the document's root).
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  JsonField(const nlohmann::json& value, std::string file, std::string pointer);
  [[noreturn]] void fail_type(std::string_view expected) const;

  const nlohmann::json* value_;
  std::string file_;
  std::string pointer_;
};

// A JSON file parsed (syntax errors name the file, line and column).
nlohmann::json read_json_file(const std::filesystem::path& file);

}  // namespace rbcsim::report
