#include "io/pvd_collection.hpp"

#include <stdexcept>
#include <string_view>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "io/atomic_file.hpp"
#include "io/text_file.hpp"
#include "io/xml_attribute.hpp"

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
        {xml_number_attribute(element, "timestep", path), xml_attribute(element, "file", path)});
  }
  return entries;
}

}  // namespace rbcsim::io
