#include "io/xml_attribute.hpp"

#include <charconv>

#include "common/errors.hpp"
#include "common/format.hpp"

namespace rbcsim::io {
namespace {

// "DataSet" of "<DataSet timestep=...".
std::string tag_of(std::string_view element) {
  if (!element.empty() && element.front() == '<') element.remove_prefix(1);
  return std::string(element.substr(0, element.find_first_of(" />")));
}

}  // namespace

std::string xml_attribute(std::string_view element, std::string_view name,
                          const std::filesystem::path& path) {
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on " " + std::string (format.hpp).
  std::string key(1, ' ');
  key.append(name).append("=\"");
  const auto start = element.find(key);
  const auto end = start == std::string_view::npos ? start : element.find('"', start + key.size());
  if (end == std::string_view::npos) {
    throw InputError(path.string(),
                     "a " + tag_of(element) + " without a " + std::string(name) + " attribute");
  }
  return std::string(element.substr(start + key.size(), end - start - key.size()));
}

double xml_number_attribute(std::string_view element, std::string_view name,
                            const std::filesystem::path& path) {
  const std::string text = xml_attribute(element, name, path);
  double value = 0.0;
  const auto parsed = std::from_chars(text.data(), text.data() + text.size(), value);
  if (parsed.ec != std::errc() || parsed.ptr != text.data() + text.size()) {
    throw InputError(path.string(), tag_of(element) + " " + std::string(name) + " " +
                                        in_quotes(text) + " is not a number");
  }
  return value;
}

}  // namespace rbcsim::io
