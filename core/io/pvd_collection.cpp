#include "io/pvd_collection.hpp"

#include <charconv>
#include <stdexcept>
#include <string_view>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "io/atomic_file.hpp"
#include "io/text_file.hpp"

namespace rbcsim::io {

void write_pvd_collection(const std::filesystem::path& path, std::span<const PvdEntry> entries) {
  for (const auto& entry : entries) {
    if (entry.file.empty() || entry.file.find_first_of("<>&\"'") != std::string::npos) {
      throw std::invalid_argument("PVD entry file '" + entry.file +
                                  "' must be non-empty plain text (no XML markup characters)");
    }
  }
  write_file_atomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    for (const auto& entry : entries) {
      out << "    <DataSet timestep=\"" << format_number(entry.timestep)
          << "\" group=\"\" part=\"0\" file=\"" << entry.file << "\"/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";
  });
}

namespace {

// The value of `name="..."` in one element's text; InputError naming the file if it is missing.
std::string attribute(std::string_view element, std::string_view name,
                      const std::filesystem::path& path) {
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on " " + std::string (format.hpp).
  std::string key(1, ' ');
  key.append(name).append("=\"");
  const auto start = element.find(key);
  const auto end = start == std::string_view::npos ? start : element.find('"', start + key.size());
  if (end == std::string_view::npos) {
    throw InputError(path.string(), "a DataSet without a " + std::string(name) + " attribute");
  }
  return std::string(element.substr(start + key.size(), end - start - key.size()));
}

double number_attribute(std::string_view element, std::string_view name,
                        const std::filesystem::path& path) {
  const std::string text = attribute(element, name, path);
  double value = 0.0;
  const auto parsed = std::from_chars(text.data(), text.data() + text.size(), value);
  if (parsed.ec != std::errc() || parsed.ptr != text.data() + text.size()) {
    throw InputError(path.string(),
                     "DataSet " + std::string(name) + " " + in_quotes(text) + " is not a number");
  }
  return value;
}

}  // namespace

std::vector<PvdEntry> read_pvd_collection(const std::filesystem::path& path) {
  const std::string text = read_text_file(path);
  if (text.find("<VTKFile type=\"Collection\"") == std::string::npos ||
      text.find("</VTKFile>") == std::string::npos) {
    throw InputError(path.string(), "not a complete ParaView collection (.pvd)");
  }
  std::vector<PvdEntry> entries;
  for (auto begin = text.find("<DataSet "); begin != std::string::npos;
       begin = text.find("<DataSet ", begin + 1)) {
    const auto end = text.find("/>", begin);
    if (end == std::string::npos) throw InputError(path.string(), "an unterminated DataSet");
    const std::string_view element(text.data() + begin, end - begin);
    entries.push_back(
        {number_attribute(element, "timestep", path), attribute(element, "file", path)});
  }
  return entries;
}

}  // namespace rbcsim::io
