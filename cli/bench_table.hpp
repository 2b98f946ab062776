// The text table `rbcsim bench` prints: a label column and one column per thread count.
#pragma once

#include <array>
#include <cstdio>
#include <string>
#include <vector>

namespace rbcsim::cli {

inline std::string fixed(double value, int decimals) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%.*f", decimals, value);
  return text.data();
}

// One row: a label, one cell per thread count, and an optional note after them.
inline void print_row(const std::string& label, const std::vector<std::string>& cells,
                      const std::string& note = "") {
  std::printf("%-44s", label.c_str());
  for (const auto& cell : cells) std::printf("%14s", cell.c_str());
  if (!note.empty()) std::printf("   %s", note.c_str());
  std::printf("\n");
}

}  // namespace rbcsim::cli
