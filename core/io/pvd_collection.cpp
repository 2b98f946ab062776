#include "io/pvd_collection.hpp"

#include <charconv>
#include <regex>
#include <stdexcept>

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

std::vector<PvdEntry> read_pvd_collection(const std::filesystem::path& path) {
  const std::string text = read_text_file(path);
  if (text.find("<VTKFile type=\"Collection\"") == std::string::npos ||
      text.find("</VTKFile>") == std::string::npos) {
    throw InputError(path.string(), "not a complete ParaView collection (.pvd)");
  }
  // The attributes in the order write_pvd_collection writes them.
  static const std::regex data_set(R"re(<DataSet timestep="([^"]*)"[^>]* file="([^"]*)"/>)re");
  std::vector<PvdEntry> entries;
  for (auto match = std::sregex_iterator(text.begin(), text.end(), data_set);
       match != std::sregex_iterator(); ++match) {
    const std::string timestep = (*match)[1].str();
    PvdEntry entry{.file = (*match)[2].str()};
    const auto parsed =
        std::from_chars(timestep.data(), timestep.data() + timestep.size(), entry.timestep);
    if (parsed.ec != std::errc() || parsed.ptr != timestep.data() + timestep.size()) {
      throw InputError(path.string(),
                       "DataSet timestep " + in_quotes(timestep) + " is not a number");
    }
    entries.push_back(std::move(entry));
  }
  return entries;
}

}  // namespace rbcsim::io
