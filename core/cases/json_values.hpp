// Small conversions shared by the cases' result.json sections.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>

namespace rbcsim::cases {

// The number, or JSON null when there is none (a quantity that was not measured).
inline nlohmann::ordered_json optional_number(const std::optional<double>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

}  // namespace rbcsim::cases
