// docs/configuration.md, generated from the option table like the schema: every option by area,
// with its type, unit, default, allowed range or choices and its one-line doc. Shipped as
// docs/configuration.md (refresh with `rbcsim config reference > docs/configuration.md`; a test
// fails while the two differ).
#pragma once

#include <string>

namespace rbcsim::config {

std::string configuration_reference_markdown();

}  // namespace rbcsim::config
