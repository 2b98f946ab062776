// The JSON Schema (draft 2020-12) of rbcsim config files, generated from the option table:
// nested objects, types, units and docs in "description", defaults, ranges, enums, and
// additionalProperties false everywhere. Shipped as schemas/config.schema.json (refresh with
// `rbcsim config schema > schemas/config.schema.json`; a test fails while the two differ).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace rbcsim::config {

nlohmann::json config_schema();

// The text of schemas/config.schema.json: config_schema() indented by 2, with a final newline.
std::string config_schema_text();

}  // namespace rbcsim::config
