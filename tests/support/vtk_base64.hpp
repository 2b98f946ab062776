// Reading back VTK's inline binary data arrays in tests, independently of the writer: a plain
// base64 decoder (RFC 4648) and the split into VTK's UInt64 byte-count header and the values.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace rbcsim::testing {

inline std::vector<std::uint8_t> decode_base64(std::string_view text) {
  const auto value_of = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;  // padding or white space
  };
  std::vector<std::uint8_t> bytes;
  unsigned buffer = 0;
  int bits = 0;
  for (const char c : text) {
    const int value = value_of(c);
    if (value < 0) continue;
    buffer = (buffer << 6) | static_cast<unsigned>(value);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes.push_back(static_cast<std::uint8_t>((buffer >> bits) & 0xFF));
    }
  }
  return bytes;
}

// The values of a VTK inline binary array with a UInt64 header; fails the test when the header's
// byte count does not match the data.
template <typename T>
std::vector<T> decode_vtk_binary(std::string_view text) {
  const auto bytes = decode_base64(text);
  std::uint64_t byte_count = 0;
  EXPECT_GE(bytes.size(), sizeof(byte_count));
  if (bytes.size() < sizeof(byte_count)) return {};
  std::memcpy(&byte_count, bytes.data(), sizeof(byte_count));
  EXPECT_EQ(byte_count, bytes.size() - sizeof(byte_count));
  std::vector<T> values((bytes.size() - sizeof(byte_count)) / sizeof(T));
  std::memcpy(values.data(), bytes.data() + sizeof(byte_count), values.size() * sizeof(T));
  return values;
}

}  // namespace rbcsim::testing
