// Text as the report writes it: escaped for XML/XHTML and Markdown, numbers with a fixed
// number of significant digits, and JSON keys with their unit suffix turned into a readable unit.
// Everything here is deterministic: no locale, no clock.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "common/format.hpp"  // format_significant

namespace rbcsim::report {

// The parts appended into one string. Markup is built with this rather than chains of `+`:
// GCC 12 warns falsely (-Wrestrict) on "literal" + std::string temporaries.
template <typename... Parts>
std::string concat(const Parts&... parts) {
  std::string joined;
  (joined.append(std::string_view(parts)), ...);
  return joined;
}

// Text safe inside an XML element or a double-quoted attribute: & < > " ' become entities, bytes
// that are not valid UTF-8 and characters XML 1.0 forbids (control characters other than tab,
// newline and carriage return) become U+FFFD, so any run-directory string keeps the page
// well-formed.
std::string escape_xml(std::string_view text);

// Text safe inside a Markdown table cell: one line, Markdown's punctuation backslash-escaped
// (so no emphasis, link, code span, HTML tag or cell break), invalid UTF-8 replaced as above.
std::string escape_markdown(std::string_view text);

// A JSON scalar as a table cell: numbers by format_significant (integers exactly), booleans
// "yes"/"no", strings as they are, null "—", arrays of scalars joined by ", ".
std::string format_cell(const nlohmann::json& value);

// A key of the run-directory contract with its unit suffix read out: "wall_time_s" -> {"wall_time",
// "s"}, "E_s_uN_per_m" -> {"E_s", "µN/m"}, "deformation_index" -> {"deformation_index", ""}.
struct KeyLabel {
  std::string name;
  std::string unit;
};
KeyLabel describe_key(std::string_view key);

// "wall_time (s)", or the bare name of a dimensionless key.
std::string key_title(std::string_view key);

}  // namespace rbcsim::report
