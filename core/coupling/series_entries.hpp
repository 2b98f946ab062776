// What a resumed run keeps of a snapshot series (.pvd, snapshot.cpp; .xdmf, hdf5_snapshot.cpp).
#pragma once

#include <filesystem>
#include <utility>
#include <vector>

namespace rbcsim::coupling {

// The entries of the series file at `path` (read by `read`) up to the restored time `time_s`;
// none if there is no file yet. Those after it were written after the checkpoint and are written
// again, to the same file names.
template <class Entry>
std::vector<Entry> entries_up_to(const std::filesystem::path& path, double time_s,
                                 std::vector<Entry> (*read)(const std::filesystem::path&),
                                 double Entry::*time) {
  std::vector<Entry> kept;
  if (!std::filesystem::exists(path)) return kept;
  for (auto& entry : read(path)) {
    if (entry.*time <= time_s) kept.push_back(std::move(entry));
  }
  return kept;
}

}  // namespace rbcsim::coupling
