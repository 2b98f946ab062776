// Values in diagnostics and reports.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
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

// `value` with `significant_digits` significant digits in the shortest of fixed or scientific
// notation ("29.85", "0.001234", "1.234e-19"), for computed values whose last bits are noise
// ("24.8", not "24.799999999999997"); "nan", "inf", "-inf" for non-finite values.
inline std::string format_significant(double value, int significant_digits = 4) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                    std::chars_format::general, significant_digits);
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
