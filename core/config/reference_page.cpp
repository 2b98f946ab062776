#include "config/reference_page.hpp"

#include <sstream>

#include "common/format.hpp"
#include "config/option_table.hpp"

namespace rbcsim::config {
namespace {

std::string type_name(const Option& option) {
  switch (option.type) {
    case OptionType::number:
      return "number";
    case OptionType::integer:
      return "integer";
    case OptionType::boolean:
      return "boolean";
    case OptionType::string:
      return "string";
    case OptionType::choice:
      return "choice";
    case OptionType::choice_list:
      return "list of choices";
    case OptionType::cell_list:
      return "list of cells";
  }
  return "";
}

std::string range_text(const Option& option) {
  std::string text;
  if (option.minimum) {
    text += (option.minimum->inclusive ? ">= " : "> ") + format_number(option.minimum->value);
  }
  if (option.maximum) {
    if (!text.empty()) text += ", ";
    text += (option.maximum->inclusive ? "<= " : "< ") + format_number(option.maximum->value);
  }
  if (!option.choices.empty()) {
    for (std::size_t k = 0; k < option.choices.size(); ++k) {
      text += (k == 0 ? "" : ", ") + ("`" + option.choices[k] + "`");
    }
  }
  return text;
}

// A table cell: pipes escaped, so a doc with "|" does not split the row.
std::string cell(std::string text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '|') escaped += "\\";
    escaped += c;
  }
  return escaped;
}

}  // namespace

std::string configuration_reference_markdown() {
  std::ostringstream out;
  out << "# Configuration reference\n\n"
         "Generated from the option table (`core/config/options/`) by `rbcsim config reference`; "
         "a test fails when this page and the table differ. Every key can be given in a "
         "`--config` file (nested JSON objects) or as `--set key.path=value`; the JSON Schema "
         "`schemas/config.schema.json` says the same for editors. Keys carry their unit.\n";
  std::string area;
  for (const auto& option : option_table().options()) {
    const auto first = option.path.substr(0, option.path.find('.'));
    if (first != area) {
      area = first;
      out << "\n## `" << area << "`\n\n| key | type | unit | default | allowed | what |\n"
          << "|---|---|---|---|---|---|\n";
    }
    out << "| `" << option.path << "` | " << type_name(option) << " | " << option.unit << " | `"
        << cell(option.default_value.dump()) << "` | " << cell(range_text(option)) << " | "
        << cell(option.doc) << " |\n";
  }
  return out.str();
}

}  // namespace rbcsim::config
