// A strict XML parse (expat) of what rbcsim writes (the report, VTK files), for tests:
// well-formedness, and the elements with their attributes and text, to find plots, series and
// labels by structure, not by regex.
#pragma once

#include <expat.h>

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace rbcsim::testing {

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;  // character data directly inside the element
  long parent = -1;  // index in XmlDocument::elements, -1 for the root
  std::string attribute(const std::string& key) const {
    const auto found = attributes.find(key);
    return found == attributes.end() ? "" : found->second;
  }
  bool has_class(std::string_view name_of_class) const {
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string chains.
    std::string classes(" ");
    classes.append(attribute("class")).append(" ");
    std::string wanted(" ");
    wanted.append(name_of_class).append(" ");
    return classes.find(wanted) != std::string::npos;
  }
};

struct XmlDocument {
  std::string error;  // empty when well-formed
  std::vector<XmlElement> elements;

  bool is_descendant(std::size_t element, std::size_t ancestor) const {
    for (long at = elements[element].parent; at >= 0; at = elements[at].parent) {
      if (static_cast<std::size_t>(at) == ancestor) return true;
    }
    return false;
  }
  // Indices of the elements named `name` (any name if empty) with class `class_name` (any if
  // empty) inside element `ancestor` (anywhere if -1).
  std::vector<std::size_t> find(std::string_view name, std::string_view class_name = "",
                                long ancestor = -1) const {
    std::vector<std::size_t> found;
    for (std::size_t i = 0; i < elements.size(); ++i) {
      const auto& element = elements[i];
      if (!name.empty() && element.name != name) continue;
      if (!class_name.empty() && !element.has_class(class_name)) continue;
      if (ancestor >= 0 && !is_descendant(i, static_cast<std::size_t>(ancestor))) continue;
      found.push_back(i);
    }
    return found;
  }
  // The data-label attributes of the `class_name` elements inside `ancestor`.
  std::vector<std::string> labels(std::string_view class_name, long ancestor) const {
    std::vector<std::string> result;
    for (const auto i : find("", class_name, ancestor)) {
      result.push_back(elements[i].attribute("data-label"));
    }
    return result;
  }
};

namespace detail {
struct XmlBuilder {
  XmlDocument document;
  std::vector<long> open;
};
inline void start_element(void* data, const char* name, const char** attributes) {
  auto& builder = *static_cast<XmlBuilder*>(data);
  XmlElement element{name, {}, "", builder.open.empty() ? -1 : builder.open.back()};
  for (int i = 0; attributes[i] != nullptr; i += 2)
    element.attributes[attributes[i]] = attributes[i + 1];
  builder.open.push_back(static_cast<long>(builder.document.elements.size()));
  builder.document.elements.push_back(std::move(element));
}
inline void end_element(void* data, const char*) {
  static_cast<XmlBuilder*>(data)->open.pop_back();
}
inline void character_data(void* data, const char* text, int length) {
  auto& builder = *static_cast<XmlBuilder*>(data);
  if (!builder.open.empty()) {
    builder.document.elements[builder.open.back()].text.append(text,
                                                               static_cast<std::size_t>(length));
  }
}
}  // namespace detail

inline XmlDocument parse_xml(std::string_view text) {
  detail::XmlBuilder builder;
  XML_Parser parser = XML_ParserCreate("UTF-8");
  XML_SetUserData(parser, &builder);
  XML_SetElementHandler(parser, detail::start_element, detail::end_element);
  XML_SetCharacterDataHandler(parser, detail::character_data);
  if (XML_Parse(parser, text.data(), static_cast<int>(text.size()), 1) == XML_STATUS_ERROR) {
    builder.document.error = std::string(XML_ErrorString(XML_GetErrorCode(parser))) + " at line " +
                             std::to_string(XML_GetCurrentLineNumber(parser)) + ", column " +
                             std::to_string(XML_GetCurrentColumnNumber(parser));
  }
  XML_ParserFree(parser);
  return builder.document;
}

}  // namespace rbcsim::testing
