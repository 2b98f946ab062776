#include "io/atomic_file.hpp"

#include <fstream>
#include <random>
#include <string>
#include <system_error>

#include "common/errors.hpp"

namespace rbcsim::io {
namespace {

bool g_process_writes_files = true;

std::filesystem::path temporary_sibling(const std::filesystem::path& path) {
  std::random_device entropy;
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on "." + std::string.
  std::string name = path.filename().string();
  name.insert(0, 1, '.');
  name.append(".tmp").append(std::to_string(entropy()));
  return path.parent_path() / name;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  if (!g_process_writes_files) return;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  const auto temporary = temporary_sibling(path);
  try {
    {
      std::ofstream stream(temporary, std::ios::binary | std::ios::trunc);
      if (!stream) throw RuntimeFailure(path.string() + ": cannot open for writing");
      write(stream);
      stream.flush();
      if (!stream) throw RuntimeFailure(path.string() + ": write failed (disk full?)");
    }
    std::filesystem::rename(temporary, path);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

void write_text_atomically(const std::filesystem::path& path, std::string_view text) {
  write_file_atomically(path, [text](std::ostream& out) { out << text; });
}

void set_process_writes_files(bool writes) { g_process_writes_files = writes; }

bool process_writes_files() { return g_process_writes_files; }

}  // namespace rbcsim::io
