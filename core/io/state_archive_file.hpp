// The file of a checkpoint (common/state_archive.hpp's named arrays of doubles), whoever writes it:
// a coupled simulation (coupling/checkpoint.hpp) or the fluid across processes
// (parallel/distributed_fluid.hpp).
//
// Layout (little-endian, as in memory on the machines rbcsim runs on):
//   "RBCSIMCK"                       8 bytes, the magic
//   uint32 version
//   uint32 n, n bytes                 the config fingerprint of the run that wrote it
//   uint32 array count, then per array (in name order):
//     uint32 n, n bytes name;  uint64 count;  count float64 values
//   64 bytes                          SHA-256 of everything above, hex digits
// Written atomically (atomic_file.hpp): a kill during the write leaves the previous file intact.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>

#include "common/state_archive.hpp"

namespace rbcsim::io {

void write_state_archive(const std::filesystem::path& file, const StateArchive& archive,
                         std::uint32_t version, std::string_view config_fingerprint);

// Throws InputError (one line naming the file) for a file that is missing, not a checkpoint, of
// another version, truncated or corrupted (checksum), or written under another config.
StateArchive read_state_archive(const std::filesystem::path& file, std::uint32_t version,
                                std::string_view config_fingerprint);

}  // namespace rbcsim::io
