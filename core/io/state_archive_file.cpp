#include "io/state_archive_file.hpp"

#include <bit>
#include <cstring>
#include <fstream>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/sha256.hpp"

namespace rbcsim::io {
namespace {

constexpr std::string_view kMagic = "RBCSIMCK";
static_assert(std::endian::native == std::endian::little, "checkpoints are little-endian");

constexpr std::size_t kDigestBytes = 64;  // SHA-256 as hex digits

class ByteWriter {
 public:
  template <typename T>
  void put(const T& value) {
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void put_text(std::string_view text) {
    put(static_cast<std::uint32_t>(text.size()));
    bytes_.append(text);
  }
  void put_values(const std::vector<double>& values) {
    put(static_cast<std::uint64_t>(values.size()));
    bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
  }
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

// Reads from the checked payload; every read is bounds-checked, so a file whose counts lie
// (corrupt, yet with a matching checksum) is refused, not read past its end.
class ByteReader {
 public:
  ByteReader(std::string_view bytes, std::string source)
      : bytes_(bytes), source_(std::move(source)) {}

  template <typename T>
  T get() {
    T value;
    std::memcpy(&value, take(sizeof(T)).data(), sizeof(T));
    return value;
  }
  std::string get_text() { return std::string(take(get<std::uint32_t>())); }
  std::vector<double> get_values() {
    const auto count = get<std::uint64_t>();
    if (count > bytes_.size() / sizeof(double)) fail("an array runs past the end");
    std::vector<double> values(count);
    const auto bytes = take(count * sizeof(double));
    if (count > 0) std::memcpy(values.data(), bytes.data(), bytes.size());  // data() may be null
    return values;
  }
  bool at_end() const { return bytes_.empty(); }
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(source_, "corrupt checkpoint: " + problem);
  }

 private:
  std::string_view take(std::size_t count) {
    if (count > bytes_.size()) fail("truncated");
    const auto taken = bytes_.substr(0, count);
    bytes_.remove_prefix(count);
    return taken;
  }

  std::string_view bytes_;
  std::string source_;
};

std::string sha256_hex(std::string_view bytes) {
  io::Sha256 hash;
  hash.update(std::as_bytes(std::span(bytes.data(), bytes.size())));
  return hash.hex_digest();
}

std::string read_whole_file(const std::filesystem::path& file) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw InputError(file.string(), "no checkpoint there (cannot open it)");
  std::ostringstream bytes;
  bytes << stream.rdbuf();
  return bytes.str();
}

}  // namespace

void write_state_archive(const std::filesystem::path& file, const StateArchive& archive,
                         std::uint32_t version, std::string_view config_fingerprint) {
  ByteWriter writer;
  writer.bytes().append(kMagic);
  writer.put(version);
  writer.put_text(config_fingerprint);
  writer.put(static_cast<std::uint32_t>(archive.arrays().size()));
  for (const auto& [name, values] : archive.arrays()) {
    writer.put_text(name);
    writer.put_values(values);
  }
  const auto digest = sha256_hex(writer.bytes());
  write_file_atomically(file, [&](std::ostream& out) { out << writer.bytes() << digest; });
}

StateArchive read_state_archive(const std::filesystem::path& file, std::uint32_t version,
                                std::string_view config_fingerprint) {
  const std::string name = file.string();
  const auto bytes = read_whole_file(file);
  if (bytes.compare(0, kMagic.size(), kMagic) != 0) {
    throw InputError(name, "not an rbcsim checkpoint (no RBCSIMCK header)");
  }
  if (bytes.size() < kMagic.size() + sizeof(std::uint32_t) + kDigestBytes) {
    throw InputError(name, "corrupt checkpoint: truncated");
  }
  const std::string_view payload(bytes.data(), bytes.size() - kDigestBytes);
  if (sha256_hex(payload) != std::string_view(bytes).substr(payload.size())) {
    throw InputError(name, "corrupt checkpoint: the SHA-256 checksum does not match");
  }
  ByteReader reader(payload.substr(kMagic.size()), name);
  if (const auto found = reader.get<std::uint32_t>(); found != version) {
    throw InputError(name, "checkpoint version " + std::to_string(found) +
                               ", this rbcsim reads version " + std::to_string(version));
  }
  if (reader.get_text() != config_fingerprint) {
    throw InputError(name,
                     "written by a run with a different config; resume with the "
                     "options and config files of that run");
  }
  StateArchive archive(name);
  const auto count = reader.get<std::uint32_t>();
  for (std::uint32_t i = 0; i < count; ++i) {
    auto array_name = reader.get_text();
    archive.put(array_name, reader.get_values());
  }
  if (!reader.at_end()) reader.fail("bytes after the last array");
  return archive;
}

}  // namespace rbcsim::io
