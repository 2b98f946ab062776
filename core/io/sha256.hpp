// SHA-256 (FIPS 180-4) of bytes in memory, as lowercase hex: the checksums a run directory
// records (the mesh a run started from), so two runs can be told to use the same input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace rbcsim::io {

class Sha256 {
 public:
  Sha256();
  void update(std::span<const std::byte> bytes);
  // The digest of everything given to update(), as 64 hex digits. Ends the computation.
  std::string hex_digest();

 private:
  void compress(const std::uint8_t* block);

  std::uint32_t state_[8];
  std::uint8_t buffer_[64];
  std::size_t buffered_ = 0;
  std::uint64_t total_bytes_ = 0;
};

std::string sha256_hex(std::span<const std::byte> bytes);

}  // namespace rbcsim::io
