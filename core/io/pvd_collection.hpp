// ParaView collection files (.pvd): one entry per saved dataset with its "timestep" value, so a
// sweep (force, shear rate) or a time series opens as one animated dataset.
#pragma once

#include <filesystem>
#include <span>
#include <string>

namespace rbcsim::io {

struct PvdEntry {
  double timestep = 0.0;  // the sweep parameter or the time: what ParaView's time slider shows
  std::string file;       // path relative to the .pvd file
};

// Through write_file_atomically. Throws std::invalid_argument for a file name with XML markup.
void write_pvd_collection(const std::filesystem::path& path, std::span<const PvdEntry> entries);

}  // namespace rbcsim::io
