#include "geometry/shape_parameters.hpp"

#include <cmath>

#include "common/errors.hpp"

namespace rbcsim::geometry {

std::string parameter_path(std::string_view source, std::string_view key) {
  if (source.empty()) return std::string(key);
  return std::string(source) + "." + std::string(key);
}

void require_positive_length(double value_um, std::string_view source, std::string_view key) {
  if (!std::isfinite(value_um) || value_um <= 0.0) {
    throw InputError(parameter_path(source, key),
                     "must be a positive length in um, got " + std::to_string(value_um));
  }
}

ParameterReader::ParameterReader(const nlohmann::json& parameters, std::string json_path)
    : parameters_(parameters.is_null() ? nlohmann::json::object() : parameters),
      json_path_(std::move(json_path)) {
  if (!parameters_.is_object()) {
    throw InputError(json_path_, std::string("expected an object of shape parameters, got ") +
                                     parameters_.type_name());
  }
}

const nlohmann::json* ParameterReader::find(std::string_view key) {
  read_keys_.emplace(key);
  const auto it = parameters_.find(key);
  return it == parameters_.end() ? nullptr : &*it;
}

std::optional<double> ParameterReader::optional_number(std::string_view key) {
  const auto* value = find(key);
  if (value == nullptr) return std::nullopt;
  if (!value->is_number()) {
    throw InputError(parameter_path(json_path_, key),
                     std::string("expected a number, got ") + value->type_name());
  }
  return value->get<double>();
}

double ParameterReader::number(std::string_view key, std::optional<double> fallback) {
  const auto value = optional_number(key);
  if (value) return *value;
  if (fallback) return *fallback;
  throw InputError(parameter_path(json_path_, key), "missing (a number is required)");
}

std::string ParameterReader::text(std::string_view key, std::optional<std::string> fallback) {
  const auto* value = find(key);
  if (value == nullptr) {
    if (fallback) return *fallback;
    throw InputError(parameter_path(json_path_, key), "missing (a string is required)");
  }
  if (!value->is_string()) {
    throw InputError(parameter_path(json_path_, key),
                     std::string("expected a string, got ") + value->type_name());
  }
  return value->get<std::string>();
}

std::vector<std::string> ParameterReader::text_list(std::string_view key) {
  const auto* value = find(key);
  if (value == nullptr) return {};
  const auto path = parameter_path(json_path_, key);
  if (!value->is_array()) {
    throw InputError(path, std::string("expected an array of strings, got ") + value->type_name());
  }
  std::vector<std::string> texts;
  for (const auto& item : *value) {
    if (!item.is_string()) {
      throw InputError(path,
                       std::string("expected an array of strings, found a ") + item.type_name());
    }
    texts.push_back(item.get<std::string>());
  }
  return texts;
}

void ParameterReader::reject_unread_keys() const {
  for (const auto& [key, value] : parameters_.items()) {
    if (!read_keys_.contains(key)) {
      throw InputError(parameter_path(json_path_, key), "unknown parameter of this wall shape");
    }
  }
}

}  // namespace rbcsim::geometry
