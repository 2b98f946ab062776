#include "io/text_file.hpp"

#include <fstream>
#include <sstream>

#include "common/errors.hpp"

namespace rbcsim::io {

void require_regular_file(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) throw InputError(file.string(), "no such file");
  if (std::filesystem::is_directory(file)) throw InputError(file.string(), "is a directory");
  if (!std::filesystem::is_regular_file(file)) {
    throw InputError(file.string(), "is not a regular file");
  }
}

std::string read_text_file(const std::filesystem::path& file) {
  require_regular_file(file);
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw InputError(file.string(), "cannot open the file for reading");
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

}  // namespace rbcsim::io
