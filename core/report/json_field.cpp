#include "report/json_field.hpp"

#include "common/errors.hpp"
#include "common/format.hpp"
#include "config/config_sources.hpp"
#include "io/text_file.hpp"

namespace rbcsim::report {
namespace {

std::string json_type_phrase(const nlohmann::json& value) {
  if (value.is_number_integer()) return "an integer";
  if (value.is_number()) return "a number with a fraction or an exponent";
  if (value.is_array()) return "an array";
  if (value.is_object()) return "an object";
  if (value.is_null()) return "null";
  return std::string("a ") + value.type_name();
}

// RFC 6901: '~' and '/' inside a key are escaped in a JSON pointer.
std::string pointer_token(std::string_view key) {
  std::string token;
  for (const char c : key) {
    if (c == '~') {
      token += "~0";
    } else if (c == '/') {
      token += "~1";
    } else {
      token += c;
    }
  }
  return token;
}

}  // namespace

JsonField::JsonField(const nlohmann::json& document, std::string file)
    : JsonField(document, std::move(file), "") {}

JsonField::JsonField(const nlohmann::json& value, std::string file, std::string pointer)
    : value_(&value), file_(std::move(file)), pointer_(std::move(pointer)) {}

void JsonField::fail(const std::string& problem) const {
  if (pointer_.empty()) throw InputError(file_, problem);
  throw InputError(file_, pointer_ + ": " + problem);
}

void JsonField::fail_type(std::string_view expected) const {
  fail("expected " + std::string(expected) + ", found " + json_type_phrase(*value_));
}

std::optional<JsonField> JsonField::find(std::string_view key) const {
  const auto& members = object();
  const auto member = members.find(key);
  if (member == members.end()) return std::nullopt;
  return JsonField(*member, file_, pointer_ + "/" + pointer_token(key));
}

JsonField JsonField::at(std::string_view key) const {
  auto member = find(key);
  if (!member) fail("missing member " + in_quotes(key));
  return *member;
}

JsonField JsonField::at(std::size_t index) const {
  if (index >= array_size()) fail("has no element " + std::to_string(index));
  return JsonField((*value_)[index], file_, pointer_ + "/" + std::to_string(index));
}

double JsonField::number() const {
  if (!value_->is_number()) fail_type("a number");
  return value_->get<double>();
}

int JsonField::integer() const {
  if (!value_->is_number_integer()) fail_type("an integer");
  return value_->get<int>();
}

bool JsonField::boolean() const {
  if (!value_->is_boolean()) fail_type("true or false");
  return value_->get<bool>();
}

std::string JsonField::string() const {
  if (!value_->is_string()) fail_type("a string");
  return value_->get<std::string>();
}

std::size_t JsonField::array_size() const {
  if (!value_->is_array()) fail_type("an array");
  return value_->size();
}

const nlohmann::json& JsonField::object() const {
  if (!value_->is_object()) fail_type("an object");
  return *value_;
}

nlohmann::json read_json_file(const std::filesystem::path& file) {
  return config::parse_json(io::read_text_file(file), file.string());
}

}  // namespace rbcsim::report
