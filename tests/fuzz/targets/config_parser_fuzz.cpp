// libFuzzer entry point: any bytes as a --config file and as a --set assignment (JSON parsing with
// line/column, validation against the option table, "did you mean"). Bad input must end in
// InputError; anything else is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "common/errors.hpp"
#include "config/config_sources.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    rbcsim::config::parse_config_text(text, "fuzz.json");
  } catch (const rbcsim::InputError&) {
  }
  try {
    rbcsim::config::parse_assignment(text);
  } catch (const rbcsim::InputError&) {
  }
  return 0;
}
