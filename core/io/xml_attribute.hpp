// Reading back the attributes of the small XML indexes rbcsim writes itself (.pvd, .xdmf), one
// element at a time, without an XML library in the core.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace rbcsim::io {

// The value of `name="..."` in `element` (the text of one start tag); InputError naming `path`
// and the element's tag if it is missing.
std::string xml_attribute(std::string_view element, std::string_view name,
                          const std::filesystem::path& path);
// The same, read as a double; InputError if it is not one.
double xml_number_attribute(std::string_view element, std::string_view name,
                            const std::filesystem::path& path);

}  // namespace rbcsim::io
