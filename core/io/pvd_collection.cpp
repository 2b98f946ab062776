#include "io/pvd_collection.hpp"

#include <stdexcept>

#include "common/format.hpp"
#include "io/atomic_file.hpp"

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

}  // namespace rbcsim::io
