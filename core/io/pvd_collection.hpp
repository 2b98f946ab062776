// ParaView collection files (.pvd): one entry per saved data set with its "timestep" value, so a
// time series (or a sweep over force or shear rate) opens as one animated data set.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace rbcsim::io {

struct PvdEntry {
  double timestep = 0.0;  // the time or the sweep parameter: what ParaView's time slider shows
  std::string file;       // path relative to the .pvd file
};

// Through write_file_atomically. Throws std::invalid_argument for an empty file name or one with
// XML markup characters.
void write_pvd_collection(const std::filesystem::path& path, std::span<const PvdEntry> entries);

// The entries of a collection written by write_pvd_collection, in file order, so a resumed run can
// continue it. Throws InputError naming the file if it is not such a collection.
std::vector<PvdEntry> read_pvd_collection(const std::filesystem::path& path);

}  // namespace rbcsim::io
