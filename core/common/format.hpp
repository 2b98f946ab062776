// Values in diagnostics and reports.
#pragma once

#include <array>
#include <charconv>
#include <string>
#include <string_view>

namespace rbcsim {

// The shortest text that reads back as the same double ("0.5005", "1.1e-06", "50"), so a
// diagnostic shows exactly the value the user gave.
inline std::string format_number(double value) {
  std::array<char, 32> buffer{};  // the longest shortest form of a double is 24 characters
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

// Text in double quotes, as a diagnostic quotes what the user wrote. Built by appending: GCC 12
// warns falsely (-Wrestrict) on "\"" + std::string.
inline std::string in_quotes(std::string_view text) {
  std::string result;
  result.reserve(text.size() + 2);
  result.append(1, '"').append(text).append(1, '"');
  return result;
}

}  // namespace rbcsim
