// Reading and checking the parameters of a wall shape. Every message names the parameter by its
// full JSON path ("capillary.wall.throat_diameter_um: ...") so the user knows what to fix.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rbcsim::geometry {

// "source.key", or "key" when source is empty.
std::string parameter_path(std::string_view source, std::string_view key);

// Throws rbcsim::InputError naming source.key unless value is finite and > 0.
void require_positive_length(double value_um, std::string_view source, std::string_view key);

// Reads the keys of one JSON object of shape parameters and remembers which it read, so that a
// misspelt key is reported instead of silently ignored.
class ParameterReader {
 public:
  // Throws rbcsim::InputError unless `parameters` is a JSON object (or null: no parameters).
  ParameterReader(const nlohmann::json& parameters, std::string json_path);

  const std::string& json_path() const { return json_path_; }

  // A number; required unless a fallback is given.
  double number(std::string_view key, std::optional<double> fallback = std::nullopt);
  std::optional<double> optional_number(std::string_view key);
  // A string; required unless a fallback is given.
  std::string text(std::string_view key, std::optional<std::string> fallback = std::nullopt);
  // An array of strings, empty if the key is absent.
  std::vector<std::string> text_list(std::string_view key);

  // Throws rbcsim::InputError naming the first key that no read asked for.
  void reject_unread_keys() const;

 private:
  const nlohmann::json* find(std::string_view key);

  nlohmann::json parameters_;
  std::string json_path_;
  std::set<std::string, std::less<>> read_keys_;
};

}  // namespace rbcsim::geometry
